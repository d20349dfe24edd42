// The window as it starts (EditorApp::show_start_mesh, what run_window calls before it opens the file it was given)
// when memory runs out: FailingAllocations fails the Nth allocation, or the Nth and every later one, for N = 1, 2, ...
// until the start gets through without a failure. Each time nothing escapes, and the window shows the default cube,
// whole and valid, under "MeshEdit - untitled", or it starts empty under "MeshEdit" with an Error that says memory ran
// out. Then, with memory to spare, the empty window draws a frame without an error, and starting again shows the cube.
// EditorApp needs an OpenGL context: a surfaceless EGL one, as the render tests use; skipped where none can be made.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "render/gl_test_support.h"
#include "render/render_target.h"
#include "support/failing_allocations.h"
#include "support/imgui_harness.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;
using Later = FailingAllocations::Later;

class EditorStartOutOfMemory : public testing::GlTest {
 protected:
  void TearDown() override { app_.reset(); }  // its GL objects go while the context is current

  // One frame of the window, drawn offscreen with memory to spare; returns the status line it leaves.
  DocumentMessage draw_frame() {
    constexpr int kWidth = 640, kHeight = 400;
    ui_testing::ImGuiHarness imgui(ImVec2(kWidth, kHeight));
    const RenderTarget target(kWidth, kHeight, 1);
    target.bind();
    EXPECT_GT(imgui.frame([&] { app_->frame(kWidth, kHeight, 16.0f); }), 0);  // the menu bar and the panels
    return app_->document().message;
  }

  std::unique_ptr<EditorApp> app_;
};

bool is_memory_error(const DocumentMessage& message) {
  return message.severity == Severity::Error && message.text.find(kMemoryRanOut) != std::string::npos;
}

TEST_F(EditorStartOutOfMemory, TheWindowStartsWithTheWholeCubeOrEmptyAndSaysWhy) {
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  bool started_empty = false;
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      app_ = std::make_unique<EditorApp>();  // made with memory to spare: it compiles shaders
      const MeshDocument& doc = app_->document();
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          app_->show_start_mesh();
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      ASSERT_FALSE(escaped);
      if (doc.generation == 0) {
        started_empty = true;
        EXPECT_EQ(doc.mesh.num_vertices(), 0u);
        EXPECT_EQ(app_->title(), "MeshEdit");
        EXPECT_TRUE(is_memory_error(doc.message)) << doc.message.text;
        const DocumentMessage before = doc.message;
        const DocumentMessage after = draw_frame();  // the window works on with nothing to show
        EXPECT_EQ(after.text, before.text);
        EXPECT_EQ(after.severity, before.severity);
      } else {
        EXPECT_EQ(doc.generation, 1u);
        EXPECT_TRUE(doc.mesh.same_as(cube));
        EXPECT_TRUE(validate(doc.mesh).ok());
        EXPECT_EQ(app_->title(), "MeshEdit - untitled");
        // Shown, but memory ran out saying so: the message says that instead (document/mesh_document.h).
        if (doc.message.text.find(kMemoryRanOut) != std::string::npos) {
          EXPECT_NE(doc.message.severity, Severity::Info);
        }
      }
      app_->show_start_mesh();  // with memory to spare again
      EXPECT_TRUE(doc.mesh.same_as(cube));
      EXPECT_EQ(app_->title(), "MeshEdit - untitled");
      if (!failed || HasFailure()) break;
    }
  }
  EXPECT_TRUE(started_empty);
}

}  // namespace
}  // namespace meshedit
