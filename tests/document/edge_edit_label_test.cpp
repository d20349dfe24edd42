// The labels of flip, split and collapse read back (document/edge_edit_label.h): the ones the key actions and their
// undo and redo leave in doc.last.label name the operation, the edge and the direction; every other label reads as
// nothing.
#include <gtest/gtest.h>

#include "document/document_actions.h"
#include "document/document_test_support.h"
#include "document/edge_edit_label.h"

namespace meshedit {
namespace {

using namespace document_testing;

void expect_label(const std::string& label, EdgeOperation operation, EdgeId edge, bool undone) {
  SCOPED_TRACE(label);
  const std::optional<EdgeEditLabel> read = read_edge_edit_label(label);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->operation, operation);
  EXPECT_EQ(read->edge, edge);
  EXPECT_EQ(read->undone, undone);
}

TEST(EdgeEditLabel, MadeLabelsReadBackWithTheirUndoAndRedo) {
  for (const EdgeOperation operation : {EdgeOperation::Flip, EdgeOperation::Split, EdgeOperation::Collapse}) {
    const std::string label = edge_edit_label(operation, E(17));
    EXPECT_EQ(label, std::string(edge_operation_verb(operation)) + " e17");
    expect_label(label, operation, E(17), false);
    expect_label("redo " + label, operation, E(17), false);
    expect_label("undo " + label, operation, E(17), true);
  }
}

TEST(EdgeEditLabel, TheKeyActionsLabelsNameTheirOperationAndEdge) {
  MeshDocument doc = make_document(grid_1x1());
  Selection selection{E(2), {}};
  ASSERT_TRUE(flip_selected(doc, selection).ok);
  expect_label(doc.last.label, EdgeOperation::Flip, E(2), false);
  ASSERT_TRUE(undo_edit(doc, selection));
  expect_label(doc.last.label, EdgeOperation::Flip, E(2), true);
  ASSERT_TRUE(redo_edit(doc, selection));
  expect_label(doc.last.label, EdgeOperation::Flip, E(2), false);
  ASSERT_TRUE(split_selected(doc, selection).ok);
  expect_label(doc.last.label, EdgeOperation::Split, E(2), false);
  selection.selected = E(0);
  ASSERT_TRUE(collapse_selected(doc, selection).ok);
  expect_label(doc.last.label, EdgeOperation::Collapse, E(0), false);
  ASSERT_TRUE(undo_edit(doc, selection));
  expect_label(doc.last.label, EdgeOperation::Collapse, E(0), true);
}

TEST(EdgeEditLabel, OtherLabelsReadAsNothing) {
  for (const char* label : {"",
                            "flip",
                            "flip ",
                            "flip e",
                            "flip h5",
                            "flip e5 ",
                            "flip e5x",
                            "flipe5",
                            " flip e5",
                            "undo",
                            "undo flip",
                            "undo undo flip e5",
                            "console: flip e5",
                            "mine: flip e5",
                            "Loop subdivision",
                            "undo Loop subdivision",
                            "Loop 2/4: split every original edge",
                            "split v3",
                            "collapse -",
                            "turn e5"}) {
    EXPECT_FALSE(read_edge_edit_label(label)) << '"' << label << '"';
  }
}

}  // namespace
}  // namespace meshedit
