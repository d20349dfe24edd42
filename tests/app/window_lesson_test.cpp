// Lessons in the real window under Xvfb: `meshedit lessons/welcome.lua` opens the lesson panel on its first
// step; keys, a click on a vertex and Next reach the lesson through the same handlers a student uses, the
// lesson's highlight and label are drawn, and a broken lesson shows its file:line without taking the window.
// Lesson 6's "The app's phases: Shift+L" step follows the app's own Loop phases, one Shift+L at a time, and lesson 7's
// the Subdivide menu's Catmull-Clark phases. The asking demo's questions are answered wrong, then right, through the
// panel's actions and clicks in the view, with the feedback, the answers, the arrows and the live text on screen.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "app/editor_app.h"
#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "core/palette.h"
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

// Lesson 7's "The app's phases" waits for the Subdivide menu's Catmull-Clark phases, one command at a time; a whole
// subdivision between two phases makes the lesson start again on a fresh cube.
TEST(WindowLesson, LessonSevenFollowsTheMenusCatmullClarkPhases) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  std::ostringstream actions;
  actions << "frames 2\n";
  for (int i = 0; i < 4; ++i) actions << "lesson-next\n";
  actions << "frames 1\n"
          << "expect-lesson-step 5 waiting\n"
          << "lesson-choose At the edge's midpoint (0, -0.5, -0.5)\n"
          << "frames 1\n"
          << "subdivide-phase catmull-clark\n"
          << "expect-message Catmull-Clark 1/3\n"
          << "expect-lesson-said **Phase 1** computed 6 face points, 12 edge points and 8 vertex points\n"
          << "subdivide catmull-clark\n"  // the whole level instead of phase 2
          << "subdivide-phase catmull-clark\n"
          << "expect-lesson-said That is not the cube after phase 2\n"
          << "frames 1\n"
          << "subdivide-phase catmull-clark\n"
          << "subdivide-phase catmull-clark\n"
          << "expect-lesson-said **Phase 2** split the 6 faces into 24 quads. The new vertex v11 sits at "
             "(0, -0.5, -0.5)\n"
          << "subdivide-phase catmull-clark\n"
          << "expect-valid\n"
          << "expect-lesson-step 5 finished\n"
          << "expect-lesson-said One level done: 26 vertices, 48 edges, 24 faces.\n"
          << "quit\n";
  const WindowRun run =
      run_window(x.display(), testing::source_dir() / "lessons" / "7_catmull_clark.lua", actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

// Pixels of `shot` in the rectangle [x0, x1) x [y0, y1) within 24 (per channel) of `colour`.
int pixels_near(const Image& shot, glm::vec3 colour, int x0, int y0, int x1, int y1) {
  int count = 0;
  for (int y = y0; y < y1 && y < shot.height; ++y) {
    for (int x = x0; x < x1 && x < shot.width; ++x) {
      const uint8_t* p = &shot.rgba[(size_t(y) * size_t(shot.width) + size_t(x)) * 4];
      bool near = true;
      for (int c = 0; c < 3; ++c) near = near && std::abs(int(p[c]) - int(std::lround(colour[c] * 255.0f))) <= 24;
      count += near;
    }
  }
  return count;
}

TEST(WindowLesson, TheAskingDemoAnswersEachWrongAnswerAndGoesOnAtTheRightOne) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = testing::source_dir() / "tests" / "lesson" / "lessons" / "asking_demo.lua";
  std::ostringstream actions;
  actions << "frames 3\n"
          << "expect-lesson-step 1 waiting\n"
          << "lesson-choose h6\n"
          << "expect-lesson-feedback h6 is h0's twin on the boundary\n"
          << "expect-lesson-hint one old outer halfedge\n"
          << "expect-lesson-step 1 waiting\n"
          << "frames 2\n"
          << "screenshot " << (dir / "choose_wrong.png").string() << "\n"
          << "frames 2\n"
          << "lesson-choose h4\n"
          << "expect-lesson-step 1 finished\n"
          << "frames 2\n"
          << "screenshot " << (dir / "choose_right.png").string() << "\n"
          << "frames 2\n"
          << "lesson-next\n"
          << "frames 2\n"
          << "click-on h2\n"  // a click is a pick's answer: wrong, with its feedback
          << "expect-selected h2\n"
          << "expect-lesson-feedback h2 is h1.next before the flip\n"
          << "click-on h4\n"
          << "expect-lesson-step 2 finished\n"
          << "expect-lesson-said You clicked **h4**\n"
          << "lesson-next\n"
          << "frames 2\n"
          << "click-on v0\n"
          << "frames 2\n"
          << "expect-lesson-live Selected: v0.\n"
          << "screenshot " << (dir / "normals.png").string() << "\n"
          << "frames 2\n"
          << "lesson-button Continue\n"
          << "lesson-next\n"
          << "frames 2\n"
          << "expect-lesson-live t = 0.50\n"
          << "curve-t 0.25\n"
          << "frames 2\n"
          << "expect-lesson-live t = 0.25, C(t) = (0.906, 1.125)\n"
          << "lesson-answer 1/8\n"
          << "expect-lesson-feedback an end point's weight\n"
          << "lesson-answer 0.375\n"
          << "expect-lesson-step 4 waiting\n"  // the next question: where C(0.5) is
          << "expect-lesson-said Yes: B1(0.5) = 0.375.\n"
          << "frames 2\n"
          << "screenshot " << (dir / "weights.png").string() << "\n"
          << "frames 2\n"
          << "lesson-choose h4\n"  // no choice is asked now: the check fails, the script goes on
          << "quit\n";
  const WindowRun run = run_window(x.display(), lesson, actions.str(), dir);
  EXPECT_EQ(run.status, 3) << run.output;  // the one failure the script asks for
  EXPECT_NE(run.output.find("lesson-choose failed: the lesson is not asking for it (it waits for a point answering "
                            "'Where is C(0.5)? Give x, y.')"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("expect-"), std::string::npos) << run.output;  // every expectation held

  // The lesson column (left of x = 350, under the menu, above the buttons): the wrong answer's feedback in the
  // warning colour and no answer marked right yet; then the answer in the ok colour.
  const Palette& palette = palette_for(Theme::Dark);
  const Image wrong = read_png(dir / "choose_wrong.png");
  ASSERT_EQ(wrong.width, 1280);
  EXPECT_GT(pixels_near(wrong, palette.warning, 0, 30, 350, 700), 100);
  EXPECT_EQ(pixels_near(wrong, palette.ok, 0, 30, 350, 700), 0);
  const Image right = read_png(dir / "choose_right.png");
  EXPECT_GT(pixels_near(right, palette.ok, 0, 30, 350, 700), 100);
  EXPECT_EQ(pixels_near(right, palette.warning, 0, 30, 350, 700), 0);
  // The face normals: blue arrows in the view (the centre, between the columns).
  EXPECT_GT(pixels_near(read_png(dir / "normals.png"), kDarkSwatches.blue, 360, 30, 870, 750), 300);
}

}  // namespace
}  // namespace meshedit
