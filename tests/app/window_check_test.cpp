// File > Check my work in the real window under Xvfb: the grader runs beside the window (the window keeps drawing and
// says how far it got), the Check tab shows the verdict `meshedit grade --visible-only` gives for the same files and
// suite, word for word, and "Open in Exercises" puts a failed test's input in the Exercises tab with the student's
// function run on it; Stop ends a check that hangs; a suite that does not load is said in the tab.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "app/window_test_support.h"
#include "core/primitives.h"
#include "grade/report_json.h"
#include "grade/results_writers.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

fs::path grading() { return testing::source_dir() / "tests" / "grading"; }

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A student folder holding flip.lua from a fixture.
fs::path student(const fs::path& dir, const fs::path& fixture) {
  fs::create_directories(dir / "student");
  std::ofstream(dir / "student" / "flip.lua") << read_file(fixture);
  return dir / "student";
}

// What `meshedit grade --visible-only --report` says of the folder.
GradeReport desktop_verdict(const fs::path& dir, const fs::path& suite, const fs::path& folder) {
  const std::string command = "cd '" + dir.string() + "' && '" + MESHEDIT_BINARY + "' grade --suite '" +
                              suite.string() + "' --submission '" + folder.string() +
                              "' --visible-only --report cli.json >/dev/null 2>&1";
  const int raw = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0);
  return decode_grade_report(read_file(dir / "cli.json"));
}

TEST(WindowCheck, TheCheckTabGivesTheGradersVerdictAndOpensTheFailingInput) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = student(dir, grading() / "students" / "flip_forgets_faces.lua");
  const fs::path suite = grading() / "suites" / "flip.lua";
  const GradeReport cli = desktop_verdict(dir, suite, folder);
  ASSERT_EQ(cli.tests.size(), 3u);
  ASSERT_FALSE(cli.tests[0].passed);
  ASSERT_TRUE(cli.tests[0].failing_case);
  const fs::path mesh = dir / "cube.obj";
  save_mesh(mesh, make_cube());

  std::ostringstream actions;
  actions << "frames 2\n"
          << "exercise flip " << folder.string() << "\n"
          << "check-suite " << suite.string() << "\n"
          << "expect-check Not checked yet\n"
          << "key ctrl+K\n"
          << "expect-message Checking your work\n"
          << "wait-message 20000 Check my work: " << score_line(cli) << "; " << summary_line(cli) << "\n"
          << "frames 2\n"
          << "screenshot " << (dir / "verdict.png").string() << "\n"
          << "expect-check " << score_line(cli) << "; " << summary_line(cli) << ".\n"
          << "expect-check Not run here: 1 more test, 2 points, shown after the due date\n";
  for (const TestResult& t : cli.tests) {
    actions << "expect-check " << (t.passed ? "passed (" : "FAILED (") << points_text(t) << ") " << t.number << ": "
            << t.name << "\n";
    // The grader's words for the test, line by line.
    std::istringstream lines(t.output);
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty()) actions << "expect-check " << line << "\n";
    }
  }
  actions << "check-open " << cli.tests[0].number << "\n"
          << "frames 2\n"
          << "expect-message mine: flip\n"
          << "screenshot " << (dir / "opened.png").string()
          << "\n"
          // The whole assignment on a folder with only flip.lua: the missing files are said at once.
          << "check-suite " << (grading() / "suites" / "all.lua").string() << "\n"
          << "command check-my-work\n"
          << "wait-message 20000 Check my work: Score\n"
          << "expect-check Missing: split.lua (the tests that need it fail).\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), mesh, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

TEST(WindowCheck, StopEndsACheckThatHangsAndABrokenSuiteIsSaid) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = student(dir, grading() / "broken" / "hangs_at_load.lua");
  std::ofstream(dir / "broken_suite.lua") << "suite{ name = 'broken' }\ntest{ name = 'one', run = function() end\n";
  const fs::path mesh = dir / "cube.obj";
  save_mesh(mesh, make_cube());
  std::ostringstream actions;
  actions << "frames 2\n"
          << "exercise flip " << folder.string() << "\n"
          << "check-suite " << (grading() / "suites" / "flip.lua").string() << "\n"
          << "command check-my-work\n"
          << "frames 20\n"
          << "expect-check Running:\n"  // the window draws frames while the grader runs
          << "screenshot " << (dir / "running.png").string() << "\n"
          << "frames 2\n"
          << "check-stop\n"
          << "expect-message Check my work stopped\n"
          << "expect-check Stopped: no verdict.\n"
          << "check-suite " << (dir / "broken_suite.lua").string() << "\n"
          << "command check-my-work\n"
          << "wait-message 20000 Check my work: the grader could not\n"
          << "expect-check The grader could not check your work:\n"
          << "expect-check broken_suite.lua:3:\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), mesh, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

}  // namespace
}  // namespace meshedit
