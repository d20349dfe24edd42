// Building the refined mesh of Catmull-Clark and linear subdivision (see subdivision_refine.h): the children are
// written as indexed polygons and handed to build_halfedge_mesh, which checks them and fixes the id order.
#include "core/subdivision_refine.h"

#include <string>

#include "core/mesh_build.h"
#include "core/validate.h"

namespace meshedit {

namespace {

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

HalfedgeMesh refine_mesh(const HalfedgeMesh& mesh, RefineRule rule, const RefineLayout& layout,
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
  return build_halfedge_mesh(polygons);
}

}  // namespace meshedit
