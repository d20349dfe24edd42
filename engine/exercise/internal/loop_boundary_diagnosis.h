// Why a Loop subdivision's boundary is in the wrong place: the course's extra-credit rules (a boundary vertex moves
// to 3/4 p + 1/8 (a + b), a and b its two neighbours along the boundary; a boundary edge's new vertex is its
// midpoint) against the interior rules a student applied there. Part of the upsample comparison, beside
// loop_position_diagnosis.h, so the window, the lessons and the grader say it alike.
//
//   diagnose_loop_boundary(before, yours, tolerance)
//     -> {"4 of your boundary vertices, e.g. v0, moved by the interior rule ... a boundary vertex moves to ..."}
//
// Invariants:
// - Only what can be told from positions, and only on the boundary of `before` (interior vertices and edges are
//   loop_position_diagnosis.h's): an original boundary vertex of yours (same id in `before`) that is not at the
//   course's position is fitted to the interior rule over all its neighbours in `before` (with the course's u);
//   a new vertex of yours whose original neighbours include the two ends of a boundary edge of `before` and that is
//   where the course puts the new vertex of none of the original edges between its original neighbours (wrong flips
//   may join it to the ends of edges it was not made on) is
//   fitted, on the first such edge, to the interior edge rule with d read across the boundary loop
//   (h.twin.next.next), and with d left out. What fits no rule is still named, with the course's position.
// - At most one message per rule (the first vertex in id order, and how many share the mistake).
// - Reads every mesh through bounded walks only; `yours` should be valid (the caller checks first).
#pragma once

#include <string>
#include <vector>

#include "core/halfedge_mesh.h"

namespace meshedit {

std::vector<std::string> diagnose_loop_boundary(const HalfedgeMesh& before, const HalfedgeMesh& yours,
                                                double tolerance);

}  // namespace meshedit
