// CPU-side geometry of a half-edge mesh for drawing and picking (see mesh_geometry.h for the rules).
//
// Invariant: no pointer is followed before alive() says its target exists, and the whole-mesh builds
// visit each halfedge at most once (a face walk only follows halfedges that point back to that face,
// and marks them), so a broken mesh can neither crash nor hang the renderer.
#include "render/mesh_geometry.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/finite.h"
#include "core/normals.h"

namespace meshedit {
namespace {

// Arrow layout, as fractions: how far the arrow sits from its edge towards the face centre, how much of
// the inset edge each end leaves out, and the head's length relative to the shaft.
constexpr double kArrowInset = 0.2;
constexpr double kArrowTrim = 0.12;
constexpr double kArrowHead = 0.25;

// Collects f's cycle (see the header's rule for a drawable face); see walk_face_cycle. `Mesh`: a HalfedgeMesh, or
// the StateBefore of an edit.
template <class Mesh>
FaceWalk walk(const Mesh& mesh, FaceId f, std::vector<HalfedgeId>& cycle, std::vector<uint8_t>* visited,
              uint32_t max_steps) {
  cycle.clear();
  if (f.is_boundary() || !mesh.alive(f)) return FaceWalk::Broken;
  const HalfedgeId start = mesh.halfedge(f);
  HalfedgeId h = start;
  const uint32_t bound = std::min(mesh.halfedge_capacity(), max_steps);
  for (uint32_t steps = 0; steps <= bound; ++steps) {
    if (!mesh.alive(h) || mesh.face(h) != f) return FaceWalk::Broken;
    if (visited != nullptr) {
      if ((*visited)[h.index]) return FaceWalk::Broken;
      (*visited)[h.index] = 1;
    }
    const VertexId v = mesh.vertex(h);
    if (!mesh.alive(v) || !finite(mesh.position(v))) return FaceWalk::Broken;
    cycle.push_back(h);
    h = mesh.next(h);
    if (h == start) return cycle.size() >= 3 ? FaceWalk::Closed : FaceWalk::Broken;
  }
  return bound < mesh.halfedge_capacity() ? FaceWalk::TooLong : FaceWalk::Broken;
}

bool walk_face(const HalfedgeMesh& mesh, FaceId f, std::vector<HalfedgeId>& cycle, std::vector<uint8_t>* visited) {
  return walk(mesh, f, cycle, visited, kInvalidIndex) == FaceWalk::Closed;
}

glm::dvec3 cycle_centre(const HalfedgeMesh& mesh, const std::vector<HalfedgeId>& cycle) {
  glm::dvec3 sum(0.0);
  for (HalfedgeId h : cycle) sum += mesh.position(mesh.vertex(h));
  return sum / double(cycle.size());
}

// The arrow of the halfedge from corner a to corner b of a face with centre c.
HalfedgeArrow make_arrow(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, HalfedgeId h) {
  const glm::dvec3 inset_a = a + (c - a) * kArrowInset;
  const glm::dvec3 inset_b = b + (c - b) * kArrowInset;
  const glm::dvec3 tail = inset_a + (inset_b - inset_a) * kArrowTrim;
  const glm::dvec3 tip = inset_b + (inset_a - inset_b) * kArrowTrim;
  const glm::dvec3 shaft = tip - tail;
  const glm::dvec3 base = tip - shaft * kArrowHead;
  // The barbs spread across the shaft in the face's plane. The shaft lies kArrowInset of the way from
  // the edge to the centre, so it is inset/(1-inset) times as far from the edge as from the centre;
  // the barbs spread at most 60% of that, and stay inside.
  const double length_sq = glm::dot(shaft, shaft);
  glm::dvec3 inward = c - base;
  if (length_sq > 0.0) inward -= shaft * (glm::dot(inward, shaft) / length_sq);
  const double to_centre = glm::length(inward);
  glm::dvec3 spread(0.0);
  if (to_centre > 0.0 && std::isfinite(to_centre)) {
    const double half_width =
        std::min(0.5 * kArrowHead * std::sqrt(length_sq), 0.6 * to_centre * kArrowInset / (1.0 - kArrowInset));
    spread = inward * (half_width / to_centre);
  }
  HalfedgeArrow arrow;
  arrow.tail = glm::vec3(tail);
  arrow.tip = glm::vec3(tip);
  arrow.barb_inner = glm::vec3(base + spread);
  arrow.barb_outer = glm::vec3(base - spread);
  arrow.halfedge = h.index;
  return arrow;
}

void add_arrows(const HalfedgeMesh& mesh, const std::vector<HalfedgeId>& cycle, std::vector<HalfedgeArrow>& out) {
  const glm::dvec3 c = cycle_centre(mesh, cycle);
  for (size_t i = 0; i < cycle.size(); ++i) {
    const glm::dvec3& a = mesh.position(mesh.vertex(cycle[i]));
    const glm::dvec3& b = mesh.position(mesh.vertex(cycle[(i + 1) % cycle.size()]));
    out.push_back(make_arrow(a, b, c, cycle[i]));
  }
}

}  // namespace

FaceWalk walk_face_cycle(const HalfedgeMesh& mesh, FaceId f, std::vector<HalfedgeId>& cycle,
                         std::vector<uint8_t>* visited, uint32_t max_steps) {
  return walk(mesh, f, cycle, visited, max_steps);
}

void add_cycle_arrows(const HalfedgeMesh& mesh, const std::vector<HalfedgeId>& cycle, std::vector<HalfedgeArrow>& out) {
  add_arrows(mesh, cycle, out);
}

FaceWalk walk_face_cycle(const StateBefore& mesh, FaceId f, std::vector<HalfedgeId>& cycle,
                         std::vector<uint8_t>* visited, uint32_t max_steps) {
  return walk(mesh, f, cycle, visited, max_steps);
}

namespace {

template <class Mesh>
std::optional<EdgeSegment> segment_of(const Mesh& mesh, EdgeId e) {
  if (!mesh.alive(e)) return std::nullopt;
  const HalfedgeId h = mesh.halfedge(e);
  if (!mesh.alive(h)) return std::nullopt;
  const HalfedgeId t = mesh.twin(h);
  if (!mesh.alive(t)) return std::nullopt;
  const VertexId a = mesh.vertex(h), b = mesh.vertex(t);
  if (!mesh.alive(a) || !mesh.alive(b) || !finite(mesh.position(a)) || !finite(mesh.position(b))) {
    return std::nullopt;
  }
  EdgeSegment segment;
  segment.start = glm::vec3(mesh.position(a));
  segment.end = glm::vec3(mesh.position(b));
  segment.edge = e.index;
  if (mesh.face(h).is_boundary() || mesh.face(t).is_boundary()) segment.flags |= kEdgeBoundaryFlag;
  return segment;
}

}  // namespace

std::optional<EdgeSegment> edge_segment(const HalfedgeMesh& mesh, EdgeId e) { return segment_of(mesh, e); }
std::optional<EdgeSegment> edge_segment(const StateBefore& mesh, EdgeId e) { return segment_of(mesh, e); }

std::optional<HalfedgeArrow> halfedge_arrow(const HalfedgeMesh& mesh, HalfedgeId h) {
  if (!mesh.alive(h)) return std::nullopt;
  std::vector<HalfedgeId> cycle;
  if (!walk_face(mesh, mesh.face(h), cycle, nullptr)) return std::nullopt;
  const auto it = std::find(cycle.begin(), cycle.end(), h);
  if (it == cycle.end()) return std::nullopt;  // points to the face but is not on its cycle
  const size_t i = size_t(it - cycle.begin());
  const glm::dvec3& a = mesh.position(mesh.vertex(cycle[i]));
  const glm::dvec3& b = mesh.position(mesh.vertex(cycle[(i + 1) % cycle.size()]));
  return make_arrow(a, b, cycle_centre(mesh, cycle), h);
}

std::optional<std::vector<glm::dvec3>> face_corners(const HalfedgeMesh& mesh, FaceId f) {
  std::vector<HalfedgeId> cycle;
  if (!walk_face(mesh, f, cycle, nullptr)) return std::nullopt;
  std::vector<glm::dvec3> corners;
  corners.reserve(cycle.size());
  for (HalfedgeId h : cycle) corners.push_back(mesh.position(mesh.vertex(h)));
  return corners;
}

BoundingBox mesh_bounds(const HalfedgeMesh& mesh) {
  BoundingBox box;
  for (VertexId v : mesh.vertices()) {
    if (finite(mesh.position(v))) box.add(mesh.position(v));
  }
  return box;
}

MeshGeometry build_mesh_geometry(const HalfedgeMesh& mesh) {
  MeshGeometry g;
  g.positions.assign(mesh.vertex_capacity(), glm::vec3(0.0f));
  g.smooth_normals.assign(mesh.vertex_capacity(), glm::vec3(0.0f));
  g.face_normals.assign(mesh.face_capacity(), glm::vec3(0.0f));

  const std::vector<glm::dvec3> vertex_normal = vertex_normals(mesh);
  g.points.reserve(mesh.num_vertices());
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3& p = mesh.position(v);
    if (!finite(p)) continue;
    g.positions[v.index] = glm::vec3(p);
    if (v.index < vertex_normal.size()) g.smooth_normals[v.index] = glm::vec3(vertex_normal[v.index]);
    g.points.push_back({glm::vec3(p), v.index});
    g.bounds.add(p);
  }

