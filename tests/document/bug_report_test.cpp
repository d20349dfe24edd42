// Bug reports (document/bug_report.h): a report reads back byte for byte, code that closes long brackets included;
// its replay of a buggy student run gives the diagnosis the window gave, and of a correct one the reference's answer;
// what is not a report, a report of a version this reader cannot read, a field of the wrong type, a file name with a
// folder in it and a report that tries to run code are refused with the file's name (and the line where Lua knows it).
#include "document/bug_report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/ids.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_records.h"
#include "core/primitives.h"
#include "document/exercise_session.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

fs::path students() { return testing::source_dir() / "tests" / "grading" / "students"; }

// A student folder whose flip.lua is the fixture `fixture` (tests/grading/students).
fs::path student_folder(const std::string& fixture) {
  const fs::path folder = testing::scratch_dir() / "student";
  fs::create_directories(folder);
  fs::copy_file(students() / fixture, folder / "flip.lua", fs::copy_options::overwrite_existing);
  return folder;
}

// What Help > Save a bug report makes after Run mine of the folder's flip on e7 of the cube (bug_report_room.cpp).
BugReport report_of_a_flip_run(const fs::path& folder, std::string& window_verdict) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_cube()), "cube.obj");
  ExerciseSession session(folder);
  Selection selection;
  selection.selected = EdgeId(7);
  session.run_mine(doc, selection);
  const ExerciseRun& run = *session.last_run();
  window_verdict = mine_verdict(run.report);
  EXPECT_NE(doc.message.text.find(window_verdict), std::string::npos) << doc.message.text;
  BugReport report;
  report.app = "meshedit 0.1";
  report.mesh_name = "cube.obj";
  report.mesh = format_mesh_records(doc.mesh);
  report.selection = "e7";
  report.operation =
      BugReportOperation{"flip_edge", run.label, "e7", window_verdict, true, format_mesh_records(*run.input.mesh)};
  report.files.push_back(read_student_source(folder / "flip.lua"));
  return report;
}

TEST(BugReport, ReadsBackByteForByteWhateverTheCodeHolds) {
  BugReport report;
  report.app = "meshedit 0.1";
  report.language = "zh";  // the verdict below is in the student's window's words
  report.lesson = "04_flip.lua";
  report.step = 3;
  report.mesh_name = "cube \"two\".obj";
  HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  report.mesh = format_mesh_records(cube);
  report.selection = "h12";
  report.camera = BugReportCamera{'y', 30.25, -12.5, 3.0000000000000004, {0.1, -0.5, 1e-9}};
  report.operation = BugReportOperation{"split_edge", "mine: split e3", "e3", "different: v8 is at (0, 0, 0)\nsee",
                                        false,        report.mesh};
  report.files = {{"flip.lua", "\nlocal s = [[a]] .. [==[b]==]\n-- ]] ]=] ]==]\nreturn s"},
                  {"split.lua", "-- \t\x01 bytes \xe2\x9c\x93 and no newline at the end"}};
  const BugReport read = parse_bug_report(format_bug_report(report), "report.meshedit");
  EXPECT_EQ(read.version, kBugReportVersion);
  EXPECT_EQ(read.app, report.app);
  EXPECT_EQ(read.language, "zh");
  EXPECT_EQ(read.lesson, "04_flip.lua");
  EXPECT_EQ(read.step, 3u);
  EXPECT_EQ(read.mesh_name, report.mesh_name);
  EXPECT_EQ(read.selection, "h12");
  ASSERT_TRUE(read.camera.has_value());
  EXPECT_EQ(read.camera->up, 'y');
  EXPECT_EQ(read.camera->yaw, 30.25);
  EXPECT_EQ(read.camera->pitch, -12.5);
  EXPECT_EQ(read.camera->distance, 3.0000000000000004);  // every digit kept
  EXPECT_EQ(read.camera->target, glm::dvec3(0.1, -0.5, 1e-9));
  EXPECT_TRUE(parse_mesh_records(read.mesh, "m").same_as(cube));
  ASSERT_TRUE(read.operation.has_value());
  EXPECT_EQ(read.operation->exercise, "split_edge");
  EXPECT_EQ(read.operation->label, "mine: split e3");
  EXPECT_EQ(read.operation->element, "e3");
  EXPECT_EQ(read.operation->verdict, report.operation->verdict);
  EXPECT_FALSE(read.operation->result_shown);
  EXPECT_EQ(read.operation->input, report.mesh);
  ASSERT_EQ(read.files.size(), 2u);
  EXPECT_EQ(read.files[0].name, "flip.lua");
  EXPECT_EQ(read.files[0].text, report.files[0].text);
  EXPECT_EQ(read.files[1].text, report.files[1].text);
  EXPECT_TRUE(read.left_out.empty());
}

