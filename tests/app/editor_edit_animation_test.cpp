// The window's edits animate (EditorApp with app/edit_animator.h): with the policy on, F on the diamond's edge keeps
// animating() true for a quarter second of frame time and then false, the flip's corners are the diamond's, and Ctrl+Z
// plays it back; with the policy off (the default, as in tests and scripted runs) or the setting off, nothing animates
// and the flip is done all the same. Drives a real EditorApp on a surfaceless EGL context, skipped where none exists.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <variant>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "render/gl_test_support.h"
#include "support/imgui_harness.h"

namespace meshedit {
namespace {

constexpr int kWidth = 1280, kHeight = 800;
constexpr float kFrameMs = 16.0f;

HalfedgeMesh diamond() {
  PolygonMesh p;
  p.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({1, 0, 3});
  return build_halfedge_mesh(p);
}

class EditorEditAnimation : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    app_ = std::make_unique<EditorApp>();
    app_->show_mesh(diamond(), "diamond");
    app_->selection().selected = EdgeId(0);
    frame();
  }
  void TearDown() override { app_.reset(); }

  void frame() {
    ui_testing::ImGuiHarness imgui(ImVec2(kWidth, kHeight));
    imgui.frame([&] { app_->frame(kWidth, kHeight, kFrameMs); });
  }
  // Presses the key, draws the frame that shows it, then frames until animating() is false; the milliseconds of frame
  // time it stayed true for after that first frame (capped at two seconds).
  float animated_ms_after_key(int key, KeyMods mods = {}) {
    app_->handle_key(key, mods);
    frame();
    float ms = 0.0f;
    while (app_->animating() && ms < 2000.0f) {
      frame();
      ms += kFrameMs;
    }
    return ms;
  }
  // The edge e0's ends now.
  std::pair<VertexId, VertexId> ends() {
    const HalfedgeMesh& mesh = app_->document().mesh;
    const HalfedgeId h = mesh.halfedge(EdgeId(0));
    return {mesh.vertex(h), mesh.vertex(mesh.twin(h))};
  }

  std::unique_ptr<EditorApp> app_;
};

TEST_F(EditorEditAnimation, OffByDefaultTheFlipIsDoneWithoutAnimating) {
  EXPECT_FALSE(app_->edits_animate());
  EXPECT_EQ(animated_ms_after_key(GLFW_KEY_F), 0.0f);
  EXPECT_FALSE(app_->view().edit_animator().playing());
  EXPECT_EQ(ends(), std::make_pair(VertexId(3), VertexId(2)));  // flipped: e0 runs d->c
}

TEST_F(EditorEditAnimation, AFlipAnimatesForAQuarterSecondAndItsUndoPlaysBack) {
  app_->view().set_edit_animation_policy(EditAnimationPolicy::Always);
  app_->handle_key(GLFW_KEY_F, {});
  EXPECT_EQ(ends(), std::make_pair(VertexId(3), VertexId(2)));  // the mesh is flipped at once
  frame();
  ASSERT_TRUE(app_->animating());
  const std::optional<EditAnimation>& animation = app_->view().edit_animator().animation();
  ASSERT_TRUE(animation);
  EXPECT_EQ(animation->direction, PlayDirection::Forward);
  const FlipMotion& flip = std::get<FlipMotion>(animation->motion);
  EXPECT_EQ(flip.a, glm::dvec3(-1, 0, 0));
  EXPECT_EQ(flip.b, glm::dvec3(1, 0, 0));
  EXPECT_EQ(flip.c, glm::dvec3(0, 1, 0));
  EXPECT_EQ(flip.d, glm::dvec3(0, -1, 0));
  float ms = 0.0f;
  while (app_->animating() && ms < 2000.0f) {
    frame();
    ms += kFrameMs;
  }
  EXPECT_GE(ms, 200.0f);
  EXPECT_LE(ms, 300.0f);
  EXPECT_FALSE(app_->view().edit_animator().playing());

  const float undo_ms = animated_ms_after_key(GLFW_KEY_Z, {true, false});
  EXPECT_GE(undo_ms, 200.0f);
  EXPECT_LE(undo_ms, 300.0f);
  EXPECT_EQ(ends(), std::make_pair(VertexId(0), VertexId(1)));  // undone: e0 runs a->b again
  // The frames after it do not play it again.
  frame();
  EXPECT_FALSE(app_->animating());
}

TEST_F(EditorEditAnimation, TheUndoPlaysBackward) {
  app_->view().set_edit_animation_policy(EditAnimationPolicy::Always);
  app_->handle_key(GLFW_KEY_S, {});
  frame();
  ASSERT_TRUE(app_->view().edit_animator().animation());
  EXPECT_EQ(app_->view().edit_animator().animation()->direction, PlayDirection::Forward);
  app_->handle_key(GLFW_KEY_Z, {true, false});
  frame();
  ASSERT_TRUE(app_->view().edit_animator().animation());
  EXPECT_EQ(app_->view().edit_animator().animation()->direction, PlayDirection::Backward);
  EXPECT_EQ(std::get<SplitMotion>(app_->view().edit_animator().animation()->motion).m, glm::dvec3(0, 0, 0));
}

TEST_F(EditorEditAnimation, TheWindowsPolicyFollowsTheSetting) {
  app_->view().set_edit_animation_policy(EditAnimationPolicy::AsSettingSays);
  Settings settings = app_->settings();
  settings.animate_edits = false;
  app_->panels().apply_settings(settings);
  EXPECT_FALSE(app_->edits_animate());
  EXPECT_EQ(animated_ms_after_key(GLFW_KEY_F), 0.0f);
  settings.animate_edits = true;
  app_->panels().apply_settings(settings);
  EXPECT_TRUE(app_->edits_animate());
  EXPECT_GE(animated_ms_after_key(GLFW_KEY_F), 200.0f);
}

}  // namespace
}  // namespace meshedit
