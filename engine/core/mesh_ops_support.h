// The checks flip, split and collapse share before they trust a pointer, and the bounded fan walk.
// Internal to engine/core (callers use mesh_ops.h).
//
// Invariants:
// - No pointer is followed before alive() said the element holding it is in range and live, so a mesh a
//   script left in any state can be inspected without reading past an array.
// - Every walk stops after halfedge_capacity() + 1 steps, so a cycle that never returns to its start
//   (a "rho" shape) ends the walk instead of hanging it.
// - Every refusal is a sentence that names the elements with format_id.
#pragma once

#include <string>
#include <utility>

#include "core/check.h"
#include "core/halfedge_mesh.h"

namespace meshedit::ops_detail {

// The two halfedges of an edge, named as in mesh_ops.h: h0 runs a -> b, h1 = h0.twin runs b -> a.
struct EdgeHalves {
  HalfedgeId h0, h1;
};

// h0 as mesh_ops.h names it for split and collapse: e's halfedge inside a face (the twin comes first when
// the given h0 lies on a boundary loop).
inline EdgeHalves face_side_first(const HalfedgeMesh& mesh, EdgeHalves halves) {
  if (mesh.face(halves.h0).is_boundary()) std::swap(halves.h0, halves.h1);
  return halves;
}

// Checks that e is alive and that its halfedges can be operated on: both alive, twins of each other, both
// on e, with live distinct tails and live faces, and not the same face on both sides. On success
// `halves` holds h0 = e.halfedge and h1 = its twin.
Check check_edge(const HalfedgeMesh& mesh, EdgeId e, EdgeHalves& halves);

// Checks that h's face is a triangle whose three halfedges are consistent enough to rewire: the next-cycle
// from h closes after three steps, all three lie in h's face, have live tails (three distinct corners),
// live edges shared with live twins that point back, and each twin leaves the vertex its halfedge reaches.
// `purpose` ends the sentence of a non-triangle refusal ("only edges between two triangles can be flipped"): English,
// translated here (tr) with the rest of the reason.
Check check_triangle(const HalfedgeMesh& mesh, HalfedgeId h, const char* purpose);

// Checks that the halfedge after h in h's boundary loop is alive, in the same loop, and leaves the vertex
// h reaches (`head`): the one step split and collapse take along a boundary loop.
Check check_loop_step(const HalfedgeMesh& mesh, HalfedgeId h, VertexId head);

// Refusal for a fan walk that could not go around `v` (broken pointers), saying what needed the walk.
Check broken_fan(VertexId v, HalfedgeId start, const std::string& needed_for);

// Calls fn(o) for each outgoing halfedge o of vertex(start), start first, stepping o -> o.twin.next.
// Returns true when the walk comes back to `start`; false (having called fn for the steps it took) when a
// halfedge is dead, leaves another vertex, has a twin that does not point back, or the bound runs out.
template <class Fn>
bool walk_fan(const HalfedgeMesh& mesh, HalfedgeId start, Fn&& fn) {
  if (!mesh.alive(start)) return false;
  const VertexId v = mesh.vertex(start);
  HalfedgeId o = start;
  for (uint32_t steps = 0; steps <= mesh.halfedge_capacity(); ++steps) {
    if (!mesh.alive(o) || mesh.vertex(o) != v) return false;
    const HalfedgeId t = mesh.twin(o);
    if (!mesh.alive(t) || mesh.twin(t) != o) return false;
    fn(o);
    o = mesh.next(t);
    if (o == start) return true;
  }
  return false;
}

}  // namespace meshedit::ops_detail
