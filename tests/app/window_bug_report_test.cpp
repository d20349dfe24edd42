// Help > Save a bug report in the real window under Xvfb, as a student and a TA use it: the student, in a lesson's
// step, runs a wrong flip_edge on the cube and saves a report without one of the code files; the file holds the
// lesson and step, the mesh with its ids, the selection, the run and only the ticked code. The TA opens it in another
// window, which comes back to the same state (the lesson's step, the run made again with the student's code and its
// diagnosis, the same mesh: a report saved there again holds the same mesh, run and verdict), and `meshedit run`
// replays it headless to the same diagnosis. A report from a newer MeshEdit that this one cannot read is refused by
// name.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/cli_test_support.h"
#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "document/bug_report.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

// A student folder holding the solutions, its flip.lua the fixture that forgets to set the faces' halfedges.
fs::path student(const fs::path& dir) {
  const fs::path folder = dir / "student";
  fs::create_directories(folder);
  for (const auto& entry : fs::directory_iterator(testing::source_dir() / "tests" / "exercise" / "solutions")) {
    fs::copy_file(entry.path(), folder / entry.path().filename(), fs::copy_options::overwrite_existing);
  }
  fs::copy_file(testing::source_dir() / "tests" / "grading" / "students" / "flip_forgets_faces.lua",
                folder / "flip.lua", fs::copy_options::overwrite_existing);
  return folder;
}

BugReport read_report(const fs::path& path) { return parse_bug_report(testing::read_text(path), path.string()); }

