// The web page's end-to-end scripts (tests/web/*.txt, which scripts/web_test.sh plays in headless Chromium) played
// in the desktop window under Xvfb: the same checks hold in both. The page starts in its packaged source tree, so the
// lesson 4 script names the student folder relative to the top of a checkout; here that folder is the source tree's.
// The page's files from the student's disk arrive as /uploads/NAME; here the same files open from tests/web, through
// the same open path, with the same counts and the same message naming the bad file; the runaway student files and the
// broken lessons the page is given stop with the same messages here; the lessons' own interactions (a click on the
// curve, the patch probe, a lesson's Check button) hold the same way. Also the two verbs those scripts add:
// wait-message waits frames for the status line, and open-picker fails where the window has no picker.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "app/window_test_support.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

TEST(WindowWebActions, TheWebPagesLessonFourScriptHoldsInTheDesktopWindow) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  std::ifstream in(testing::source_dir() / "tests" / "web" / "lesson4_flip.txt");
  ASSERT_TRUE(in) << "tests/web/lesson4_flip.txt";
  std::ostringstream script;
  for (std::string line; std::getline(in, line);) {
    const std::string relative = "exercise flip scripts/student";
    if (line == relative) line = "exercise flip " + (testing::source_dir() / "scripts" / "student").string();
    script << line << "\n";
  }
  const WindowRun run =
      run_window(x.display(), testing::source_dir() / "lessons" / "4_edge_flip.lua", script.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("actions: all expectations held"), std::string::npos) << run.output;
}

// The lessons' own interactions the page's scripts drive (lesson 1's click on the curve, lesson 2's probe and lesson
// 6's Check button) and an exercise on points, each script played as the page plays it; its student folder, named from
// the top of the page's tree, is the source tree's here.
TEST(WindowWebActions, TheWebPagesLessonAndExerciseScriptsHoldInTheDesktopWindow) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const std::pair<const char*, const char*> scripts[] = {
      {"lesson1_curve_pick.txt", "lessons/1_de_casteljau.lua"},
      {"lesson2_probe.txt", "lessons/2_bezier_patches.lua"},
      {"lesson6_sharp_corners.txt", "lessons/6_loop_subdivision.lua"},
      {"values_exercise.txt", "assets/suzanne.obj"}};
  const std::string relative = " scripts/student";
  for (const auto& [name, opened] : scripts) {
    std::ifstream in(testing::source_dir() / "tests" / "web" / name);
    ASSERT_TRUE(in) << name;
    std::ostringstream script;
    for (std::string line; std::getline(in, line);) {
      if (line.size() > relative.size() && line.ends_with(relative)) {
        line.replace(line.size() - relative.size() + 1, relative.size() - 1,
                     (testing::source_dir() / "scripts" / "student").string());
      }
      script << line << "\n";
    }
    const WindowRun run = run_window(x.display(), testing::source_dir() / opened, script.str(), testing::scratch_dir());
    EXPECT_EQ(run.status, 0) << name << ": " << run.output;
    EXPECT_NE(run.output.find("actions: all expectations held"), std::string::npos) << name << ": " << run.output;
  }
}

// The lines of tests/web/NAME that follow the file's arrival in the page (after its first wait-message), with the
// page's /uploads/ folder read as tests/web/.
std::string checks_after_arrival(const std::string& name) {
  std::ifstream in(testing::source_dir() / "tests" / "web" / name);
  std::ostringstream script;
  bool arrived = false;
  for (std::string line; std::getline(in, line);) {
    if (!arrived && line.rfind("wait-message ", 0) == 0) {
      arrived = true;
      continue;
    }
    if (!arrived) continue;
    if (const size_t at = line.find("/uploads/"); at != std::string::npos) {
      line.replace(at, 9, (testing::source_dir() / "tests" / "web").string() + "/");
    }
    script << line << "\n";
  }
  return script.str();
}

TEST(WindowWebActions, TheWebPagesFilesFromDiskOpenAsOnTheDesktop) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path web = testing::source_dir() / "tests" / "web";
  const std::string picked = checks_after_arrival("open_picked_mesh.txt");
  ASSERT_NE(picked.find("expect-console 5 vertices"), std::string::npos) << picked;
  WindowRun run = run_window(x.display(), web / "pyramid.obj", picked, dir);
  EXPECT_EQ(run.status, 0) << run.output;
  const std::string dropped = checks_after_arrival("open_dropped_bad_file.txt");
  ASSERT_NE(dropped.find("expect-message " + (web / "bad_face.obj").string() + ":5:"), std::string::npos) << dropped;
  run = run_window(x.display(), web / "bad_face.obj", dropped, dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

// The page is given each runaway flip.lua by a drop over its student folder; here the exercise reads it from its own
// folder in tests/web/runaway_student, and the same Run mine (started, the window drawing on while it runs) fails with
// the same message on the same line.
TEST(WindowWebActions, TheWebPagesRunawayStudentFilesStopAsOnTheDesktop) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  for (const std::string runaway : {"loop", "recursion", "allocation"}) {
    const std::string checks = checks_after_arrival("student_runaway_" + runaway + ".txt");
    ASSERT_NE(checks.find("start-mine\n"), std::string::npos) << checks;
    ASSERT_NE(checks.find(" flip.lua:"), std::string::npos) << checks;
    const fs::path folder = testing::source_dir() / "tests" / "web" / "runaway_student" / runaway;
    const WindowRun run = run_window(x.display(), testing::source_dir() / "lessons" / "4_edge_flip.lua",
                                     "frames 3\nkey X\nexercise flip " + folder.string() + "\n" + checks, dir);
    EXPECT_EQ(run.status, 0) << runaway << ": " << run.output;
  }
}

// The page is given each broken lesson by a drop; here it is the window's file, and its messages are the same.
TEST(WindowWebActions, TheWebPagesBrokenLessonsStopAsOnTheDesktop) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  for (const std::string broken : {"syntax_error", "endless_step"}) {
    const std::string checks = checks_after_arrival("lesson_" + broken + ".txt");
    ASSERT_NE(checks.find("expect-lesson-error " + broken + ".lua:7:"), std::string::npos) << checks;
    const WindowRun run =
        run_window(x.display(), testing::source_dir() / "tests" / "web" / "broken_lesson" / (broken + ".lua"),
                   "frames 2\n" + checks, dir);
    EXPECT_EQ(run.status, 0) << broken << ": " << run.output;
  }
}

TEST(WindowWebActions, WaitMessageWaitsFramesForTheStatusLineAndFailsWithoutIt) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path mesh = testing::source_dir() / "tests" / "web" / "pyramid.obj";
  // The screenshot's message comes after the next frame is drawn: an expect-message right away would not see it.
  WindowRun run = run_window(x.display(), mesh,
                             "screenshot " + (dir / "shot.png").string() +
                                 "\nwait-message 30 screenshot saved to\nexpect-message shot.png\nquit\n",
                             dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "shot.png"));
  run = run_window(x.display(), mesh, "wait-message 3 words never said\nexpect-valid\nquit\n", dir);
  EXPECT_EQ(run.status, 3) << run.output;
  EXPECT_NE(run.output.find("wait-message failed: the status line is 'opened "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("after 3 frames"), std::string::npos) << run.output;
}

TEST(WindowWebActions, OpenPickerFailsInTheDesktopWindowWhichHasNoPicker) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const WindowRun run =
      run_window(x.display(), testing::source_dir() / "tests" / "web" / "pyramid.obj", "open-picker\nquit\n", dir);
  EXPECT_EQ(run.status, 3) << run.output;
  EXPECT_NE(run.output.find("no file picker of its own"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace meshedit
