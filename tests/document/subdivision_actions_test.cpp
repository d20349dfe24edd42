// The Subdivide menu's Catmull-Clark and linear actions: one undoable step each, labelled, keeping a selected
// original vertex, a refusal that changes nothing but the message, and Catmull-Clark phase by phase.
#include <gtest/gtest.h>

#include "core/catmull_clark.h"
#include "core/linear_subdivision.h"
#include "core/primitives.h"
#include "document/document_actions.h"
#include "document/document_test_support.h"
#include "document/subdivision_actions.h"

namespace meshedit {
namespace {

using namespace document_testing;

TEST(SubdivisionActions, CatmullClarkIsOneUndoableStep) {
  const HalfedgeMesh start = build_halfedge_mesh(make_cube_quads());
  HalfedgeMesh reference = start;
  ASSERT_TRUE(catmull_clark_subdivide(reference));
  MeshDocument doc = make_document(start);
  Selection sel{V(3), E(1)};
  ASSERT_TRUE(catmull_clark_all(doc, sel).ok);
  EXPECT_TRUE(doc.mesh.same_as(reference));
  EXPECT_EQ(doc.last.label, "Catmull-Clark subdivision");
  EXPECT_REF(sel.selected, V(3));     // original vertices keep their ids
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

// Phase by phase: 1 records nothing, 2 and 3 are each an undo step, and the end is the one call's mesh.
TEST(SubdivisionActions, CatmullClarkPhaseByPhase) {
  const HalfedgeMesh start = build_halfedge_mesh(make_cube_quads());
  HalfedgeMesh reference = start;
  ASSERT_TRUE(catmull_clark_subdivide(reference));
  MeshDocument doc = make_document(start);
  Selection sel{V(5), {}};
  SubdivisionStepper stepper(SubdivisionScheme::CatmullClark);
  EXPECT_EQ(next_phase_label(doc, stepper), "Catmull-Clark 1/3: compute face, edge and vertex points");
  ASSERT_TRUE(subdivision_step(doc, sel, stepper).ok);
  EXPECT_TRUE(doc.mesh.same_as(start));
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_EQ(doc.message.text,
            "Catmull-Clark 1/3: compute face, edge and vertex points: 6 face points, 12 edge points, 8 vertex points; "
            "nothing moved yet");
  EXPECT_EQ(next_phase_label(doc, stepper), "Catmull-Clark 2/3: split every face into quads (nothing moves yet)");
  ASSERT_TRUE(subdivision_step(doc, sel, stepper).ok);
  EXPECT_EQ(doc.mesh.num_faces(), 24u);
  EXPECT_EQ(doc.mesh.position(V(5)), start.position(V(5)));  // nothing moved yet
  EXPECT_REF(sel.selected, V(5));
  ASSERT_TRUE(subdivision_step(doc, sel, stepper).ok);
  EXPECT_TRUE(doc.mesh.same_as(reference));
  EXPECT_EQ(doc.last.label, "Catmull-Clark 3/3: move every vertex to its point");
  EXPECT_EQ(stepper.phases.next_phase(), 1);
  // Two undo steps back to the start.
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_EQ(doc.mesh.num_faces(), 24u);
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_TRUE(doc.mesh.same_as(start));
}

// A change between phases (here an undo) makes the next call start again at phase 1, saying so.
TEST(SubdivisionActions, CatmullClarkStepsStartAgainAfterAChange) {
  const HalfedgeMesh start = build_halfedge_mesh(make_cube_quads());
  MeshDocument doc = make_document(start);
  Selection sel;
  SubdivisionStepper stepper(SubdivisionScheme::CatmullClark);
  ASSERT_TRUE(subdivision_step(doc, sel, stepper).ok);
  ASSERT_TRUE(subdivision_step(doc, sel, stepper).ok);
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_EQ(next_phase_label(doc, stepper), "Catmull-Clark 1/3: compute face, edge and vertex points");
  ASSERT_TRUE(subdivision_step(doc, sel, stepper).ok);
  EXPECT_EQ(doc.message.text.rfind("the mesh changed after Catmull-Clark phase 2; starting again. ", 0), 0u)
      << doc.message.text;
  EXPECT_EQ(stepper.phases.next_phase(), 2);
  EXPECT_TRUE(doc.mesh.same_as(start));
}

}  // namespace
}  // namespace meshedit
