// patch_of: runs an edit on a mesh under a change journal and returns the edit's patch, as the document records an
// operation (tests of patches and of what is checked or made from them). The edits given must not make the journal
// fall back to a snapshot; the helper fails the test when one does.
#pragma once

#include <gtest/gtest.h>

#include "core/change_journal.h"
#include "core/halfedge_mesh.h"
#include "core/mesh_patch.h"

namespace meshedit::testing {

template <class Edit>
MeshPatch patch_of(HalfedgeMesh& mesh, Edit&& edit) {
  ChangeJournal journal(mesh);
  edit(mesh);
  EXPECT_FALSE(journal.has_snapshot());
  return make_patch(journal, mesh);
}

}  // namespace meshedit::testing
