// The arithmetic of Loop subdivision's new positions, shared by the phase-by-phase path (loop_subdivision.cpp)
// and the whole-mesh fast path (loop_subdivision_fast.cpp), so both produce the same bits.
//
// Invariant: every formula is written once, here; callers sum a vertex's neighbours in the same walk order
// (from v.halfedge, h -> h.twin.next), so a vertex point is bit-identical whichever path computed it.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <glm/vec3.hpp>

#include "core/loop_subdivision.h"

namespace meshedit::loop_rules {

// u for an interior vertex of valence n, cached because Loop's weight needs a cosine. Not thread-safe: one per thread.
class ValenceWeights {
 public:
  explicit ValenceWeights(LoopWeights weights) : weights_(weights) { cache_.reserve(32); }

  double operator()(uint32_t n) {
    if (n >= cache_.size()) {
      const size_t from = cache_.size();
      cache_.resize(n + 1);
      for (size_t k = from; k <= n; ++k) cache_[k] = compute(static_cast<uint32_t>(k));
    }
    return cache_[n];
  }

 private:
  double compute(uint32_t n) const {
    if (n == 0) return 0.0;
    if (weights_ == LoopWeights::Course) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * std::numbers::pi / n);
    const double beta = 5.0 / 8.0 - c * c;
    return beta / n;
  }

  LoopWeights weights_;
  std::vector<double> cache_;
};

// An interior vertex at p with `valence` neighbours summing to neighbour_sum; u = ValenceWeights(valence).
inline glm::dvec3 interior_vertex(const glm::dvec3& p, const glm::dvec3& neighbour_sum, uint32_t valence, double u) {
  return (1.0 - valence * u) * p + u * neighbour_sum;
}

// A boundary vertex at p whose boundary neighbours are r0 and r1.
inline glm::dvec3 boundary_vertex(const glm::dvec3& p, const glm::dvec3& r0, const glm::dvec3& r1) {
  return 0.75 * p + 0.125 * (r0 + r1);
}

// The new vertex of interior edge a-b whose triangles' third corners are c and d.
inline glm::dvec3 interior_edge(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  return 0.375 * (a + b) + 0.125 * (c + d);
}

// The new vertex of boundary edge a-b.
inline glm::dvec3 boundary_edge(const glm::dvec3& a, const glm::dvec3& b) { return 0.5 * (a + b); }

}  // namespace meshedit::loop_rules
