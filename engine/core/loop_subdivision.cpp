// Loop subdivision as four phases built on the core's own split and flip (see loop_subdivision.h).
//
// Invariants kept here:
// - Phase 1 reads the mesh only; phases 2-4 change it only through split(), flip() and set_position(),
//   so each phase leaves a mesh that validate() accepts (the positions of phases 2-3 are midpoints).
// - Only the edges listed by phase 1 are split: edges created by a split are never split again.
// - Per-element work allocates nothing: every array is sized once per phase (with a fallback growth
//   step in case split() allocates more ids than its documented count), and the valence weights are
//   cached by valence, so the cost is O(V + E + F) plus what split() and flip() cost.
#include "core/loop_subdivision.h"

#include <string>

#include "core/loop_rules.h"
#include "core/mesh_ops.h"
#include "core/quick_check.h"
#include "core/triangulate.h"
#include "core/validate.h"
#include "core/vertex_ring.h"

namespace meshedit {

namespace {

using loop_rules::ValenceWeights;

// Sets flags[index] = 1, growing the array if split() allocated past the size reserved for it.
void mark(std::vector<uint8_t>& flags, uint32_t index) {
  if (index >= flags.size()) flags.resize(size_t(index) + 1 + flags.size() / 2, 0);
  flags[index] = 1;
}

bool flagged(const std::vector<uint8_t>& flags, uint32_t index) { return index < flags.size() && flags[index]; }

}  // namespace

Check can_loop_subdivide(const HalfedgeMesh& mesh, int threads) {
  if (loop_input_is_clean(mesh, threads)) return Check::yes();  // quick_check.h: sufficient; the full checks explain
  return can_loop_subdivide_without_shortcut(mesh);
}

Check can_loop_subdivide_without_shortcut(const HalfedgeMesh& mesh) {
  // Validation first: the degree walks below and every later phase assume closed cycles and fans.
  const ValidationReport report = validate_without_shortcut(mesh, 1);
  if (!report.ok()) return Check::no("Loop subdivision needs a valid mesh (" + report.summary() + ")");
  for (FaceId f : mesh.faces()) {
    const uint32_t sides = mesh.degree(f);
    if (sides != 3) {
      return Check::no(format_id(f) + " has " + std::to_string(sides) + " sides; Loop subdivision needs triangles; " +
                       kHowToTriangulate);
    }
  }
  // A valid triangle mesh can still hold an edge split() refuses (two faces with the same three corners,
  // which a script can build); refusing here keeps phase 2 from stopping half way.
  for (EdgeId e : mesh.edges()) {
    const Check splittable = can_split(mesh, e);
    if (!splittable) return Check::no("Loop subdivision cannot split " + format_id(e) + ": " + splittable.reason);
  }
  return Check::yes();
}

OpResult<LoopState> loop_compute_positions(const HalfedgeMesh& mesh, LoopWeights weights) {
  OpResult<LoopState> result;
  result.check = can_loop_subdivide(mesh);
  if (!result.ok()) return result;

  LoopState& state = result.value;
  state.weights = weights;
  state.vertex_position.assign(mesh.vertex_capacity(), glm::dvec3(0.0));
  state.edge_position.assign(mesh.edge_capacity(), glm::dvec3(0.0));
  state.original_edges.reserve(mesh.num_edges());

  ValenceWeights weight(weights);
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3& p = mesh.position(v);
    const VertexRing ring = vertex_ring(mesh, v);
    glm::dvec3& out = state.vertex_position[v.index];
    if (ring.rim_count == 0) {
      const double u = weight(ring.valence);
      out = loop_rules::interior_vertex(p, ring.neighbour_sum, ring.valence, u);
    } else if (ring.rim_count == 2) {
      out = loop_rules::boundary_vertex(p, mesh.position(ring.rim[0]), mesh.position(ring.rim[1]));
    } else {
      // Not reachable on a mesh validate() accepts (one boundary loop per vertex means exactly two
      // boundary edges); keeping the vertex is the least surprising answer.
      out = p;
    }
  }

