// Why a Loop subdivision's vertices are in the wrong places: a wrong weight (named with the weight it was) or
// positions written to the wrong vertices. Part of the upsample comparison (exercise_compare.cpp), so the window
// and the grader (which compares through the same code) say it alike.
//
//   diagnose_loop_positions(before, yours, reference, tolerance, origin_explained)
//     -> {"your original vertex v0 (degree 3) moved as if u = 0.125 ...; the course's u for degree 3 is 3/16 ..."}
//
// Invariants:
// - Only what can be told from positions: an original vertex (same id in yours, the reference and `before`) that
//   is not where the reference puts it is fitted to (1 - n u) p + u (sum of its neighbours in `before`); when the
//   fit is exact (within the tolerance) and u is not 0 (an unmoved vertex is diagnosed elsewhere), the message
//   names that u and the course's. A new vertex of yours whose two original neighbours a, b were joined by an
//   interior edge of `before` is tested against the usual wrong edge rules (the midpoint, the weights swapped,
//   the average of a, b, c, d). An original vertex of yours that sits where the reference puts a new vertex was
//   given a new vertex's position.
// - At most one message per rule (the first vertex in id order, and how many share the mistake); boundary
//   vertices and edges are left out (their rules are extra credit: loop_boundary_diagnosis.h). With
//   `origin_explained` (weights of 0 put them there: loop_zero_weight_diagnosis.h), new vertices at (0, 0, 0) are
//   not fitted to the wrong edge rules, one of which may pass through the origin too.
// - Reads every mesh through bounded walks only; `yours` should be valid (the caller checks first).
#pragma once

#include <string>
#include <vector>

#include "core/halfedge_mesh.h"

namespace meshedit {

std::vector<std::string> diagnose_loop_positions(const HalfedgeMesh& before, const HalfedgeMesh& yours,
                                                 const HalfedgeMesh& reference, double tolerance,
                                                 bool origin_explained);

}  // namespace meshedit
