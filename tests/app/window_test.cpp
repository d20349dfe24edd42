// The real window under Xvfb, driven by scripted actions (engine/app/scripted_actions.h): pick a vertex by
// clicking where it is drawn, select an edge, flip it with F, check every pointer the flip wrote, undo it
// with Ctrl+Z and check they are back, and save a screenshot. Starts its own Xvfb when DISPLAY is unset;
// skips when there is no Xvfb at all.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <set>
#include <sstream>

#include "app/editor_app.h"
#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "render/mesh_geometry.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::expect_every_pointer;
using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

TEST(Window, PickFlipUndoAndScreenshotOnTheCube) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());

  const HalfedgeMesh before = build_halfedge_mesh(make_cube());
  HalfedgeMesh flipped = before;
  const EdgeId e(7);
  ASSERT_TRUE(flip(flipped, e).ok());

  std::ostringstream actions;
  actions << "frames 3\n"
          << "click-on v7\n"  // a real pick, where the fitted camera puts v7 in the view
          << "expect-selected v7\n"
          << "select e7\n"
          << "key F\n"
          << "expect-selected e7\n"
          << "expect-changed h" << before.halfedge(e).index << " next\n"
          << expect_every_pointer(flipped) << "expect-valid\n"
          << "frames 2\n"
          << "screenshot " << (dir / "flipped.png").string() << "\n"
          << "frames 2\n"
          << "key ctrl+Z\n"
          << expect_every_pointer(before) << "expect-message undo flip e7\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), file, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;

  const Image shot = read_png(dir / "flipped.png");
  EXPECT_EQ(shot.width, 1280);
  EXPECT_EQ(shot.height, 800);
  // Not blank: the background, the faces, the panels and the highlight give many distinct colours.
  std::set<uint32_t> colours;
  for (size_t i = 0; i + 3 < shot.rgba.size(); i += 4 * 97) {
    colours.insert(uint32_t(shot.rgba[i]) << 16 | uint32_t(shot.rgba[i + 1]) << 8 | shot.rgba[i + 2]);
  }
  EXPECT_GT(colours.size(), 20u);
}

TEST(Window, ABadFileKeepsTheCurrentMeshAndSaysWhy) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());
  const fs::path bad = dir / "bad.obj";
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nf 1 2 3\n";
  const std::string actions = "frames 2\nselect e3\nopen " + bad.string() +
                              "\nexpect-message bad.obj:3\nexpect-selected e3\nexpect-valid\n"
                              "open /no/such/file.obj\nexpect-message cannot open\nquit\n";
  // `open` of a bad file is an action failure by design: the run reports it, and the state must survive.
  const WindowRun run = run_window(x.display(), file, actions, dir);
  EXPECT_EQ(run.status, 3) << run.output;
  EXPECT_NE(run.output.find("actions.txt:3: open failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-selected failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-valid failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-message failed"), std::string::npos) << run.output;
}

TEST(Window, TheConsoleFlipsTheSelectedEdgeAndCtrlZUndoesIt) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());
  const HalfedgeMesh before = build_halfedge_mesh(make_cube());
  HalfedgeMesh flipped = before;
  ASSERT_TRUE(flip(flipped, EdgeId(7)).ok());

  std::ostringstream actions;
  actions << "frames 2\n"
          << "select e7\n"
          << "console tostring(selected) .. ' of ' .. mesh:num_faces()\n"
          << "expect-console e7 of 12\n"
          << "console mesh:flip(selected)\n"
          << "expect-console e7\n"
          << "expect-message console: mesh:flip(selected)\n"
          << expect_every_pointer(flipped) << "expect-valid\n"
          << "console nosuch()\n"
          << "expect-console console:1: attempt to call a nil value (global 'nosuch')\n"
          << "frames 2\n"
          << "screenshot " << (dir / "console.png").string() << "\n"
          << "frames 2\n"
          << "key ctrl+Z\n"
          << expect_every_pointer(before) << "quit\n";
  const WindowRun run = run_window(x.display(), file, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(read_png(dir / "console.png").width, 1280);
}

}  // namespace
}  // namespace meshedit
