// The walk around a vertex that the subdivision rules read: its neighbours (the tips of its outgoing halfedges) in
// for_each_outgoing order, their count and sum, and the neighbours across its boundary edges. Loop subdivision,
// Catmull-Clark and the diagnoses of a student's Loop subdivision all walk it here, so they read a ring alike and sum
// it in the same order (the same bits, as loop_rules.h needs).
//
// Invariants:
// - An edge is on the boundary when a boundary loop is on either side of it. `rim` holds the neighbours across the
//   first two such edges in walk order, `rim_count` counts all of them: 0 inside a valid mesh, 2 on its boundary.
// - The walk is for_each_outgoing's: bounded, and `closed` says whether it came back to its start; a broken fan gives
//   what was walked before it broke.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit {

struct VertexRing {
  uint32_t valence = 0;           // neighbours walked
  glm::dvec3 neighbour_sum{0.0};  // their positions, summed in walk order
  uint32_t rim_count = 0;         // boundary edges at the vertex
  VertexId rim[2];                // the neighbours across the first two of them
  bool closed = false;            // the walk came back to its start
};

// The ring of v; `each(h, q)` also sees every outgoing halfedge h and the position q of its tip, in walk order, for
// the sums a rule needs besides these (Catmull-Clark's face points and edge midpoints).
template <class Each>
VertexRing vertex_ring(const HalfedgeMesh& mesh, VertexId v, Each&& each) {
  VertexRing ring;
  ring.closed = mesh.for_each_outgoing(v, [&](HalfedgeId h) {
    const HalfedgeId t = mesh.twin(h);
    const VertexId tip = mesh.vertex(t);
    const glm::dvec3& q = mesh.position(tip);
    ring.neighbour_sum += q;
    ++ring.valence;
    if (mesh.face(h).is_boundary() || mesh.face(t).is_boundary()) {
      if (ring.rim_count < 2) ring.rim[ring.rim_count] = tip;
      ++ring.rim_count;
    }
    each(h, q);
  });
  return ring;
}

inline VertexRing vertex_ring(const HalfedgeMesh& mesh, VertexId v) {
  return vertex_ring(mesh, v, [](HalfedgeId, const glm::dvec3&) {});
}

}  // namespace meshedit
