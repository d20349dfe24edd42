// EditorApp's quality governor end to end, in a 4x multisampled framebuffer: frames the window says took 80 ms drop
// multisampling (the renderer then draws single-sampled), then the wireframe; W gives the wireframe back and the back
// sides go instead; fast frames bring everything back. The status bar's note follows. Needs an OpenGL context: a
// surfaceless EGL one, skipped where none exists.
#include <gtest/gtest.h>

#include <string>

#include <GLFW/glfw3.h>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "render/gl_test_support.h"
#include "support/imgui_harness.h"

namespace meshedit {
namespace {

constexpr int kWidth = 640, kHeight = 400;

class EditorViewQuality : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    target_ = std::make_unique<RenderTarget>(kWidth, kHeight, 4);
    target_->bind();  // the window's framebuffer, as a 4x multisampled one
    app_ = std::make_unique<EditorApp>();
  }
  void TearDown() override {
    app_.reset();  // its GL objects go while the context is current
    target_.reset();
  }

  // `count` window frames, each told that the one before it took `ms`.
  void frames(float ms, int count) {
    for (int i = 0; i < count; ++i) {
      ui_testing::ImGuiHarness imgui(ImVec2(kWidth, kHeight));
      imgui.frame([&] { app_->frame(kWidth, kHeight, ms); });
    }
  }

  std::unique_ptr<RenderTarget> target_;
  std::unique_ptr<EditorApp> app_;
};

TEST_F(EditorViewQuality, SlowFramesLowerTheQualityTheUsersWireframeWinsAndFastFramesRestoreIt) {
  app_->show_mesh(build_halfedge_mesh(make_torus(24, 32)), "");  // 1536 triangles, closed
  frames(10.0f, 2);
  ASSERT_EQ(app_->view().mesh_render_stats().framebuffer_samples, 4);
  EXPECT_TRUE(app_->view().mesh_render_stats().multisampled);
  EXPECT_TRUE(app_->view().options().wireframe);
  EXPECT_EQ(app_->view().status_bar().note, "");

  frames(80.0f, 4);  // the first is the frame before (fast); then three slow ones
  EXPECT_FALSE(app_->view().mesh_render_stats().multisampled);
  EXPECT_TRUE(app_->view().options().wireframe);
  EXPECT_EQ(app_->view().status_bar().note, "frame 80 ms: multisampling off");

  frames(80.0f, 3);
  EXPECT_FALSE(app_->view().options().wireframe);
  EXPECT_EQ(app_->view().status_bar().note, "frame 80 ms: multisampling and wireframe off (W shows it)");

  app_->handle_key(GLFW_KEY_W, {});
  frames(80.0f, 1);
  EXPECT_TRUE(app_->view().options().wireframe);
  EXPECT_EQ(app_->view().status_bar().note, "frame 80 ms: multisampling off");
  frames(80.0f, 3);
  EXPECT_TRUE(app_->view().options().wireframe);
  EXPECT_EQ(app_->view().status_bar().note, "frame 80 ms: multisampling and back sides off");

  frames(5.0f, 30);
  EXPECT_TRUE(app_->view().mesh_render_stats().multisampled);
  EXPECT_TRUE(app_->view().options().wireframe);
  EXPECT_EQ(app_->view().status_bar().note, "");
}

}  // namespace
}  // namespace meshedit
