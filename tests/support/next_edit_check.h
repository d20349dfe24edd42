// expect_next_edit_recorded: after memory ran out somewhere, the document's next edit is recorded, listed and undone
// as on a document that never ran out (the shared last step of the out-of-memory tests).
#pragma once

#include <gtest/gtest.h>

#include "document/mesh_document.h"
#include "support/state_before_last.h"

namespace meshedit::testing {

// Moves v0 through apply_operation and undoes it with `undo()` (the document's undo, or a key action's).
template <class Undo>
void expect_next_edit_recorded(MeshDocument& doc, Undo&& undo) {
  const HalfedgeMesh kept = doc.mesh;
  ASSERT_TRUE(apply_operation(doc, "move", [](HalfedgeMesh& m) {
                m.set_position(VertexId(0), {0.125, 2, 3});
                return Check::yes();
              }).ok);
  EXPECT_TRUE(doc.last.recorded);
  const std::optional<HalfedgeMesh> before = state_before_last(doc);
  ASSERT_TRUE(before.has_value());
  EXPECT_TRUE(before->same_as(kept));
  EXPECT_EQ(doc.message.text, "move: 1 field changed");
  ASSERT_TRUE(undo());
  EXPECT_TRUE(doc.mesh.same_as(kept));
}

}  // namespace meshedit::testing
