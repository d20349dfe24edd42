// The quick validity check of one edit: given a mesh that was clean (quick_check.h's mesh_is_clean) before an edit
// and the edit's patch, says whether the mesh is clean after it, in time proportional to the edit and the faces and
// fans around it instead of the whole mesh. The window validates every local edit this way (a flip on a mesh of
// millions of triangles costs microseconds, not a whole-mesh pass).
//
// Invariant (held by tests/core/patch_check_test.cpp on real and randomly broken edits):
//   if mesh_is_clean(before) and `patch` turns `before` into `after`, then
//   edit_keeps_clean(after, patch) == mesh_is_clean(after).
// So a true answer implies validate(after).ok(). The patch must list every slot the edit changed (MeshPatch's
// invariant); the state before is read from the patch's `before` values and `after`'s unchanged slots, so the mesh
// before is not needed. A patch that does not end in `after` (its shape, or a listed slot's `after` values, differ)
// gives false: the caller then runs the whole-mesh check.
#pragma once

#include "core/halfedge_mesh.h"
#include "core/mesh_patch.h"

namespace meshedit {

bool edit_keeps_clean(const HalfedgeMesh& after, const MeshPatch& patch);

}  // namespace meshedit
