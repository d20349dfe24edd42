// The Subdivide menu's Catmull-Clark and linear actions: one undoable step each, labelled, keeping a selected
// original vertex, and a refusal that changes nothing but the message.
#include <gtest/gtest.h>

#include "core/catmull_clark.h"
#include "core/linear_subdivision.h"
#include "core/primitives.h"
#include "ui/document_actions.h"
#include "ui/subdivision_actions.h"
#include "ui_test_support.h"

namespace meshedit {
namespace {

using namespace ui_testing;

TEST(SubdivisionActions, CatmullClarkIsOneUndoableStep) {
  const HalfedgeMesh start = build_halfedge_mesh(make_cube_quads());
  HalfedgeMesh reference = start;
  ASSERT_TRUE(catmull_clark_subdivide(reference));
  MeshDocument doc = make_document(start);
  Selection sel{V(3), E(1)};
  ASSERT_TRUE(catmull_clark_all(doc, sel).ok);
  EXPECT_TRUE(doc.mesh.same_as(reference));
  EXPECT_EQ(doc.last.label, "Catmull-Clark subdivision");
  EXPECT_REF(sel.selected, V(3));  // original vertices keep their ids
  EXPECT_FALSE(sel.hovered.valid());  // edge e1 is another edge now
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_TRUE(doc.mesh.same_as(start));
  EXPECT_FALSE(doc.history.can_undo());
}

TEST(SubdivisionActions, LinearIsOneUndoableStepAndDeselectsAnEdge) {
  const HalfedgeMesh start = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh reference = start;
  ASSERT_TRUE(linear_subdivide(reference));
  MeshDocument doc = make_document(start);
  Selection sel{E(2), {}};
  ASSERT_TRUE(linear_subdivide_all(doc, sel).ok);
  EXPECT_TRUE(doc.mesh.same_as(reference));
  EXPECT_EQ(doc.last.label, "Linear subdivision");
  EXPECT_FALSE(sel.selected.valid());
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_TRUE(doc.mesh.same_as(start));
}

TEST(SubdivisionActions, RefusalChangesNothing) {
  HalfedgeMesh broken = build_halfedge_mesh(make_cube_quads());
  broken.set_next(H(0), H(0));
  MeshDocument doc = make_document(broken);
  Selection sel;
  EXPECT_FALSE(catmull_clark_all(doc, sel).ok);
  EXPECT_FALSE(linear_subdivide_all(doc, sel).ok);
  EXPECT_TRUE(doc.mesh.same_as(broken));
  EXPECT_EQ(doc.message.severity, Severity::Warning);
  EXPECT_FALSE(doc.history.can_undo());
}

}  // namespace
}  // namespace meshedit
