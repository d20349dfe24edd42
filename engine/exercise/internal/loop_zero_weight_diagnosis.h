// Loop weights that are 0 where the course's are not, as Lua's integer division makes them (3 // 16, 3 // (8 * n),
// 3 // 8, 1 // 8, 3 // 4 and 1 // 2 are all 0 in Lua 5.4), told as the weight's mistake before anything a later
// step could be blamed for. Part of the upsample comparison (exercise_compare.cpp), so the window, the lessons and
// the grader say it alike.
//
//   const ZeroLoopWeights found = diagnose_zero_loop_weights(before, yours, tolerance);
//   found.messages -> {"your weight u is 0 (in Lua 3 // 16 is 0, an integer division: write 3 / 16): 4 of the 4
//                      original vertices kept their old positions while your new vertices moved; ..."}
//
// Invariants:
// - Only what can be told from positions. Each rule is fitted with its weights set to 0, one at a time and all
//   together: an interior vertex's u (it stays at p), an interior edge's 3/8 and 1/8, a boundary vertex's 3/4 and
//   1/8, a boundary edge's 1/2. A vertex counts for a zeroed rule when it is not where the course puts it and is
//   where the zeroed rule puts it (within the tolerance), the fit with every weight zeroed tried first.
// - An interior original vertex left at p is blamed on u = 0 only when step 5 visibly ran (a new vertex of an
//   interior edge of `before` is not at the midpoint its split left it at) and, for degree 3 and for the other
//   degrees alike, either every such vertex stayed or none did (u is one weight per branch); otherwise an unmoved
//   vertex is left to the caller's step-5 diagnosis, and `originals_unmoved` is false.
// - At most one message per rule (the first vertex in id order, and how many share the mistake). `origin_told` says
//   that a message put vertices at (0, 0, 0), so the caller's general "vertices at the origin" need not.
// - Reads `before` and `yours` through bounded walks only; `yours` should be valid (the caller checks first), with
//   the original vertices keeping their ids and the new ones after them.
#pragma once

#include <string>
#include <vector>

#include "core/halfedge_mesh.h"

namespace meshedit {

struct ZeroLoopWeights {
  std::vector<std::string> messages;
  bool originals_unmoved = false;  // the unmoved original vertices are explained (u is 0)
  bool origin_told = false;        // a message explains vertices at (0, 0, 0)
};

ZeroLoopWeights diagnose_zero_loop_weights(const HalfedgeMesh& before, const HalfedgeMesh& yours, double tolerance);

}  // namespace meshedit
