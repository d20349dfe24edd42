// The geometry of one flip, split or collapse (render/edit_animation.h's EditMotion), read from the mesh in the
// operation's two states: `start`, the mesh the operation ran on, and `result`, the mesh it left. For the document's
// last change, both come from the mesh and the change's patch (core/state_before.h): an edit's start is the state
// before the patch and its result the mesh; an undo's are the other way round, and it plays backward.
//
// What is read, with core/mesh_ops.h's names:
// - flip of e: e's ends a, b in start (from e's halfedge h0: a = h0.vertex, b = h0.twin.vertex) and the same
//   halfedges' vertices d, c in result (h0 then runs d->c).
// - split of e: e's ends a, b in start; m, the end of e in result that start does not have (e keeps its id as m-b);
//   the far ends of m's edges in result other than a and b (c, and d when e had two faces).
// - collapse of e: e's ends in start, of which one lives on in result (a, where they meet: its position in result)
//   and one is gone (b); the far ends in start of a's edges other than e, and of b's.
//
// Invariants:
// - Only reads, through the mesh's (or the state before's) read functions, following an id only after alive() says
//   it lives (alive() checks the range too), and walks around a vertex for at most kMaxWalk halfedges: a mesh a
//   script broke gives nullopt, never a crash or a hang.
// - nullopt also when the two states do not show that operation on that edge: e dead in either, a flip whose ends
//   did not move, a split with no new end, a collapse that did not remove exactly one end.
#pragma once

#include <cstddef>
#include <optional>

#include "core/edge_operation.h"
#include "core/halfedge_mesh.h"
#include "core/mesh_patch.h"
#include "render/edit_animation.h"

namespace meshedit {

// The longest walk around a vertex; a fan that does not close within it is read as broken.
inline constexpr size_t kMaxWalk = size_t(1) << 16;

std::optional<EditMotion> edit_motion(EdgeOperation operation, EdgeId edge, const HalfedgeMesh& start,
                                      const HalfedgeMesh& result);

// The animation of a change the document recorded as `patch`, leaving `mesh`: the operation on `edge` played forward,
// or (`undone`: the change was its undo) backward.
std::optional<EditAnimation> edit_animation_of_change(EdgeOperation operation, EdgeId edge, bool undone,
                                                      const HalfedgeMesh& mesh, const MeshPatch& patch);

}  // namespace meshedit
