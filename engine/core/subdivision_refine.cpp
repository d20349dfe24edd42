// Building the refined mesh of Catmull-Clark and linear subdivision (see subdivision_refine.h): the children are
// written as indexed polygons, their twins worked out from the original mesh's, and the builder's own last step
// (finish_build: boundary loops, edges, vertices) gives the ids build_halfedge_mesh would give.
#include "core/subdivision_refine.h"

#include <algorithm>
#include <string>

#include "core/finite.h"
#include "core/mesh_build_fast.h"
#include "core/mesh_storage.h"
#include "core/validate.h"

namespace meshedit {

namespace {

constexpr uint32_t kNone = kInvalidIndex;

// The corners of live face f from halfedge(f) in `next` order, with the edge leaving each corner.
void face_corners(const HalfedgeMesh& mesh, FaceId f, std::vector<uint32_t>& corners, std::vector<uint32_t>& edges) {
  corners.clear();
  edges.clear();
  mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
    corners.push_back(mesh.vertex(h).index);
    edges.push_back(mesh.edge(h).index);
  });
}

bool gets_centre(RefineRule rule, size_t sides) { return rule == RefineRule::Quads || sides != 3; }

}  // namespace

Check can_refine(const HalfedgeMesh& mesh, const char* scheme) {
  const ValidationReport report = validate(mesh);
  if (!report.ok()) return Check::no(std::string(scheme) + " needs a valid mesh (" + report.summary() + ")");
  std::vector<uint32_t> seen(mesh.vertex_capacity(), RefineLayout::kNone);
  for (FaceId f : mesh.faces()) {
    Check problem = Check::yes();
    mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
      if (!problem) return;
      if (mesh.face(mesh.twin(h)) == f) {
        problem = Check::no(format_id(f) + " lies on both sides of " + format_id(mesh.edge(h)) + "; " + scheme +
                            " needs faces that do not");
      } else if (seen[mesh.vertex(h).index] == f.slot()) {
        problem = Check::no(format_id(f) + " has " + format_id(mesh.vertex(h)) + " as a corner twice; " + scheme +
                            " needs faces that do not");
      }
      seen[mesh.vertex(h).index] = f.slot();
    });
    if (!problem) return problem;
  }
  return Check::yes();
}

RefineLayout plan_refinement(const HalfedgeMesh& mesh, RefineRule rule) {
  RefineLayout layout;
  uint32_t next = mesh.vertex_capacity();
  layout.edge_vertex.assign(mesh.edge_capacity(), RefineLayout::kNone);
  for (EdgeId e : mesh.edges()) layout.edge_vertex[e.index] = next++;
  layout.face_vertex.assign(mesh.face_capacity(), RefineLayout::kNone);
  for (FaceId f : mesh.faces()) {
    if (gets_centre(rule, mesh.degree(f))) layout.face_vertex[f.slot()] = next++;
  }
  layout.vertex_count = next;
  return layout;
}

std::vector<glm::dvec3> midpoint_positions(const HalfedgeMesh& mesh, const RefineLayout& layout) {
  std::vector<glm::dvec3> positions(layout.vertex_count, glm::dvec3(0.0));
  for (uint32_t i = 0; i < mesh.vertex_capacity(); ++i) positions[i] = mesh.position(VertexId(i));
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    positions[layout.edge_vertex[e.index]] =
        0.5 * (mesh.position(mesh.vertex(h)) + mesh.position(mesh.vertex(mesh.twin(h))));
  }
  for (FaceId f : mesh.faces()) {
    const uint32_t centre = layout.face_vertex[f.slot()];
    if (centre == RefineLayout::kNone) continue;
    glm::dvec3 sum(0.0);
    uint32_t sides = 0;
    mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
      sum += mesh.position(mesh.vertex(h));
      ++sides;
    });
    positions[centre] = sum / double(sides);
  }
  return positions;
}

