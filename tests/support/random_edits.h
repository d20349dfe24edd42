// random_local_edits: flips, splits and collapses on random live edges (the core's checked operations, so the
// mesh stays valid), leaving dead slots among the ids and irregular valences. Seeded mt19937, raw output only,
// so a seed gives the same mesh on every platform.
#pragma once

#include <cstdint>
#include <random>

#include "core/mesh_ops.h"

namespace meshedit::testing {

inline void random_local_edits(HalfedgeMesh& m, uint32_t seed, int steps) {
  std::mt19937 random(seed);
  for (int step = 0; step < steps; ++step) {
    const EdgeId e(random() % m.edge_capacity());
    if (!m.alive(e)) continue;
    switch (random() % 3) {
      case 0: (void)flip(m, e); break;
      case 1: (void)split(m, e); break;
      default: (void)collapse(m, e); break;
    }
  }
}

}  // namespace meshedit::testing
