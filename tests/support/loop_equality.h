// loop_paths_agree: runs the teaching Loop subdivision (loop_subdivide_by_phases, `levels` times) and the fast one
// (loop_subdivide) on copies of one mesh and succeeds only if the results are the same mesh (HalfedgeMesh::same_as:
// every id, pointer, liveness flag and position bit). On a mismatch it prints the first differing fields.
#pragma once

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "core/history.h"
#include "core/loop_subdivision.h"

namespace meshedit::testing {

inline ::testing::AssertionResult loop_paths_agree(const HalfedgeMesh& input, LoopWeights weights, int levels,
                                                   int threads) {
  HalfedgeMesh phased = input;
  for (int i = 0; i < levels; ++i) {
    const Check ok = loop_subdivide_by_phases(phased, weights);
    if (!ok) return ::testing::AssertionFailure() << "the phases refused: " << ok.reason;
  }
  HalfedgeMesh fast = input;
  const Check ok = loop_subdivide(fast, weights, levels, threads);
  if (!ok) return ::testing::AssertionFailure() << "the fast path refused: " << ok.reason;
  if (fast.same_as(phased)) return ::testing::AssertionSuccess();
  const std::vector<FieldChange> changes = diff(phased, fast);
  auto failure = ::testing::AssertionFailure();
  failure << changes.size() << " fields differ (phases -> fast) after " << levels << " level(s), " << threads
          << " thread(s):";
  for (size_t i = 0; i < std::min<size_t>(changes.size(), 12); ++i) {
    failure << "\n  " << format_id(changes[i].element) << "." << changes[i].field << ": " << changes[i].before << " -> "
            << changes[i].after;
  }
  return failure;
}

}  // namespace meshedit::testing
