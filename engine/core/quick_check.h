// Quick sufficient checks: true only for a mesh the full checks accept, in a few passes over the raw arrays with
// no report to build. False says nothing: the caller then runs the full check (validate(), can_loop_subdivide's
// own), which finds and words the problem. validate() and can_loop_subdivide() start with these, so a valid mesh
// (the common case: every frame's status bar, every subdivision) costs a fraction of a full validation. A mesh
// vouched for (HalfedgeMesh::proven_valid_triangles) is clean without a pass, and skips the validity part of
// loop_input_is_clean.
//
// Invariant (held by tests/core/quick_check_test.cpp on fixtures and randomly broken meshes):
//   mesh_is_clean(m)  implies  validate(m).ok();
//   loop_input_is_clean(m)  implies  can_loop_subdivide(m).
#pragma once

#include "core/halfedge_mesh.h"

namespace meshedit {

// Each pass runs on up to `threads` threads (a big mesh's whole-mesh passes: the window's validation, L); the answer
// does not depend on the count.
bool mesh_is_clean(const HalfedgeMesh& mesh, int threads = 1);
bool loop_input_is_clean(const HalfedgeMesh& mesh, int threads = 1);

}  // namespace meshedit
