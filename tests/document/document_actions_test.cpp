// The key actions: which edge they act on, what they say, what stays selected, and Loop subdivision phase by
// phase with undo in between.
#include <string>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "document/document_actions.h"
#include "document/document_test_support.h"

namespace meshedit {
namespace {

using namespace document_testing;

TEST(EdgeForOperation, AcceptsEdgesAndHalfedgesOnly) {
  HalfedgeMesh m = grid_1x1();
  EXPECT_REF(edge_for_operation(m, E(2)).value, E(2));
  EXPECT_REF(edge_for_operation(m, H(3)).value, E(2));
  EXPECT_EQ(edge_for_operation(m, ElementRef()).check.reason, "select an edge first");
  EXPECT_EQ(edge_for_operation(m, V(3)).check.reason, "v3 is a vertex; select an edge (or one of its halfedges) first");
  EXPECT_EQ(edge_for_operation(m, F(0)).check.reason, "f0 is a face; select an edge (or one of its halfedges) first");
  EXPECT_EQ(edge_for_operation(m, E(9)).check.reason, "e9 does not exist (edges e0..e4)");
  m.set_edge(H(3), EdgeId());
  EXPECT_EQ(edge_for_operation(m, H(3)).check.reason, "h3.edge is - (a null pointer)");
}

TEST(Actions, FlipKeepsTheEdgeSelectedAndRefusalsSayWhy) {
  MeshDocument doc = make_document(grid_1x1());
  Selection sel{H(2), {}};
  ASSERT_TRUE(flip_selected(doc, sel).ok);
  EXPECT_REF(sel.selected, H(2));  // the halfedge survives too
  EXPECT_EQ(doc.last.label, "flip e2");
  EXPECT_EQ(doc.message.text, "flip e2: 11 fields changed");

  sel.selected = E(0);
  const HalfedgeMesh before = doc.mesh;
  EXPECT_FALSE(flip_selected(doc, sel).ok);
  EXPECT_TRUE(doc.mesh.same_as(before));
  EXPECT_REF(sel.selected, E(0));
  EXPECT_EQ(doc.message.severity, Severity::Warning);
  EXPECT_EQ(doc.message.text.rfind("flip e0: ", 0), 0u) << doc.message.text;

  sel.selected = V(1);
  EXPECT_FALSE(flip_selected(doc, sel).ok);
  EXPECT_EQ(doc.message.text, "flip: v1 is a vertex; select an edge (or one of its halfedges) first");
}

TEST(Actions, SplitNamesTheNewVertexAndCollapseSelectsTheSurvivor) {
  MeshDocument doc = make_document(grid_1x1());
  Selection sel{E(2), {}};
  ASSERT_TRUE(split_selected(doc, sel).ok);
  EXPECT_REF(sel.selected, E(2));
  EXPECT_TRUE(doc.message.text.ends_with("; new vertex v4")) << doc.message.text;
  EXPECT_TRUE(doc.mesh.alive(V(4)));

  MeshDocument grid = make_document(build_halfedge_mesh(make_grid(2, 2)));
  Selection s{E(2), {}};  // v4 (centre) - v0; v4 survives
  ASSERT_TRUE(collapse_selected(grid, s).ok);
  EXPECT_REF(s.selected, V(4));
  EXPECT_FALSE(grid.mesh.alive(E(2)));
  EXPECT_TRUE(grid.message.text.ends_with("; v4 remains")) << grid.message.text;
  ASSERT_TRUE(undo_edit(grid, s));
  EXPECT_REF(s.selected, V(4));  // v4 existed before the collapse too
  EXPECT_TRUE(grid.mesh.alive(E(2)));
}

TEST(Actions, NavigationMovesTheSelectionOrExplains) {
  MeshDocument doc = make_document(grid_1x1());
  Selection sel{H(0), {}};
  EXPECT_TRUE(navigate_selection(doc, sel, NavStep::Next));
  EXPECT_REF(sel.selected, H(1));
  EXPECT_EQ(doc.message.text, "N: selected h1");
  EXPECT_TRUE(navigate_selection(doc, sel, NavStep::Twin));
  EXPECT_REF(sel.selected, H(9));
  EXPECT_TRUE(navigate_selection(doc, sel, NavStep::Face));
  EXPECT_REF(sel.selected, B(0));
  EXPECT_TRUE(navigate_selection(doc, sel, NavStep::Face));  // b0.halfedge.face is b0 itself
  EXPECT_REF(sel.selected, B(0));
  doc.mesh.set_next(H(6), H(40));  // b0.halfedge = h6, whose next is now missing
  EXPECT_FALSE(navigate_selection(doc, sel, NavStep::Next));
  EXPECT_REF(sel.selected, B(0));
  EXPECT_EQ(doc.message.text, "N (next): b0.halfedge is h6; h6.next is h40, which does not exist (halfedges h0..h9)");
  EXPECT_EQ(doc.message.severity, Severity::Warning);
}

TEST(Actions, SelectElementRefusesMissingIds) {
  MeshDocument doc = make_document(grid_1x1());
  Selection sel;
  EXPECT_TRUE(select_element(doc, sel, F(1)));
  EXPECT_REF(sel.selected, F(1));
  EXPECT_FALSE(select_element(doc, sel, F(5)));
  EXPECT_REF(sel.selected, F(1));
  EXPECT_EQ(doc.message.text, "cannot select: f5 does not exist (faces f0..f1)");
}

TEST(Actions, LoopSubdivisionAllAtOnce) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_tetrahedron()));
  Selection sel{V(2), {}};
  ASSERT_TRUE(loop_subdivide_all(doc, sel).ok);
  EXPECT_EQ(doc.mesh.num_vertices(), 4u + 6u);
  EXPECT_EQ(doc.mesh.num_faces(), 16u);
  EXPECT_REF(sel.selected, V(2));  // original vertices keep their ids
  EXPECT_EQ(doc.last.label, "Loop subdivision");
}

