// Catmull-Clark subdivision as three phases, and the one call (see catmull_clark.h).
//
// Invariants kept here:
// - Phase 1 reads the mesh only; phase 2 replaces it by refine_mesh's result, phase 3 changes positions only, so
//   each phase leaves a mesh validate() accepts.
// - Every point is computed once, in compute_points, by catmull_clark_rules.h; both paths place those same values,
//   so the one call and the phases agree bit for bit.
#include "core/catmull_clark.h"

#include <utility>

#include "core/catmull_clark_rules.h"
#include "core/mesh_error.h"
#include "core/vertex_ring.h"

namespace meshedit {

namespace {

namespace rules = catmull_clark_rules;

CatmullClarkState compute_points(const HalfedgeMesh& mesh) {
  CatmullClarkState state;
  state.layout = plan_refinement(mesh, RefineRule::Quads);
  state.face_point.assign(mesh.face_capacity(), glm::dvec3(0.0));
  for (FaceId f : mesh.faces()) {
    glm::dvec3 sum(0.0);
    uint32_t sides = 0;
    mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
      sum += mesh.position(mesh.vertex(h));
      ++sides;
    });
    state.face_point[f.slot()] = rules::face_point(sum, sides);
  }

  state.edge_point.assign(mesh.edge_capacity(), glm::dvec3(0.0));
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    const HalfedgeId t = mesh.twin(h);
    const glm::dvec3& a = mesh.position(mesh.vertex(h));
    const glm::dvec3& b = mesh.position(mesh.vertex(t));
    if (mesh.face(h).is_boundary() || mesh.face(t).is_boundary()) {
      state.edge_point[e.index] = rules::boundary_edge(a, b);
    } else {
      state.edge_point[e.index] =
          rules::interior_edge(a, b, state.face_point[mesh.face(h).slot()], state.face_point[mesh.face(t).slot()]);
    }
  }

  state.vertex_point.resize(mesh.vertex_capacity());
  for (uint32_t i = 0; i < mesh.vertex_capacity(); ++i) state.vertex_point[i] = mesh.position(VertexId(i));
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3& p = mesh.position(v);
    glm::dvec3 face_sum(0.0), midpoint_sum(0.0);
    const VertexRing ring = vertex_ring(mesh, v, [&](HalfedgeId h, const glm::dvec3& q) {
      midpoint_sum += 0.5 * (p + q);
      if (!mesh.face(h).is_boundary()) face_sum += state.face_point[mesh.face(h).slot()];
    });
    if (ring.rim_count == 0) {
      state.vertex_point[v.index] = rules::interior_vertex(p, face_sum, midpoint_sum, ring.valence);
    } else if (ring.rim_count == 2) {
      state.vertex_point[v.index] = rules::boundary_vertex(p, mesh.position(ring.rim[0]), mesh.position(ring.rim[1]));
    }
    // Any other count is not reachable on a mesh validate() accepts (one boundary loop per vertex means
    // exactly two boundary edges); the vertex then keeps its position.
  }
  return state;
}

// Every refined vertex's final position, by refined id.
std::vector<glm::dvec3> final_positions(const HalfedgeMesh& mesh, const CatmullClarkState& state) {
  std::vector<glm::dvec3> positions(state.layout.vertex_count, glm::dvec3(0.0));
  for (uint32_t i = 0; i < mesh.vertex_capacity(); ++i) positions[i] = state.vertex_point[i];
  for (EdgeId e : mesh.edges()) positions[state.layout.edge_vertex[e.index]] = state.edge_point[e.index];
  for (FaceId f : mesh.faces()) positions[state.layout.face_vertex[f.slot()]] = state.face_point[f.slot()];
  return positions;
}

}  // namespace

Check can_catmull_clark(const HalfedgeMesh& mesh) { return can_refine(mesh, "Catmull-Clark subdivision"); }

OpResult<CatmullClarkState> catmull_clark_compute_points(const HalfedgeMesh& mesh) {
  OpResult<CatmullClarkState> result;
  result.check = can_catmull_clark(mesh);
  if (result.check) result.value = compute_points(mesh);
  return result;
}

void catmull_clark_refine(HalfedgeMesh& mesh, const CatmullClarkState& state) {
  mesh.replace_with(refine_mesh(mesh, RefineRule::Quads, state.layout, midpoint_positions(mesh, state.layout)));
}

void catmull_clark_commit_positions(HalfedgeMesh& mesh, const CatmullClarkState& state) {
  // Phase 2 kept the original ids, and the new vertices' ids are the layout's, so the targets are known by id.
  const auto place = [&](uint32_t id, const glm::dvec3& p) {
    if (mesh.alive(VertexId(id))) mesh.set_position(VertexId(id), p);
  };
  for (uint32_t i = 0; i < state.vertex_point.size(); ++i) place(i, state.vertex_point[i]);
  for (uint32_t e = 0; e < state.layout.edge_vertex.size(); ++e) {
    if (state.layout.edge_vertex[e] != RefineLayout::kNone) place(state.layout.edge_vertex[e], state.edge_point[e]);
  }
  for (uint32_t f = 0; f < state.layout.face_vertex.size(); ++f) {
    if (state.layout.face_vertex[f] != RefineLayout::kNone) place(state.layout.face_vertex[f], state.face_point[f]);
  }
}

Check catmull_clark_subdivide_by_phases(HalfedgeMesh& mesh) {
  OpResult<CatmullClarkState> computed = catmull_clark_compute_points(mesh);
  if (!computed) return computed.check;
  catmull_clark_refine(mesh, computed.value);
  catmull_clark_commit_positions(mesh, computed.value);
  return Check::yes();
}

Check catmull_clark_subdivide(HalfedgeMesh& mesh, int levels) {
  // Checked once: a level of an accepted mesh is a valid mesh of quads with four distinct corners, accepted too.
  const Check check = can_catmull_clark(mesh);
  if (!check) return check;
  for (int level = 0; level < levels; ++level) {
    const CatmullClarkState state = compute_points(mesh);
    mesh.replace_with(refine_mesh(mesh, RefineRule::Quads, state.layout, final_positions(mesh, state)));
  }
  return Check::yes();
}

}  // namespace meshedit