TEST(WindowBugReport, ASavedReportReopensToTheSameStateAndReplaysHeadlessToTheSameDiagnosis) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = student(dir);
  const fs::path cube = dir / "cube.obj";
  save_mesh(cube, make_cube());
  const fs::path lesson = testing::source_dir() / "lessons" / "4_edge_flip.lua";
  const fs::path saved = dir / "alice.meshedit";
  fs::create_directories(dir / "student-window");
  fs::create_directories(dir / "ta-window");

  std::ostringstream student_actions;
  student_actions << "frames 2\n"
                  << "open " << lesson.string() << "\n"
                  << "lesson-next\n"
                  << "exercise flip " << folder.string() << "\n"
                  << "open " << cube.string() << "\n"
                  << "orbit 80 -30\n"
                  << "select e7\n"
                  << "run-mine\n"
                  << "expect-message different\n"
                  << "command bug-report\n"
                  << "frames 2\n"
                  << "screenshot " << (dir / "dialog.png").string() << "\n"
                  << "bug-report-send split.lua no\n"
                  << "bug-report " << saved.string() << "\n"
                  << "expect-message saved a bug report in " << saved.string() << "\n"
                  << "quit\n";
  WindowRun run = run_window(x.display(), cube, student_actions.str(), dir / "student-window");
  ASSERT_EQ(run.status, 0) << run.output;

  const BugReport report = read_report(saved);
  EXPECT_EQ(report.lesson, "4_edge_flip.lua");
  EXPECT_EQ(report.step, 2u);
  EXPECT_EQ(report.mesh_name, "cube.obj");
  EXPECT_EQ(report.selection, "e7");
  ASSERT_TRUE(report.operation.has_value());
  EXPECT_EQ(report.operation->exercise, "flip_edge");
  EXPECT_EQ(report.operation->label, "mine: flip e7");
  EXPECT_TRUE(report.operation->result_shown);
  EXPECT_EQ(report.operation->verdict.rfind("different: ", 0), 0u) << report.operation->verdict;
  std::vector<std::string> names;
  for (const StudentSource& file : report.files) names.push_back(file.name);
  // Every exercise's file, the scripted exercises' too, but split.lua, which the student unticked.
  EXPECT_EQ(names,
            (std::vector<std::string>{"catmull_clark.lua", "collapse.lua", "curve.lua", "flip.lua", "hodograph.lua",
                                      "normals.lua", "patch.lua", "patch_normal.lua", "upsample.lua"}));
  const std::string flip = testing::read_text(folder / "flip.lua");
  for (const StudentSource& file : report.files) {
    if (file.name == "flip.lua") {
      EXPECT_EQ(file.text, flip);
    }
  }

  // The TA's window: the report opens in the lesson's step, the run made again with the student's code, which is put
  // in a folder of its own, where no file of another report of that name stays.
  const fs::path code = fs::temp_directory_path() / "meshedit report alice";
  fs::create_directories(code);
  std::ofstream(code / "split.lua") << "-- another alice's split.lua\n";
  const fs::path again = dir / "again.meshedit";
  std::ostringstream ta_actions;
  ta_actions << "frames 2\n"
             << "open " << saved.string()
             << "\n"
             // The run is made again beside the window (or at once, when it ended before the open returned).
             << "expect-console opened the bug report alice.meshedit saved by meshedit 0.1: the student's code is "
                "in "
             << code.string() << "; \n"
             << "wait-message 5000 " << report.operation->verdict << "\n"
             << "expect-exercise-run mine: flip e7 (e7 of a mesh with 8 vertices and 12 faces): different: after your "
                "flip_edge the mesh is not valid\n"
             << "expect-selected e7\n"
             << "expect-lesson-step 2 waiting\n"
             << "frames 2\n"
             << "screenshot " << (dir / "reopened.png").string() << "\n"
             << "bug-report " << again.string() << "\n"
             << "quit\n";
  run = run_window(x.display(), cube, ta_actions.str(), dir / "ta-window");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(testing::read_text(code / "flip.lua"), flip);
  EXPECT_FALSE(fs::exists(code / "split.lua"));  // not sent, and the other report's is gone
  const BugReport reopened = read_report(again);
  EXPECT_EQ(reopened.mesh, report.mesh);  // the same records: every id, pointer and position
  EXPECT_EQ(reopened.selection, report.selection);
  ASSERT_TRUE(report.camera.has_value() && reopened.camera.has_value());
  EXPECT_EQ(report.camera->up, 'y');  // cube.obj is Y-up
  EXPECT_EQ(reopened.camera->up, report.camera->up);
  EXPECT_NEAR(reopened.camera->yaw, report.camera->yaw, 1e-9);
  EXPECT_NEAR(reopened.camera->pitch, report.camera->pitch, 1e-9);
  EXPECT_NEAR(reopened.camera->distance, report.camera->distance, 1e-9);
  ASSERT_TRUE(reopened.operation.has_value());
  EXPECT_EQ(reopened.operation->input, report.operation->input);
  EXPECT_EQ(reopened.operation->verdict, report.operation->verdict);
  EXPECT_EQ(reopened.lesson, report.lesson);
  EXPECT_EQ(reopened.step, report.step);
  EXPECT_EQ(reopened.files.size(), report.files.size());

  // Headless: the same diagnosis, said to be the student's window's.
  const testing::CommandRun replay = testing::run_meshedit({"run", saved.string()}, "bug-report-replay");
  EXPECT_EQ(replay.status, 0) << replay.err;
  EXPECT_NE(replay.out.find(
                "replayed mine: flip e7 (e7 of a mesh with 8 vertices and 12 faces) with the report's flip.lua\n  " +
                report.operation->verdict + "\n"),
            std::string::npos)
      << replay.out;
  EXPECT_NE(replay.out.find("the same diagnosis as the student's window"), std::string::npos) << replay.out;
}

TEST(WindowBugReport, AReportThisMeshEditCannotReadIsRefusedByNameAndTheWindowKeepsItsMesh) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path cube = dir / "cube.obj";
  save_mesh(cube, make_cube());
  const fs::path newer = dir / "newer.meshedit";
  std::ofstream(newer) << "return { format = \"meshedit bug report\", version = 5, readable_by = 4, app = \"meshedit "
                          "2.0\" }\n";
  std::ostringstream actions;
  actions << "frames 2\n"
          << "select e3\n"
          << "open " << newer.string() << "\n"
          << "frames 1\n"
          << "expect-message newer.meshedit: a bug report of version 5 (saved by meshedit 2.0) that needs a newer "
             "MeshEdit\n"
          << "expect-selected e3\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), cube, actions.str(), dir);
  EXPECT_EQ(run.status, 3) << run.output;  // the open failed, as the script's line 3 says
  EXPECT_NE(run.output.find("actions.txt:3: open failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-message failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-selected failed"), std::string::npos) << run.output;

  const testing::CommandRun replay = testing::run_meshedit({"run", newer.string()}, "bug-report-newer");
  EXPECT_EQ(replay.status, 1);
  EXPECT_NE(replay.err.find("newer.meshedit: a bug report of version 5"), std::string::npos) << replay.err;
}

}  // namespace
}  // namespace meshedit
