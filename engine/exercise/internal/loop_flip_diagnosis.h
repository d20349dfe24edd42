// Why a Loop subdivision's edges are wrong while its vertices are right: flips that did nothing, flips left out, or
// flips of edges that must stay. Part of the upsample comparison (exercise_compare.cpp), so the window, the lessons
// and the grader (which compares through the same code) say it alike.
//
//   diagnose_loop_flips(before, yours, reference, comparison)
//     -> {"your upsample flipped none of the 6 new edges the reference flips: ... The usual causes, most likely
//          first: the marks never match ..."}
//
// Invariants:
// - Flips are counted from connectivity, never from a student's marks or ids: each edge of yours is read through
//   comparison.vertex_map (compare_meshes up to renumbering) against the reference's mesh after its splits (the
//   core's phases 1 and 2 run on `before`, whose vertex ids are the finished reference's) and the finished
//   reference. An edge in the finished reference and not in the split mesh is a right flip; one in the split mesh
//   and not in the finished one is a new edge left unflipped; one in neither is a flip of an edge that had to stay.
//   The reference flips the split mesh's edges that are not in the finished one.
// - Says something only when every vertex of yours matched one of the reference's (positions right) and yours has
//   edges the reference does not; otherwise the comparison's own differences tell.
// - The causes of unflipped edges are named in the order the evidence makes likely: nothing flipped, marks that
//   never match first, then the old/new test made one way only (flags on the halves would have flipped halves);
//   some flipped, the one-way test first; wrong flips too, flags set on the wrong edges first.
#pragma once

#include <string>
#include <vector>

#include "core/halfedge_mesh.h"
#include "core/mesh_compare.h"

namespace meshedit {

std::vector<std::string> diagnose_loop_flips(const HalfedgeMesh& before, const HalfedgeMesh& yours,
                                             const HalfedgeMesh& reference, const MeshComparison& comparison);

}  // namespace meshedit