TEST(BugReport, TheReplayOfABuggyFlipGivesTheWindowsDiagnosis) {
  std::string verdict;
  const BugReport report = report_of_a_flip_run(student_folder("flip_forgets_faces.lua"), verdict);
  ASSERT_NE(verdict.find("different"), std::string::npos) << verdict;
  // Read back from its text, as `meshedit run` reads it.
  const BugReport read = parse_bug_report(format_bug_report(report), "report.meshedit");
  const BugReportReplay replay = replay_bug_report(read, "report.meshedit", LuaLimits{});
  EXPECT_TRUE(replay.replayed);
  EXPECT_FALSE(replay.equal);
  EXPECT_TRUE(replay.same_verdict) << replay.text;
  EXPECT_NE(replay.text.find(
                "replayed mine: flip e7 (e7 of a mesh with 8 vertices and 12 faces) with the report's flip.lua\n  " +
                verdict + "\n"),
            std::string::npos)
      << replay.text;
  EXPECT_NE(replay.text.find("the mesh cube.obj: 12 faces, not valid: 1 problem; first: "), std::string::npos)
      << replay.text;
  EXPECT_NE(replay.text.find("the same diagnosis as the student's window\n"), std::string::npos) << replay.text;
}

TEST(BugReport, TheReplayOfACorrectFlipIsTheReferencesAnswer) {
  std::string verdict;
  BugReport report = report_of_a_flip_run(student_folder("flip_correct.lua"), verdict);
  EXPECT_EQ(verdict.rfind("same as the reference", 0), 0u) << verdict;
  BugReportReplay replay = replay_bug_report(report, "report.meshedit", LuaLimits{});
  EXPECT_TRUE(replay.equal);
  EXPECT_TRUE(replay.same_verdict);

  // The student changed the code after the run: the replay says its diagnosis is not the window's.
  report.files[0].text = testing::read_text(students() / "flip_forgets_vertices.lua");
  replay = replay_bug_report(report, "report.meshedit", LuaLimits{});
  EXPECT_FALSE(replay.equal);
  EXPECT_FALSE(replay.same_verdict);
  EXPECT_NE(replay.text.find("the student's window said: " + verdict), std::string::npos) << replay.text;

  // Without the exercise's file there is nothing to replay, and the replay says so.
  report.files.clear();
  replay = replay_bug_report(report, "report.meshedit", LuaLimits{});
  EXPECT_FALSE(replay.replayed);
  EXPECT_NE(replay.text.find("ran flip.lua, which the student did not send"), std::string::npos) << replay.text;
}

// The message parse_bug_report refuses `text` with ("" when it reads it).
std::string refusal(const std::string& text) {
  try {
    parse_bug_report(text, "report.meshedit");
  } catch (const ReportError& e) {
    return e.what();
  }
  return "";
}

