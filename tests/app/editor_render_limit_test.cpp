// EditorApp on a mesh too large to draw (the renderer's buffer cap lowered to make one cheaply): the renderer refuses
// it once per mesh state with an Error and a standing note, frames go on drawing every panel without retrying, and
// undo brings back a mesh that is drawn. Needs an OpenGL context: a surfaceless EGL one, skipped where none exists.
#include <gtest/gtest.h>

#include <string>

#include <GLFW/glfw3.h>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "document/document_actions.h"
#include "render/gl_test_support.h"
#include "support/imgui_harness.h"

namespace meshedit {
namespace {

constexpr int kWidth = 1280, kHeight = 800;

class EditorRenderLimit : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    app_ = std::make_unique<EditorApp>();
  }
  void TearDown() override { app_.reset(); }  // its GL objects go while the context is current

  // One window frame; returns how many ImGui windows it drew.
  int frame() {
    ui_testing::ImGuiHarness imgui(ImVec2(kWidth, kHeight));
    return imgui.frame([&] { app_->frame(kWidth, kHeight, 16.0f); });
  }

  std::unique_ptr<EditorApp> app_;
};

TEST_F(EditorRenderLimit, AMeshTooLargeToDrawIsRefusedOnceAndTheWindowWorksOn) {
  app_->show_mesh(build_halfedge_mesh(make_torus(6, 8)), "");  // 96 triangles, 288 halfedges
  ASSERT_GT(frame(), 0);

  ASSERT_EQ(app_->view().mesh_render_stats().triangles, 96u);
  const uint64_t uploads = app_->view().mesh_render_stats().uploads;

  // Between the torus and its subdivision (1152 halfedge slots, with headroom more): L makes a mesh it cannot draw.
  app_->view().mesh_render_style().max_buffer_texels = 1000;
  app_->handle_key(GLFW_KEY_L, {});
  ASSERT_EQ(app_->document().mesh.num_faces(), 384u);
  const int refused_frame = frame();
  EXPECT_EQ(app_->document().message.severity, Severity::Error);
  const std::string& said = app_->document().message.text;
  EXPECT_NE(said.find("too large to draw"), std::string::npos) << said;
  EXPECT_NE(app_->view().status_bar().note.find("too large to draw"), std::string::npos)
      << app_->view().status_bar().note;
  EXPECT_EQ(app_->view().mesh_render_stats().refusals, 1u);
  EXPECT_EQ(app_->view().mesh_render_stats().uploads, uploads);

  frame();
  frame();
  EXPECT_EQ(app_->view().mesh_render_stats().refusals, 1u);  // not tried again for the same mesh

  // Undo (a key like any other) brings back the torus, drawn again.
  app_->handle_key(GLFW_KEY_Z, KeyMods{.ctrl = true});
  frame();
  EXPECT_EQ(app_->document().mesh.num_faces(), 96u);
  EXPECT_EQ(app_->view().mesh_render_stats().triangles, 96u);
  EXPECT_GT(app_->view().mesh_render_stats().uploads, uploads);
  EXPECT_EQ(app_->view().status_bar().note.find("too large"), std::string::npos) << app_->view().status_bar().note;

  // The refused frame drew every panel: as many ImGui vertices, give or take the status text, as the same mesh drawn.
  app_->view().mesh_render_style().max_buffer_texels = 0;
  app_->handle_key(GLFW_KEY_Y, KeyMods{.ctrl = true});
  const int drawn_frame = frame();
  ASSERT_EQ(app_->view().mesh_render_stats().triangles, 384u);
  EXPECT_GT(refused_frame, drawn_frame * 9 / 10);
}

}  // namespace
}  // namespace meshedit
