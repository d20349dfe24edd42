// The inspector's derived facts (exact walks on the 1x1 grid, bounded walks on broken meshes) and its links,
// clicked through headless ImGui.
#include <cmath>

#include <gtest/gtest.h>

#include "document/mesh_document.h"
#include "ui/inspector.h"
#include "ui_test_support.h"

namespace meshedit {
namespace {

using namespace ui_testing;
using namespace document_testing;

std::string walk_text(const ElementFacts& f) {
  std::string s;
  for (const WalkEntry& w : f.walk) s += format_id(w.halfedge) + ":" + format_id(w.vertex) + " ";
  return s;
}

TEST(InspectElement, VertexFan) {
  const HalfedgeMesh m = grid_1x1();
  const ElementFacts f = inspect_element(m, V(0), 32);
  EXPECT_EQ(f.state, RefState::Live);
  EXPECT_EQ(walk_text(f), "h7:v2 h3:v3 h0:v1 ");  // outgoing halfedge : the neighbour it reaches
  EXPECT_TRUE(f.closed);
  EXPECT_EQ(f.degree(), 3u);
  EXPECT_TRUE(f.is_boundary);
}

TEST(InspectElement, FaceAndBoundaryCycles) {
  const HalfedgeMesh m = grid_1x1();
  const ElementFacts f = inspect_element(m, F(1), 32);
  EXPECT_EQ(walk_text(f), "h3:v0 h4:v3 h5:v2 ");  // each halfedge and the corner it leaves
  EXPECT_EQ(f.degree(), 3u);
  EXPECT_FALSE(f.is_boundary);
  const ElementFacts b = inspect_element(m, B(0), 32);
  EXPECT_EQ(walk_text(b), "h6:v1 h7:v0 h8:v2 h9:v3 ");
  EXPECT_EQ(b.degree(), 4u);
  EXPECT_TRUE(b.is_boundary);
  const ElementFacts cut = inspect_element(m, B(0), 2);
  EXPECT_EQ(walk_text(cut), "h6:v1 h7:v0 ");
  EXPECT_EQ(cut.walked, 4u);
}

TEST(InspectElement, EdgeAndHalfedge) {
  const HalfedgeMesh m = grid_1x1();
  const ElementFacts e = inspect_element(m, E(2), 32);
  EXPECT_REF(e.edge_twin, H(3));
  EXPECT_REF(e.edge_ends[0], V(3));
  EXPECT_REF(e.edge_ends[1], V(0));
  EXPECT_REF(e.edge_faces[0], F(0));
  EXPECT_REF(e.edge_faces[1], F(1));
  ASSERT_TRUE(e.length.has_value());
  EXPECT_EQ(*e.length, std::sqrt(2.0));
  EXPECT_FALSE(e.is_boundary);
  EXPECT_TRUE(inspect_element(m, E(0), 32).is_boundary);
  const ElementFacts h = inspect_element(m, H(4), 32);
  EXPECT_REF(h.prev, H(3));
  EXPECT_REF(h.head, V(2));
  EXPECT_FALSE(h.is_boundary);
  EXPECT_TRUE(inspect_element(m, H(8), 32).is_boundary);
}

TEST(InspectElement, BrokenMeshesGiveBoundedAnswers) {
  HalfedgeMesh m = grid_1x1();
  m.set_next(H(2), H(1));  // f0: h0 -> h1 -> h2 -> h1 -> ... a rho that never returns to h0
  const ElementFacts f = inspect_element(m, F(0), 5);
  EXPECT_FALSE(f.closed);
  EXPECT_FALSE(f.degree().has_value());
  EXPECT_EQ(walk_text(f), "h0:v0 h1:v1 h2:v3 h1:v1 h2:v3 ");
  EXPECT_EQ(f.walked, m.halfedge_capacity() + 1);  // the mesh's walk bound
  EXPECT_FALSE(inspect_element(m, H(0), 5).prev.valid());

  m.set_twin(H(7), HalfedgeId(77));  // v0's fan leaves through h7 and meets a missing twin
  const ElementFacts v = inspect_element(m, V(0), 8);
  EXPECT_FALSE(v.closed);
  EXPECT_EQ(walk_text(v), "h7:- ");
  m.delete_element(H(4));
  const ElementFacts e = inspect_element(m, E(3), 8);  // e3.halfedge = h4, dead: read as stored
  EXPECT_REF(e.edge_twin, H(8));
  m.set_halfedge(E(1), HalfedgeId(123));
  const ElementFacts missing = inspect_element(m, E(1), 8);
  EXPECT_FALSE(missing.edge_twin.valid());
  EXPECT_FALSE(missing.length.has_value());
  EXPECT_EQ(inspect_element(m, H(4), 8).state, RefState::Dead);
  EXPECT_TRUE(inspect_element(m, H(4), 8).walk.empty());
  EXPECT_EQ(inspect_element(m, V(9), 8).state, RefState::OutOfRange);
}

// Draws the inspector at the top-left corner, recording links in `probe`.
struct InspectorFixture {
  MeshDocument doc = make_document(grid_1x1());
  Selection sel;
  InspectorState state;
  UiProbe probe;
  ImGuiHarness imgui;
  InspectorFixture() { state.probe = &probe; }
  void draw() {
    probe.clear();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(500, 700));
    draw_inspector(doc, sel, state);
  }
  int frame() {
    return imgui.frame([&] { draw(); });
  }
  void click(const UiProbe::Item& item) {
    imgui.click(item.center(), [&] { draw(); });
  }
};

TEST(InspectorPanel, LinksSelectWhatTheyName) {
  InspectorFixture t;
  t.sel.selected = H(0);
  t.frame();
  EXPECT_GT(t.frame(), 0);
  const UiProbe::Item* next = t.probe.find("next");
  ASSERT_NE(next, nullptr);
  EXPECT_REF(next->element, H(1));
  t.click(*next);
  EXPECT_REF(t.sel.selected, H(1));

  t.frame();
  const UiProbe::Item* face = t.probe.find("face");
  ASSERT_NE(face, nullptr);
  EXPECT_REF(face->element, F(0));
  t.click(*face);
  EXPECT_REF(t.sel.selected, F(0));

  t.frame();  // the face lists its cycle: h0 h1 h2 with their corners
  const UiProbe::Item* corner = t.probe.find("walk-vertex", V(3));
  ASSERT_NE(corner, nullptr);
  t.click(*corner);
  EXPECT_REF(t.sel.selected, V(3));
}

TEST(InspectorPanel, HoveringALinkSetsHovered) {
  InspectorFixture t;
  t.sel.selected = E(2);
  t.frame();
  t.frame();
  const UiProbe::Item* twin = t.probe.find("twin");
  ASSERT_NE(twin, nullptr);
  ImGui::GetIO().MousePos = twin->center();
  t.frame();
  t.frame();
  EXPECT_REF(t.sel.hovered, H(3));
  EXPECT_REF(t.sel.selected, E(2));
}

TEST(InspectorPanel, BrokenReferencesAreNotFollowed) {
  InspectorFixture t;
  t.doc.mesh.set_next(H(0), H(99));
  t.doc.mesh.delete_element(H(6));
  t.sel.selected = H(0);
  t.frame();
  t.frame();
  const UiProbe::Item* next = t.probe.find("next");
  const UiProbe::Item* twin = t.probe.find("twin");
  ASSERT_NE(next, nullptr);
  ASSERT_NE(twin, nullptr);
  t.click(*next);
  EXPECT_REF(t.sel.selected, H(0));
  t.click(*twin);
  EXPECT_REF(t.sel.selected, H(0));
}

TEST(InspectorPanel, FactsAreComputedOncePerMeshState) {
  InspectorFixture t;
  t.sel.selected = V(0);
  for (int i = 0; i < 5; ++i) t.frame();
  EXPECT_EQ(t.state.facts_computations, 1u);
  t.sel.selected = V(1);
  t.frame();
  t.frame();
  EXPECT_EQ(t.state.facts_computations, 2u);
  ASSERT_TRUE(apply_operation(t.doc, "move v1", [](HalfedgeMesh& m) {
                m.set_position(V(1), glm::dvec3(2, 0, 0));
                return Check::yes();
              }).ok);
  t.frame();
  EXPECT_EQ(t.state.facts_computations, 3u);
}

}  // namespace
}  // namespace meshedit
