// Lessons in the real window under Xvfb: `meshedit lessons/welcome.lua` opens the lesson panel on its first
// step; keys, a click on a vertex and Next reach the lesson through the same handlers a student uses, the
// lesson's highlight and label are drawn, and a broken lesson shows its file:line without taking the window.
// Lesson 6's "Your turn: Shift+L" step follows the app's own Loop phases, one Shift+L at a time.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/editor_app.h"
#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "render/mesh_geometry.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

TEST(WindowLesson, TheWelcomeLessonFollowsKeysClicksAndNext) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = testing::source_dir() / "lessons" / "welcome.lua";

  std::ostringstream actions;
  actions << "frames 3\n"
          << "expect-lesson-step 1 finished\n"
          << "expect-lesson-said is a workbench\n"
          << "lesson-next\n"
          << "expect-lesson-step 2 waiting\n"
          << "key F\n"
          << "expect-lesson-step 2 waiting\n"  // not the key it asked for
          << "key W\n"
          << "expect-lesson-step 2 finished\n"
          << "lesson-next\n"
          << "frames 2\n"
          << "click-on v7\n"
          << "expect-selected v7\n"
          << "expect-lesson-step 3 finished\n"
          << "expect-lesson-said You picked **v7**\n"
          << "frames 2\n"
          << "screenshot " << (dir / "lesson.png").string() << "\n"
          << "frames 2\n"
          << "lesson-back\n"
          << "expect-lesson-step 2 waiting\n"  // Back runs the step again from its start
          << "quit\n";
  const WindowRun run = run_window(x.display(), lesson, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(read_png(dir / "lesson.png").width, 1280);
}

TEST(WindowLesson, ABrokenLessonShowsFileAndLineAndTheWindowKeepsWorking) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = dir / "broken.lua";
  std::ofstream(lesson) << "lesson{title = 'Broken'}\nstep('One', function()\n  say('hello')\n  nosuch()\nend)\n";
  const std::string actions =
      "frames 2\nexpect-lesson-step 1 failed\nexpect-message broken.lua\nselect e3\nkey F\n"
      "expect-message flip e3\nexpect-valid\nquit\n";
  const WindowRun run = run_window(x.display(), lesson, actions, dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

TEST(WindowLesson, LessonSixFollowsTheAppsLoopPhasesKeyByKey) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  std::ostringstream actions;
  actions << "frames 2\n";
  for (int i = 0; i < 5; ++i) actions << "lesson-next\n";
  actions << "frames 1\n"
          << "expect-lesson-step 6 waiting\n"
          << "key shift+L\n"
          << "expect-message Loop 1/4\n"
          << "expect-lesson-said Phase 1 computed every new position and changed nothing\n"
          << "key shift+L\n"
          << "expect-lesson-said Phase 2 split all 18 original edges: now 26 vertices, 72 edges, 48 faces\n"
          << "key L\n"  // a whole subdivision instead of phase 3: the lesson starts again on a fresh cube
          << "key shift+L\n"
          << "expect-lesson-said That is not the cube after phase 3\n"
          << "frames 1\n"
          << "key shift+L\n"
          << "key shift+L\n"
          << "key shift+L\n"
          << "key shift+L\n"
          << "expect-valid\n"
          << "expect-lesson-step 6 finished\n"
          << "expect-lesson-said One step done: 26 vertices, 72 edges, 48 faces, valid.\n"
          << "quit\n";
  const WindowRun run =
      run_window(x.display(), testing::source_dir() / "lessons" / "6_loop_subdivision.lua", actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

}  // namespace
}  // namespace meshedit
