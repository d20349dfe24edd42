// The status bar (validation state, its "select" button, validation on demand for big meshes) and every panel
// together on meshes broken in the ways scripts break them: each element selected in turn, frames still render.
#include <cmath>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_ops.h"
#include "core/validate.h"
#include "document/document_actions.h"
#include "ui/inspector.h"
#include "ui/pointer_tables.h"
#include "ui/status_bar.h"
#include "ui_test_support.h"

namespace meshedit {
namespace {

using namespace ui_testing;
using namespace document_testing;

struct StatusFixture {
  MeshDocument doc;
  Selection sel;
  StatusBarState state;
  UiProbe probe;
  ImGuiHarness imgui;
  float height = 0.0f;
  explicit StatusFixture(HalfedgeMesh mesh) : doc(make_document(std::move(mesh))) { state.probe = &probe; }
  void draw() {
    probe.clear();
    height = draw_status_bar(doc, sel, state, 16.7f);
  }
  int frame() {
    return imgui.frame([&] { draw(); });
  }
};

TEST(StatusBar, ValidMeshShowsGreenAndValidatesOnce) {
  StatusFixture t(grid_1x1());
  for (int i = 0; i < 5; ++i) EXPECT_GT(t.frame(), 0);
  EXPECT_GT(t.height, 0.0f);
  EXPECT_EQ(t.doc.validation.computations, 1u);
  EXPECT_EQ(t.probe.find("select-culprit"), nullptr);
}

TEST(StatusBar, SelectButtonSelectsTheCulprit) {
  StatusFixture t(grid_1x1());
  t.doc.mesh.set_twin(H(0), H(1));  // twin of twin broken
  t.frame();
  t.frame();
  const ValidationReport& report = cached_validation(t.doc);
  ASSERT_FALSE(report.ok());
  const UiProbe::Item* button = t.probe.find("select-culprit");
  ASSERT_NE(button, nullptr);
  EXPECT_EQ(button->element, report.violations.front().element);
  t.imgui.click(button->center(), [&] { t.draw(); });
  EXPECT_EQ(format_id(t.sel.selected), format_id(report.violations.front().element));
  EXPECT_EQ(t.doc.validation.computations, 1u);  // five frames, one validation
}

TEST(StatusBar, BigMeshesAreValidatedOnRequest) {
  StatusFixture t(grid_1x1());
  t.state.auto_validate_max_halfedges = 5;  // pretend ten halfedges is big
  t.frame();
  t.frame();
  EXPECT_EQ(t.doc.validation.computations, 0u);
  const UiProbe::Item* button = t.probe.find("validate");
  ASSERT_NE(button, nullptr);
  t.imgui.click(button->center(), [&] { t.draw(); });
  EXPECT_EQ(t.doc.validation.computations, 1u);
  EXPECT_TRUE(validation_is_current(t.doc));
  t.frame();
  EXPECT_EQ(t.probe.find("validate"), nullptr);  // the result is shown until the mesh changes
  EXPECT_EQ(t.doc.validation.computations, 1u);
}

// Once a big mesh has been validated, a local edit is validated by itself (from its patch, no whole-mesh pass).
TEST(StatusBar, BigMeshesStayValidatedThroughLocalEdits) {
  StatusFixture t(grid_1x1());
  t.state.auto_validate_max_halfedges = 5;
  t.frame();
  t.imgui.click(t.probe.find("validate")->center(), [&] { t.draw(); });
  ASSERT_TRUE(validation_is_current(t.doc));
  ASSERT_TRUE(apply_operation(t.doc, "flip e2", [](HalfedgeMesh& m) { return flip(m, E(2)); }).ok());
  t.frame();
  EXPECT_EQ(t.probe.find("validate"), nullptr);
  EXPECT_TRUE(validation_is_current(t.doc));
  EXPECT_TRUE(t.doc.validation.value.from_patch);
  EXPECT_EQ(t.doc.validation.computations, 2u);
}

// A local edit that breaks a big mesh is not validated by itself: the report needs a whole-mesh pass, which waits
// for the button, as for any unvalidated big mesh.
TEST(StatusBar, ABigMeshBrokenByAnEditWaitsForTheButton) {
  StatusFixture t(grid_1x1());
  t.state.auto_validate_max_halfedges = 5;
  t.frame();
  t.imgui.click(t.probe.find("validate")->center(), [&] { t.draw(); });
  ASSERT_TRUE(apply_operation(t.doc, "break", [](HalfedgeMesh& m) {
                m.set_twin(H(0), H(1));
                return Check::yes();
              }).ok);
  t.frame();
  t.frame();
  EXPECT_EQ(t.doc.validation.computations, 1u);
  EXPECT_EQ(t.doc.patch_check.computations, 1u);  // once, not once per frame
  const UiProbe::Item* button = t.probe.find("validate");
  ASSERT_NE(button, nullptr);
  t.imgui.click(button->center(), [&] { t.draw(); });
  EXPECT_FALSE(cached_validation(t.doc).ok());
  EXPECT_NE(t.probe.find("select-culprit"), nullptr);
}

TEST(StatusBar, ErrorMessagesOfferTheirElement) {
  StatusFixture t(grid_1x1());
  set_message(t.doc, Severity::Error, "f1 is upside down", F(1));
  t.frame();
  t.frame();
  const UiProbe::Item* button = t.probe.find("select-message", F(1));
  ASSERT_NE(button, nullptr);
  t.imgui.click(button->center(), [&] { t.draw(); });
  EXPECT_EQ(format_id(t.sel.selected), "f1");
}

TEST(StatusBar, ShowsTheUpAxisTheAppFilledIn) {
  StatusFixture t(grid_1x1());
  t.frame();
  EXPECT_EQ(t.probe.find("up-axis"), nullptr);  // nothing filled in, nothing shown
  t.state.up_axis = "Z up";
  t.frame();
  const UiProbe::Item* brief = t.probe.find("up-axis");
  ASSERT_NE(brief, nullptr);
  const float brief_width = brief->max.x - brief->min.x;
  EXPECT_GT(brief_width, 0.0f);
  t.state.up_axis = "Y up (from the file)";
  t.frame();
  const UiProbe::Item* longer = t.probe.find("up-axis");
  ASSERT_NE(longer, nullptr);
  EXPECT_GT(longer->max.x - longer->min.x, brief_width * 3);  // the text drawn is the one given
}

// Every element of every kind (live, dead, one past the end) selected in turn, all panels drawn for two frames.
void draw_everything_on(MeshDocument& doc) {
  ImGuiHarness imgui;
  Selection sel;
  InspectorState inspector;
  TablesState tables;
  StatusBarState status;
  const auto draw = [&] {
    draw_pointer_tables(doc, sel, tables);
    draw_inspector(doc, sel, inspector);
    draw_status_bar(doc, sel, status, 1.0f);
  };
  for (ElementKind kind :
       {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face, ElementKind::Boundary}) {
    for (uint32_t i = 0; i <= doc.mesh.capacity(kind); ++i) {
      sel.selected = ElementRef(kind, i);
      sel.hovered = ElementRef(kind, i);
      imgui.frame(draw);
      ASSERT_GT(imgui.frame(draw), 0) << format_id(sel.selected);
      for (NavStep step :
           {NavStep::Next, NavStep::Twin, NavStep::Vertex, NavStep::Edge, NavStep::Face, NavStep::Halfedge}) {
        Selection walk{ElementRef(kind, i), {}};
        // Refused or not, never crashes; when it moves, it lands on a live element.
        if (navigate_selection(doc, walk, step)) {
          EXPECT_TRUE(doc.mesh.alive(walk.selected)) << format_id(walk.selected);
        }
      }
    }
  }
  tables.active = TableTab::Changes;
  imgui.frame(draw);
  EXPECT_GT(imgui.frame(draw), 0);
}

TEST(Panels, SurviveARhoCycle) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_grid(2, 2)));
  ASSERT_TRUE(apply_operation(doc, "bend next", [](HalfedgeMesh& m) {
                m.set_next(H(2), H(1));  // f0: h0 -> h1 -> h2 -> h1 -> ... never back to h0
                m.set_next(H(7), H(7));  // and a halfedge that is its own next
                return Check::yes();
              }).ok);
  ASSERT_FALSE(cached_validation(doc).ok());
  draw_everything_on(doc);
}

TEST(Panels, SurviveDeadAndMissingReferences) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_grid(2, 2)));
  ASSERT_TRUE(apply_operation(doc, "break", [](HalfedgeMesh& m) {
                m.delete_element(V(4));                 // the centre, still referenced by six halfedges
                m.delete_element(H(5));                 // referenced by its twin, its prev and maybe a vertex
                m.set_twin(H(0), HalfedgeId(1000));     // out of range
                m.set_face(H(1), FaceId::boundary(9));  // a boundary loop that does not exist
                m.set_halfedge(F(3), HalfedgeId());     // null
                m.set_halfedge(V(0), HalfedgeId(77));   // out of range
                m.set_position(V(1), glm::dvec3(std::nan(""), 0, 0));
                return Check::yes();
              }).ok);
  ASSERT_FALSE(cached_validation(doc).ok());
  draw_everything_on(doc);
}

TEST(Panels, SurviveASubdividedMeshAndItsUndo) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_icosahedron()));
  Selection sel{V(3), {}};
  ASSERT_TRUE(loop_subdivide_all(doc, sel).ok);
  draw_everything_on(doc);
  ASSERT_TRUE(undo_edit(doc, sel));
  draw_everything_on(doc);
}

}  // namespace
}  // namespace meshedit