  const std::vector<glm::dvec3> face_normal = face_normals(mesh);
  for (size_t i = 0; i < face_normal.size() && i < g.face_normals.size(); ++i) {
    g.face_normals[i] = glm::vec3(face_normal[i]);
  }

  std::vector<uint8_t> visited(mesh.halfedge_capacity(), 0);
  std::vector<HalfedgeId> cycle;
  g.triangle_corners.reserve(mesh.num_halfedges() * 3);
  g.triangle_faces.reserve(mesh.num_halfedges());
  for (FaceId f : mesh.faces()) {
    if (!walk_face(mesh, f, cycle, &visited)) {
      g.skipped_faces.push_back(f);
      continue;
    }
    const uint32_t first = mesh.vertex(cycle[0]).index;
    for (size_t i = 1; i + 1 < cycle.size(); ++i) {
      g.triangle_corners.push_back(first);
      g.triangle_corners.push_back(mesh.vertex(cycle[i]).index);
      g.triangle_corners.push_back(mesh.vertex(cycle[i + 1]).index);
      g.triangle_faces.push_back(f.slot());
    }
  }

  g.edges.reserve(mesh.num_edges());
  for (EdgeId e : mesh.edges()) {
    if (auto segment = edge_segment(mesh, e)) {
      g.edges.push_back(*segment);
    } else {
      g.skipped_edges.push_back(e);
    }
  }
  return g;
}

std::vector<HalfedgeArrow> build_halfedge_arrows(const HalfedgeMesh& mesh) {
  std::vector<HalfedgeArrow> arrows;
  arrows.reserve(mesh.num_halfedges());
  std::vector<uint8_t> visited(mesh.halfedge_capacity(), 0);
  std::vector<HalfedgeId> cycle;
  for (FaceId f : mesh.faces()) {
    if (walk_face(mesh, f, cycle, &visited)) add_arrows(mesh, cycle, arrows);
  }
  return arrows;
}

}  // namespace meshedit
