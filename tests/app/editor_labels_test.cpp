// EditorApp's labels over the mesh view: on the flip lesson's diamond the lesson's names and the id labels are placed
// together, none overlapping and all inside the window, h0 h1 e0 f0 f1 among them; the frame's placement is kept
// (last_labels) and emptied outside the mesh view; the selected halfedge is labelled though the arrows are off.
// Needs an OpenGL context: a surfaceless EGL one, skipped where none exists.
#include <gtest/gtest.h>

#include <algorithm>

#include "app/editor_app.h"
#include "core/bezier.h"
#include "render/gl_test_support.h"
#include "support/imgui_harness.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

constexpr int kWidth = 1280, kHeight = 800;

class EditorLabels : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    app_ = std::make_unique<EditorApp>();
  }
  void TearDown() override { app_.reset(); }

  void frame() {
    ui_testing::ImGuiHarness imgui(ImVec2(kWidth, kHeight));
    imgui.frame([&] { app_->frame(kWidth, kHeight, 16.0f); });
  }

  const PlacedLabel* find(const std::string& text, LabelSource source) const {
    for (const PlacedLabel& l : app_->view().last_labels().placed) {
      if (l.text == text && l.source == source) return &l;
    }
    return nullptr;
  }

  std::unique_ptr<EditorApp> app_;
};

TEST_F(EditorLabels, TheFlipLessonsNamesAndIdsArePlacedApartInsideTheView) {
  ASSERT_TRUE(app_->lessons().open(meshedit::testing::source_dir() / "lessons" / "4_edge_flip.lua"));
  frame();
  frame();
  const LabelPlacement& labels = app_->view().last_labels();
  ASSERT_FALSE(labels.placed.empty());
  const LabelRect window{{0.0, 0.0}, {double(kWidth), double(kHeight)}};
  for (size_t i = 0; i < labels.placed.size(); ++i) {
    EXPECT_TRUE(labels.placed[i].rect.inside(window)) << labels.placed[i].text;
    for (size_t j = i + 1; j < labels.placed.size(); ++j) {
      EXPECT_FALSE(labels.placed[i].rect.overlaps(labels.placed[j].rect))
          << labels.placed[i].text << " " << labels.placed[j].text;
    }
  }
  // The lesson names every element; each of its labels is drawn, at its element.
  for (const auto& [element, text] : app_->lessons().marks().labels) {
    const PlacedLabel* label = find(text, LabelSource::Lesson);
    if (element.kind == ElementKind::Halfedge || element.kind == ElementKind::Vertex ||
        element.kind == ElementKind::Face) {
      ASSERT_NE(label, nullptr) << text;
      EXPECT_EQ(label->element, element) << text;
    }
  }
  const PlacedLabel* e0 = find("e0", LabelSource::Id);
  ASSERT_NE(e0, nullptr);
  EXPECT_EQ(e0->element, ElementRef(EdgeId(0)));
  for (const char* name : {"h0", "h1", "f0", "f1"}) EXPECT_NE(find(name, LabelSource::Lesson), nullptr) << name;
  // The lesson's "f0" is f0's id too: drawn once.
  EXPECT_EQ(find("f0", LabelSource::Id), nullptr);

  // A curve fills the window: no labels, and the report says so.
  BezierCurve curve;
  curve.control_points = {{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}};
  app_->view().show_curve(curve);
  frame();
  EXPECT_TRUE(app_->view().last_labels().placed.empty());
  EXPECT_EQ(app_->view().last_labels().dropped, 0u);
}

TEST_F(EditorLabels, TheSelectedHalfedgeIsLabelledThoughArrowsAreOff) {
  // The start cube is small: its visible elements have id labels, but no halfedge while the arrows are off.
  app_->show_start_mesh();
  ViewRequest arrows_off;
  arrows_off.halfedges = false;
  app_->view().apply_view_request(arrows_off);
  frame();
  EXPECT_GT(app_->view().last_labels().placed.size(), 20u);
  for (const PlacedLabel& l : app_->view().last_labels().placed)
    EXPECT_NE(l.element.kind, ElementKind::Halfedge) << l.text;
  ASSERT_NE(find("f2", LabelSource::Id), nullptr);  // a face turned to the camera
  const HalfedgeId h = app_->document().mesh.halfedge(FaceId::face(2));
  app_->selection().selected = h;
  frame();
  const PlacedLabel* label = find(format_id(h), LabelSource::Id);
  ASSERT_NE(label, nullptr);
  EXPECT_EQ(label->element, ElementRef(h));
}

}  // namespace
}  // namespace meshedit
