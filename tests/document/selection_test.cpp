// Navigation (N T V E F H) from every element kind with exact targets, refusals on broken pointers, and
// keep_if_alive after edits and undo.
#include <string>

#include <gtest/gtest.h>

#include "core/mesh_ops.h"
#include "document/document_actions.h"
#include "document/document_test_support.h"
#include "document/mesh_document.h"
#include "document/selection.h"

namespace meshedit {
namespace {

using namespace document_testing;

std::string go(const HalfedgeMesh& m, ElementRef from, NavStep step) {
  const OpResult<ElementRef> r = navigate(m, from, step);
  return r ? format_id(r.value) : "refused: " + r.check.reason;
}

TEST(Navigate, FromAHalfedge) {
  const HalfedgeMesh m = grid_1x1();
  EXPECT_EQ(go(m, H(0), NavStep::Next), "h1");
  EXPECT_EQ(go(m, H(0), NavStep::Twin), "h6");
  EXPECT_EQ(go(m, H(0), NavStep::Vertex), "v0");
  EXPECT_EQ(go(m, H(0), NavStep::Edge), "e0");
  EXPECT_EQ(go(m, H(0), NavStep::Face), "f0");
  EXPECT_EQ(go(m, H(7), NavStep::Face), "b0");
  EXPECT_EQ(go(m, H(9), NavStep::Next), "h6");
  EXPECT_EQ(go(m, H(3), NavStep::Twin), "h2");
  EXPECT_EQ(go(m, H(0), NavStep::Halfedge),
            "refused: h0 is already a halfedge; H goes from a vertex, edge or face to its halfedge");
}

TEST(Navigate, FromAVertexEdgeFaceAndBoundaryThroughTheirHalfedge) {
  const HalfedgeMesh m = grid_1x1();
  // v3.halfedge = h9 (its outgoing boundary halfedge).
  EXPECT_EQ(go(m, V(3), NavStep::Halfedge), "h9");
  EXPECT_EQ(go(m, V(3), NavStep::Next), "h6");
  EXPECT_EQ(go(m, V(3), NavStep::Twin), "h1");
  EXPECT_EQ(go(m, V(3), NavStep::Vertex), "v3");
  EXPECT_EQ(go(m, V(3), NavStep::Edge), "e1");
  EXPECT_EQ(go(m, V(3), NavStep::Face), "b0");
  // e2.halfedge = h2 (v3 -> v0 in f0).
  EXPECT_EQ(go(m, E(2), NavStep::Halfedge), "h2");
  EXPECT_EQ(go(m, E(2), NavStep::Twin), "h3");
  EXPECT_EQ(go(m, E(2), NavStep::Next), "h0");
  EXPECT_EQ(go(m, E(2), NavStep::Vertex), "v3");
  EXPECT_EQ(go(m, E(2), NavStep::Edge), "e2");
  EXPECT_EQ(go(m, E(2), NavStep::Face), "f0");
  // f1.halfedge = h3.
  EXPECT_EQ(go(m, F(1), NavStep::Halfedge), "h3");
  EXPECT_EQ(go(m, F(1), NavStep::Next), "h4");
  EXPECT_EQ(go(m, F(1), NavStep::Twin), "h2");
  EXPECT_EQ(go(m, F(1), NavStep::Vertex), "v0");
  EXPECT_EQ(go(m, F(1), NavStep::Edge), "e2");
  EXPECT_EQ(go(m, F(1), NavStep::Face), "f1");
  // b0.halfedge = h6.
  EXPECT_EQ(go(m, B(0), NavStep::Halfedge), "h6");
  EXPECT_EQ(go(m, B(0), NavStep::Next), "h7");
  EXPECT_EQ(go(m, B(0), NavStep::Twin), "h0");
  EXPECT_EQ(go(m, B(0), NavStep::Vertex), "v1");
  EXPECT_EQ(go(m, B(0), NavStep::Face), "b0");
}

TEST(Navigate, WalkingNextAroundAFaceComesBack) {
  const HalfedgeMesh m = grid_1x1();
  ElementRef at = H(3);
  std::string path;
  for (int i = 0; i < 3; ++i) {
    at = navigate(m, at, NavStep::Next).value;
    path += format_id(at) + " ";
  }
  EXPECT_EQ(path, "h4 h5 h3 ");
}

TEST(Navigate, RefusesBrokenPointersWithTheirName) {
  HalfedgeMesh m = grid_1x1();
  EXPECT_EQ(go(m, ElementRef(), NavStep::Next), "refused: nothing is selected");
  EXPECT_EQ(go(m, H(99), NavStep::Next), "refused: h99 does not exist (halfedges h0..h9)");
  EXPECT_EQ(go(m, F(2), NavStep::Halfedge), "refused: f2 does not exist (faces f0..f1)");

  m.set_next(H(0), H(999));
  EXPECT_EQ(go(m, H(0), NavStep::Next), "refused: h0.next is h999, which does not exist (halfedges h0..h9)");
  EXPECT_EQ(go(m, F(0), NavStep::Next),
            "refused: f0.halfedge is h0; h0.next is h999, which does not exist (halfedges h0..h9)");
  m.set_twin(H(0), HalfedgeId());
  EXPECT_EQ(go(m, H(0), NavStep::Twin), "refused: h0.twin is - (a null pointer)");
  m.set_face(H(0), FaceId());
  EXPECT_EQ(go(m, H(0), NavStep::Face), "refused: h0.face is - (a null pointer)");
  m.set_vertex(H(0), VertexId());
  EXPECT_EQ(go(m, H(0), NavStep::Vertex), "refused: h0.vertex is - (a null pointer)");
  m.set_edge(H(0), EdgeId(7));
  EXPECT_EQ(go(m, H(0), NavStep::Edge), "refused: h0.edge is e7, which does not exist (edges e0..e4)");
  m.set_halfedge(V(1), HalfedgeId(500));
  EXPECT_EQ(go(m, V(1), NavStep::Halfedge), "refused: v1.halfedge is h500, which does not exist (halfedges h0..h9)");
  EXPECT_EQ(go(m, V(1), NavStep::Next), "refused: v1.halfedge is h500, which does not exist (halfedges h0..h9)");

  m.delete_element(H(2));
  EXPECT_EQ(go(m, H(1), NavStep::Next), "refused: h1.next is h2, which is dead");
  EXPECT_EQ(go(m, E(2), NavStep::Halfedge), "refused: e2.halfedge is h2, which is dead");
  EXPECT_EQ(go(m, H(2), NavStep::Next), "refused: h2 is dead");
  // The face kind of an out-of-range face is named as such.
  m.set_face(H(4), FaceId::face(40));
  EXPECT_EQ(go(m, H(4), NavStep::Face), "refused: h4.face is f40, which does not exist (faces f0..f1)");
  m.set_face(H(5), FaceId::boundary(3));
  EXPECT_EQ(go(m, H(5), NavStep::Face), "refused: h5.face is b3, which does not exist (boundary loops b0..b0)");
}

TEST(ReferenceState, ClassifiesEveryCase) {
  HalfedgeMesh m = grid_1x1();
  m.delete_element(E(4));
  EXPECT_EQ(reference_state(m, E(3)), RefState::Live);
  EXPECT_EQ(reference_state(m, E(4)), RefState::Dead);
  EXPECT_EQ(reference_state(m, E(5)), RefState::OutOfRange);
  EXPECT_EQ(reference_state(m, EdgeId()), RefState::Null);
  EXPECT_TRUE(in_range(m, E(4)));
  EXPECT_FALSE(in_range(m, E(5)));
  EXPECT_EQ(reference_problem(m, E(3)), "");
  EXPECT_EQ(reference_problem(m, E(4)), "e4 is dead");
  EXPECT_EQ(reference_problem(m, V(4)), "v4 does not exist (vertices v0..v3)");
  EXPECT_EQ(reference_problem(m, ElementRef(ElementKind::Edge, kInvalidIndex)), "- is no edge (a null pointer)");
  const HalfedgeMesh empty;
  EXPECT_EQ(reference_problem(empty, V(0)), "v0 does not exist (there are no vertices)");
}

TEST(KeepIfAlive, SelectionSurvivesWhereItsElementSurvives) {
  MeshDocument doc = make_document(grid_1x1());
  Selection sel{E(2), H(3)};
  ASSERT_TRUE(flip_selected(doc, sel).ok);
  EXPECT_REF(sel.selected, E(2));  // flip keeps every id
  EXPECT_REF(sel.hovered, H(3));
  ASSERT_TRUE(split_selected(doc, sel).ok);
  EXPECT_REF(sel.selected, E(2));  // e2 is now the half m-b
  sel.selected = V(4);             // the new vertex
  sel.hovered = H(15);
  ASSERT_TRUE(undo_edit(doc, sel));  // v4 and h15 no longer exist
  EXPECT_FALSE(sel.selected.valid());
  EXPECT_FALSE(sel.hovered.valid());
  ASSERT_TRUE(redo_edit(doc, sel));
  sel.selected = E(5);  // a-m, made by the split
  EXPECT_FALSE(keep_if_alive(sel, doc.mesh));
  EXPECT_REF(sel.selected, E(5));
}

TEST(KeepIfAlive, CollapseDeselectsTheDeadAndKeepsTheLiving) {
  // make_grid(2, 2): e2 joins the centre v4 to the corner v0 (e2.halfedge runs v4 -> v0), so v4 survives.
  HalfedgeMesh m = build_halfedge_mesh(make_grid(2, 2));
  ASSERT_TRUE(collapse(m, E(2)).ok());
  Selection sel{E(2), V(4)};
  EXPECT_TRUE(keep_if_alive(sel, m));
  EXPECT_FALSE(sel.selected.valid());
  EXPECT_REF(sel.hovered, V(4));
  Selection merged{V(1), V(0)};
  EXPECT_FALSE(keep_if_alive(merged, m));
  EXPECT_REF(merged.selected, V(1));
  EXPECT_FALSE(merged.hovered.valid());
  Selection none;
  EXPECT_FALSE(keep_if_alive(none, m));
}

}  // namespace
}  // namespace meshedit