PolygonMesh refined_polygons(const HalfedgeMesh& mesh, RefineRule rule, const RefineLayout& layout,
                             const std::vector<glm::dvec3>& positions) {
  PolygonMesh polygons;
  polygons.positions = positions;
  polygons.indices.reserve(4 * mesh.num_halfedges());
  polygons.face_offsets.reserve(mesh.num_halfedges() + 1);
  std::vector<uint32_t> corners, edges;
  for (FaceId f : mesh.faces()) {
    face_corners(mesh, f, corners, edges);
    const size_t n = corners.size();
    // edges[i] joins corners[i] and corners[i + 1]; its new vertex is after corner i, before corner i + 1.
    const auto mid = [&](size_t i) { return layout.edge_vertex[edges[i % n]]; };
    if (!gets_centre(rule, n)) {
      for (size_t i = 0; i < 3; ++i) polygons.add_face({corners[i], mid(i), mid(i + 2)});
      polygons.add_face({mid(0), mid(1), mid(2)});
      continue;
    }
    const uint32_t centre = layout.face_vertex[f.slot()];
    for (size_t i = 0; i < n; ++i) polygons.add_face({corners[i], mid(i), centre, mid(i + n - 1)});
  }
  return polygons;
}

HalfedgeMesh refine_mesh(const HalfedgeMesh& mesh, RefineRule rule, const RefineLayout& layout,
                         const std::vector<glm::dvec3>& positions) {
  const PolygonMesh polygons = refined_polygons(mesh, rule, layout, positions);
  const auto num_interior = static_cast<uint32_t>(polygons.indices.size());

  // Each original halfedge h (a -> b, in a face) is cut at its edge's new vertex m into two child halfedges, a -> m
  // and m -> b, both in children of h's face; the first's twin is the second half of twin(h), and the other way
  // round. The halfedges inside one original face are twinned within it. Children's halfedges are numbered as the
  // builder numbers them: face by face, corner by corner, in refined_polygons' order.
  std::vector<uint32_t> first_half(mesh.halfedge_capacity(), kNone), second_half(mesh.halfedge_capacity(), kNone);
  std::vector<uint32_t> twin(num_interior, kNone);
  std::vector<HalfedgeId> around;
  uint32_t base = 0;
  for (FaceId f : mesh.faces()) {
    around.clear();
    mesh.for_each_face_halfedge(f, [&](HalfedgeId h) { around.push_back(h); });
    const auto n = static_cast<uint32_t>(around.size());
    if (!gets_centre(rule, n)) {
      // Corner child i = (v_i, m_i, m_(i-1)) at base + 3i; the middle child (m_0, m_1, m_2) at base + 9.
      for (uint32_t i = 0; i < 3; ++i) {
        first_half[around[i].index] = base + 3 * i;
        second_half[around[(i + 2) % 3].index] = base + 3 * i + 2;
        const uint32_t inner = base + 3 * i + 1, middle = base + 9 + (i + 2) % 3;  // m_i -> m_(i-1) and back
        twin[inner] = middle;
        twin[middle] = inner;
      }
      base += 12;
      continue;
    }
    // Child i = (v_i, m_i, centre, m_(i-1)) at base + 4i: m_i -> centre is the twin of child i+1's centre -> m_i.
    for (uint32_t i = 0; i < n; ++i) {
      first_half[around[i].index] = base + 4 * i;
      second_half[around[(i + n - 1) % n].index] = base + 4 * i + 3;
      const uint32_t out = base + 4 * i + 1, back = base + 4 * ((i + 1) % n) + 2;
      twin[out] = back;
      twin[back] = out;
    }
    base += 4 * n;
  }

  // The halves of original halfedges: twinned across the original edge, or open when it is on the boundary.
  std::vector<uint32_t> open_incoming(polygons.num_vertices(), kNone);
  uint32_t num_boundary = 0;
  for (FaceId f : mesh.faces()) {
    mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
      const HalfedgeId t = mesh.twin(h);
      const uint32_t a_m = first_half[h.index], m_b = second_half[h.index];
      if (mesh.face(t).is_boundary()) {
        open_incoming[layout.edge_vertex[mesh.edge(h).index]] = a_m;
        open_incoming[mesh.vertex(t).index] = m_b;
        num_boundary += 2;
      } else {
        twin[a_m] = second_half[t.index];
        twin[m_b] = first_half[t.index];
      }
    });
  }

  HalfedgeMesh refined;
  build_detail::write_face_halfedges(polygons, twin, num_interior + num_boundary, refined);
  const size_t unused = build_detail::finish_build(polygons, twin, open_incoming, refined);
  // Vouched as the builder vouches: all triangles, every vertex used, every position finite.
  const bool finite_positions =
      std::all_of(positions.begin(), positions.end(), [](const glm::dvec3& p) { return finite(p); });
  if (num_interior == 3 * polygons.num_faces() && unused == 0 && finite_positions) {
    MeshStorage::vouch_valid_triangles(refined);
  }
  return refined;
}

}  // namespace meshedit
