// The window on a large mesh (200k triangles): flip, split, undo and collapse reach the GPU as patches of the slots
// they touched (not rebuilds), with a camera orbit in between; the picture is not blank. expect-gpu-update checks the
// frame after the action before it, with or without a `frames 1` between them.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "app/window_test_support.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "render/image_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::XServer;

TEST(WindowLargeMesh, EditsArePatchedIntoTheGpuBuffers) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "torus.obj";
  save_mesh(file, make_torus_with_faces(200000));
  std::ostringstream actions;
  actions << "frames 3\n"
          << "orbit 40 15\n"
          << "frames 2\n"
          << "select e1000\n"
          << "key F\n"
          << "expect-message flip e1000\n"
          // Waits for the frame after the key by itself: read before it, the last update is still the first
          // frame's rebuild.
          << "expect-gpu-update patch\n"
          << "select e2000\n"
          << "key S\n"
          << "frames 1\n"
          << "expect-gpu-update patch\n"
          << "key ctrl+Z\n"
          << "frames 1\n"
          << "expect-gpu-update patch\n"
          << "select e3000\n"
          << "key C\n"
          << "expect-message collapse e3000\n"
          << "frames 1\n"
          << "expect-gpu-update patch\n"
          << "expect-valid\n"
          << "screenshot " << (dir / "large.png").string() << "\n"
          << "frames 2\n"
          << "quit\n";
  const testing::WindowRun run = testing::run_window(x.display(), file, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  const Image shot = read_png(dir / "large.png");
  std::set<uint32_t> colours;
  for (size_t i = 0; i + 3 < shot.rgba.size(); i += 4 * 97) {
    colours.insert(uint32_t(shot.rgba[i]) << 16 | uint32_t(shot.rgba[i + 1]) << 8 | shot.rgba[i + 2]);
  }
  EXPECT_GT(colours.size(), 20u);
}

}  // namespace
}  // namespace meshedit