TEST(Actions, LoopSubdivisionPhaseByPhase) {
  const HalfedgeMesh start = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh reference = start;
  ASSERT_TRUE(loop_subdivide(reference).ok);

  MeshDocument doc = make_document(start);
  Selection sel;
  EXPECT_EQ(next_loop_phase_label(doc), "Loop 1/4: compute new positions");
  ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);  // phase 1 changes nothing
  EXPECT_TRUE(doc.mesh.same_as(start));
  EXPECT_FALSE(doc.history.can_undo());
  EXPECT_EQ(doc.message.text,
            "Loop 1/4: compute new positions: positions for 4 vertices and 6 edge points; nothing moved yet");
  EXPECT_EQ(next_loop_phase_label(doc), "Loop 2/4: split every original edge");

  ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);
  EXPECT_EQ(doc.mesh.num_vertices(), 10u);
  EXPECT_EQ(doc.last.label, "Loop 2/4: split every original edge");
  ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);
  EXPECT_EQ(doc.last.label, "Loop 3/4: flip new edges joining an old and a new vertex");
  ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);
  EXPECT_EQ(doc.last.label, "Loop 4/4: move every vertex to its new position");
  for (const FieldChange& c : doc.last.changes) EXPECT_EQ(c.field, "position");  // phase 4 only moves
  EXPECT_TRUE(doc.mesh.same_as(reference));
  EXPECT_EQ(doc.history.undo_depth(), 3u);
  EXPECT_EQ(next_loop_phase_label(doc), "Loop 1/4: compute new positions");

  // Undo in the middle: the next press starts again at phase 1 on the restored mesh.
  ASSERT_TRUE(undo_edit(doc, sel));
  ASSERT_TRUE(undo_edit(doc, sel));
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_TRUE(doc.mesh.same_as(start));
  ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);
  ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);
  ASSERT_TRUE(undo_edit(doc, sel));
  EXPECT_EQ(next_loop_phase_label(doc), "Loop 1/4: compute new positions");
  ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);
  EXPECT_EQ(doc.message.text.rfind("the mesh changed after Loop phase 2; starting again. Loop 1/4", 0), 0u)
      << doc.message.text;
  for (int phase = 2; phase <= 4; ++phase) ASSERT_TRUE(loop_subdivide_step(doc, sel).ok);
  EXPECT_TRUE(doc.mesh.same_as(reference));
}

TEST(Actions, LoopRefusalLeavesTheMeshAlone) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_cube_quads()));
  Selection sel;
  EXPECT_FALSE(loop_subdivide_step(doc, sel).ok);
  EXPECT_EQ(doc.message.severity, Severity::Warning);
  EXPECT_EQ(doc.loop.next_phase, 1);
  EXPECT_FALSE(loop_subdivide_all(doc, sel).ok);
  EXPECT_FALSE(doc.history.can_undo());
}

}  // namespace
}  // namespace meshedit
