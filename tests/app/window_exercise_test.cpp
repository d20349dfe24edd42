// "Mine vs reference" in the real window under Xvfb: a student's flip (the solution kept under tests/) runs
// on the selected edge, the document takes its result as one undoable operation, a replay shows state k of
// the recorded writes, finishing the replay and Ctrl+Z bring back every pointer of the cube.
#include <gtest/gtest.h>

#include <sstream>

#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "render/image_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::expect_every_pointer;
using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

TEST(WindowExercise, MineRunsOnTheSelectionReplaysAndUndoes) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());
  const HalfedgeMesh before = build_halfedge_mesh(make_cube());
  HalfedgeMesh flipped = before;
  ASSERT_TRUE(flip(flipped, EdgeId(7)).ok());
  const fs::path solutions = testing::source_dir() / "tests" / "exercise" / "solutions";

  std::ostringstream actions;
  actions << "frames 2\n"
          << "key X\n"
          << "exercise flip " << solutions.string() << "\n"
          << "select e7\n"
          << "run-mine\n"
          << "expect-message mine: flip e7\n"
          << expect_every_pointer(flipped) << "expect-valid\n"
          << "replay-start\n"
          << expect_every_pointer(before)  // state 0 is the mesh before the student's function ran
          << "replay-step 3\n"
          << "frames 2\n"
          << "screenshot " << (dir / "replay.png").string() << "\n"
          << "frames 2\n"
          << "replay-finish\n"
          << expect_every_pointer(flipped) << "key ctrl+Z\n"
          << expect_every_pointer(before) << "quit\n";
  const WindowRun run = run_window(x.display(), file, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(read_png(dir / "replay.png").width, 1280);
}

}  // namespace
}  // namespace meshedit