TEST(BugReport, RefusesWhatIsNotAReportItCanRead) {
  const std::string head = "return { format = \"meshedit bug report\", version = 1, ";
  EXPECT_EQ(refusal("return { lessons = 3 }"),
            "report.meshedit: not a MeshEdit bug report (its table has no format = \"meshedit bug report\")");
  EXPECT_EQ(refusal("v 0 0 0\nf 1 2 3\n"),
            "report.meshedit:1: syntax error near '0' (reading it as a MeshEdit bug report)");
  EXPECT_EQ(refusal("return 3"), "report.meshedit: not a MeshEdit bug report (it does not return a table)");
  EXPECT_EQ(refusal(head + "\n\n step = 'three }"),
            "report.meshedit:3: unfinished string near <eof> (reading it as a MeshEdit bug report)");
  EXPECT_EQ(refusal(head + "lesson = 'a.lua', step = 'three' }"),
            "report.meshedit: the field step should be a whole number");
  EXPECT_EQ(refusal(head + "files = { ['../.bashrc'] = 'x' } }"),
            "report.meshedit: the field files holds \"../.bashrc\", which is not the name of a .lua file");
  EXPECT_EQ(refusal(head + "files = { ['flip.lua'] = 3 } }"),
            "report.meshedit: the field files should map file names to their texts");
  EXPECT_EQ(refusal(head + "camera = { up = 'x' } }"), "report.meshedit: the field camera.up should be \"y\" or \"z\"");
  EXPECT_EQ(refusal(head + "camera = { up = 'y', yaw = 0/0 } }"),
            "report.meshedit: the field camera.yaw should be a finite number");
  EXPECT_EQ(refusal(head + "operation = { label = 'x' } }"),
            "report.meshedit: the field operation.exercise should be the name of an exercise's function");
  // A report is data: its chunk sees no global, and a loop is stopped.
  EXPECT_NE(refusal("os.execute('touch /tmp/x') return {}")
                .find("report.meshedit:1: attempt to index a nil value "
                      "(global 'os')"),
            std::string::npos);
  EXPECT_NE(refusal("while true do end").find("report.meshedit:1: instruction budget exceeded"), std::string::npos);
}

TEST(BugReport, ANewerReportOpensWhenItSaysItCanElseItIsRefusedByName) {
  const BugReport newer = parse_bug_report(
      "return { format = \"meshedit bug report\", version = 2, readable_by = 1, app = \"meshedit 0.2\", "
      "ruler = {}, selection = \"v1\" }",
      "report.meshedit");
  EXPECT_EQ(newer.version, 2);
  EXPECT_EQ(newer.selection, "v1");
  ASSERT_EQ(newer.left_out.size(), 1u);
  EXPECT_EQ(newer.left_out[0], "ruler");
  EXPECT_EQ(
      refusal("return { format = \"meshedit bug report\", version = 3, readable_by = 3, app = \"meshedit 0.9\" }"),
      "report.meshedit: a bug report of version 3 (saved by meshedit 0.9) that needs a newer MeshEdit: this is "
      "meshedit 0.1, which reads version 1");
  EXPECT_EQ(refusal("return { format = \"meshedit bug report\" }"),
            "report.meshedit: a bug report of version 0, which no MeshEdit wrote");
}

TEST(BugReport, AReplayOfADamagedMeshNamesTheReportAndTheLine) {
  std::string verdict;
  BugReport report = report_of_a_flip_run(student_folder("flip_correct.lua"), verdict);
  report.operation->input = "meshedit mesh records 1\nv 0 + 0 0 0 h9\n";
  try {
    replay_bug_report(report, "report.meshedit", LuaLimits{});
    ADD_FAILURE() << "a damaged input replayed";
  } catch (const MeshError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("report.meshedit (the operation's input):2: ", 0), 0u) << e.what();
  }
  report.operation->exercise = "no_such_function";
  EXPECT_THROW(replay_bug_report(report, "report.meshedit", LuaLimits{}), ReportError);
}

}  // namespace
}  // namespace meshedit
