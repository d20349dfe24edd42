// Shared by the render tests that need OpenGL: one surfaceless EGL context per test suite, and a skip
// (not a failure) on machines where no EGL display can be created. Renderers made in a test must die
// before the suite's context does; locals in the test body do.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "core/halfedge_mesh.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_context.h"
#include "render/render_error.h"
#include "render/render_target.h"
#include "render/shader_library.h"

namespace meshedit::testing {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    try {
      context_ = std::make_unique<OffscreenContext>();
    } catch (const RenderError& e) {
      skip_reason_ = e.what();
    }
  }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override {
    if (!context_) GTEST_SKIP() << "no EGL context on this machine: " << skip_reason_;
    context_->make_current();
  }

  // A fitted camera, a cleared target, one draw; the pixels come back top row first.
  static Image render(MeshRenderer& renderer, const HalfedgeMesh& mesh, const OrbitCamera& camera,
                      const ViewOptions& options, const Highlights& highlights, int size = 256) {
    RenderTarget target(size, size, 4);
    renderer.update(mesh);
    target.clear(renderer.style().background);
    renderer.draw(camera, target.viewport(), options, highlights);
    return Image{size, size, target.read_rgba()};
  }

  static inline std::unique_ptr<OffscreenContext> context_;
  static inline std::string skip_reason_;
};

}  // namespace meshedit::testing
