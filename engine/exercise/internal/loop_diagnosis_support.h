// What the Loop subdivision diagnoses (loop_position_diagnosis.h, loop_boundary_diagnosis.h) read alike: the course's
// weight, closeness within a tolerance, the halfedge joining two vertices, and a new vertex's original neighbours.
// Internal to engine/script. Invariant: every read goes through bounded walks (for_each_outgoing), so a student's
// broken mesh cannot make a diagnosis loop.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit::loop_diagnosis {

inline bool close(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
  return glm::distance(a, b) <= tolerance;
}

// The course's u for an original vertex of degree n: 3/16 for n = 3, else 3 / (8 n).
inline double course_u(size_t n) { return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * double(n)); }

// The halfedge of `mesh` from a to b, if a and b are joined.
inline HalfedgeId halfedge_between(const HalfedgeMesh& mesh, VertexId a, VertexId b) {
  HalfedgeId found;
  mesh.for_each_outgoing(a, [&](HalfedgeId h) {
    if (mesh.vertex(mesh.twin(h)) == b) found = h;
  });
  return found;
}

// The neighbours of yours' new vertex w (an id past `before`'s) that are original vertices of `before`.
inline std::vector<VertexId> original_neighbours(const HalfedgeMesh& before, const HalfedgeMesh& yours, VertexId w) {
  const uint32_t old_capacity = before.vertex_capacity();
  std::vector<VertexId> out;
  yours.for_each_outgoing(w, [&](HalfedgeId h) {
    const VertexId x = yours.vertex(yours.twin(h));
    if (x.index < old_capacity && before.alive(x)) out.push_back(x);
  });
  return out;
}

}  // namespace meshedit::loop_diagnosis
