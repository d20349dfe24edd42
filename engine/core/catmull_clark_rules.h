// The arithmetic of Catmull-Clark's new points, written once and shared by the phase-by-phase path and the one
// call (catmull_clark.cpp), so both give the same bits.
//
// Invariant: callers sum a face's corners in `next` order from halfedge(f) and a vertex's neighbours in the walk
// order from halfedge(v) (h -> twin(h).next), so a point is bit-identical whichever path computed it.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

namespace meshedit::catmull_clark_rules {

// The face point: the centroid of the face's `sides` corners, which sum to corner_sum.
inline glm::dvec3 face_point(const glm::dvec3& corner_sum, uint32_t sides) { return corner_sum / double(sides); }

// The point of interior edge a-b whose two faces have face points f0 and f1: the mean of the four.
inline glm::dvec3 interior_edge(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& f0, const glm::dvec3& f1) {
  return 0.25 * (a + b + f0 + f1);
}

// The point of boundary edge a-b: its midpoint.
inline glm::dvec3 boundary_edge(const glm::dvec3& a, const glm::dvec3& b) { return 0.5 * (a + b); }

// An interior vertex p of valence n, whose n faces' points sum to face_sum and whose n edges' midpoints sum to
// midpoint_sum: (F + 2R + (n - 3) P) / n with F, R the two averages.
inline glm::dvec3 interior_vertex(const glm::dvec3& p, const glm::dvec3& face_sum, const glm::dvec3& midpoint_sum,
                                  uint32_t n) {
  const double count = double(n);
  const glm::dvec3 f = face_sum / count;
  const glm::dvec3 r = midpoint_sum / count;
  return (f + 2.0 * r + (count - 3.0) * p) / count;
}

// A boundary vertex p whose neighbours along the boundary are r0 and r1.
inline glm::dvec3 boundary_vertex(const glm::dvec3& p, const glm::dvec3& r0, const glm::dvec3& r1) {
  return 0.75 * p + 0.125 * (r0 + r1);
}

}  // namespace meshedit::catmull_clark_rules