  for (EdgeId e : mesh.edges()) {
    state.original_edges.push_back(e);
    const HalfedgeId h = mesh.halfedge(e);
    const HalfedgeId t = mesh.twin(h);
    const glm::dvec3& a = mesh.position(mesh.vertex(h));
    const glm::dvec3& b = mesh.position(mesh.vertex(t));
    glm::dvec3& out = state.edge_position[e.index];
    if (mesh.face(h).is_boundary() || mesh.face(t).is_boundary()) {
      out = loop_rules::boundary_edge(a, b);
    } else {
      // Triangles: the corner opposite h is the tail of next(next(h)).
      const glm::dvec3& c = mesh.position(mesh.vertex(mesh.next(mesh.next(h))));
      const glm::dvec3& d = mesh.position(mesh.vertex(mesh.next(mesh.next(t))));
      out = loop_rules::interior_edge(a, b, c, d);
    }
  }
  return result;
}

void loop_split_edges(HalfedgeMesh& mesh, LoopState& state) {
  const size_t splits = state.original_edges.size();
  const uint32_t old_vertices = mesh.vertex_capacity();
  // An interior split adds 1 vertex, 3 edges, 6 halfedges and 2 faces; a boundary split fewer.
  mesh.reserve(splits, 6 * splits, 3 * splits, 2 * splits);
  state.is_new_vertex.assign(old_vertices + splits, 0);
  state.is_new_edge.assign(mesh.edge_capacity() + 3 * splits, 0);
  state.new_position.assign(old_vertices + splits, glm::dvec3(0.0));
  for (uint32_t i = 0; i < old_vertices && i < state.vertex_position.size(); ++i)
    state.new_position[i] = state.vertex_position[i];

  for (EdgeId e : state.original_edges) {
    const uint32_t first_new_edge = mesh.edge_capacity();
    const OpResult<VertexId> split_result = split(mesh, e);
    if (!split_result.ok()) continue;  // not expected on a mesh phase 1 accepted
    const VertexId m = split_result.value;
    mark(state.is_new_vertex, m.index);
    if (m.index >= state.new_position.size()) state.new_position.resize(size_t(m.index) + 1, glm::dvec3(0.0));
    state.new_position[m.index] = state.edge_position[e.index];
    // split()'s documented id order (mesh_ops.h): e stays as the half m-b, then the new edges come as
    // ea = a-m (the other half), ec = m-c and, for an interior edge, ed = m-d (the two that cut across).
    for (uint32_t i = first_new_edge + 1; i < mesh.edge_capacity(); ++i) mark(state.is_new_edge, i);
  }
  state.is_new_vertex.resize(mesh.vertex_capacity(), 0);
  state.is_new_edge.resize(mesh.edge_capacity(), 0);
  state.new_position.resize(mesh.vertex_capacity(), glm::dvec3(0.0));
}

void loop_flip_edges(HalfedgeMesh& mesh, LoopState& state) {
  // Flips never create edges, so the flags cover every edge there is.
  const auto edge_count = static_cast<uint32_t>(state.is_new_edge.size());
  for (uint32_t i = 0; i < edge_count; ++i) {
    const EdgeId e(i);
    if (!state.is_new_edge[i] || !mesh.alive(e)) continue;
    const HalfedgeId h = mesh.halfedge(e);
    const bool tail_new = flagged(state.is_new_vertex, mesh.vertex(h).index);
    const bool head_new = flagged(state.is_new_vertex, mesh.vertex(mesh.twin(h)).index);
    if (tail_new != head_new) flip(mesh, e);
  }
}

void loop_commit_positions(HalfedgeMesh& mesh, const LoopState& state) {
  for (VertexId v : mesh.vertices()) {
    if (v.index < state.new_position.size()) mesh.set_position(v, state.new_position[v.index]);
  }
}

Check loop_subdivide_by_phases(HalfedgeMesh& mesh, LoopWeights weights) {
  OpResult<LoopState> computed = loop_compute_positions(mesh, weights);
  if (!computed.ok()) return computed.check;
  LoopState& state = computed.value;
  loop_split_edges(mesh, state);
  loop_flip_edges(mesh, state);
  loop_commit_positions(mesh, state);
  return Check::yes();
}

}  // namespace meshedit
