// your_turn end to end: the built binary runs lesson 4 (`meshedit lesson ... --headless --student DIR`) with the
// correct solutions (its last step's your_turn is right, every step passes) and with buggy flips from
// tests/grading/students, each in a folder of its own as flip.lua: the lesson names the mistake in the Exercises tab's
// words (check_exercise on the same diamond gives the same first difference), an answers file that expects "right"
// fails naming the step, and a Lua error is reported at the student's file:line. Skips when the binary is not built.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "core/mesh_build.h"
#include "core/polygon_mesh.h"
#include "script/exercises.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  int status = -1;
  std::string out, err;
};

Outcome run_meshedit(const fs::path& dir, const std::string& arguments) {
  const auto out = dir / "lesson_stdout.txt", err = dir / "lesson_stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(MESHEDIT_BINARY) + "' " + arguments +
                              " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  Outcome o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.out = testing::read_text(out);
  o.err = testing::read_text(err);
  return o;
}

const fs::path& source() {
  static const fs::path dir = testing::source_dir();
  return dir;
}

fs::path shipped_answers() { return source() / "tests" / "script" / "lessons" / "4_edge_flip_answers.lua"; }

// Lesson 4 headless with `answers` and the student folder `student`.
Outcome run_lesson_4(const fs::path& dir, const fs::path& answers, const fs::path& student) {
  const fs::path lesson = source() / "lessons" / "4_edge_flip.lua";
  return run_meshedit(dir, "lesson '" + lesson.string() + "' --headless --answers '" + answers.string() +
                               "' --student '" + student.string() + "'");
}

// A student folder in `dir` holding tests/grading/students/FIXTURE.lua as flip.lua.
fs::path student_folder(const fs::path& dir, const std::string& fixture) {
  const fs::path folder = dir / fixture;
  fs::create_directories(folder);
  fs::copy_file(source() / "tests" / "grading" / "students" / (fixture + ".lua"), folder / "flip.lua",
                fs::copy_options::overwrite_existing);
  return folder;
}

// The shipped answers with the last step's your_turn expecting a wrong verdict that names `words`.
fs::path answers_expecting_wrong(const fs::path& dir, const std::string& words) {
  std::string text = testing::read_text(shipped_answers());
  const std::string right = "{your_turn = \"right\"}";
  const size_t at = text.find(right);
  EXPECT_NE(at, std::string::npos) << "the shipped answers expect your_turn = \"right\"";
  if (at != std::string::npos) text.replace(at, right.size(), "{your_turn = \"wrong\", feedback = \"" + words + "\"}");
  const fs::path path = dir / "wrong_answers.lua";
  std::ofstream(path) << text;
  return path;
}

// The lesson's last diamond ("rigged"): f0.halfedge = h2, f1.halfedge = h4, a.halfedge = h0, b.halfedge = h1 in the
// diagram's names, walking from e0's halfedge as the lesson does.
std::shared_ptr<const HalfedgeMesh> rigged_diamond() {
  PolygonMesh polygons;
  polygons.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  polygons.indices = {0, 1, 2, 1, 0, 3};
  polygons.face_offsets = {0, 3, 6};
  auto mesh = std::make_shared<HalfedgeMesh>(build_halfedge_mesh(polygons));
  const HalfedgeId h0 = mesh->halfedge(EdgeId(0)), h1 = mesh->twin(h0);
  mesh->set_halfedge(mesh->face(h0), mesh->next(h0));
  mesh->set_halfedge(mesh->face(h1), mesh->next(h1));
  mesh->set_halfedge(mesh->vertex(h0), h0);
  mesh->set_halfedge(mesh->vertex(h1), h1);
  return mesh;
}

// What the Exercises tab says first about the fixture's flip_edge on that diamond's e0.
std::string exercises_tab_diagnosis(const fs::path& folder) {
  auto code = load_student_file(folder / "flip.lua");
  const ExerciseReport report =
      check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(rigged_diamond(), EdgeId(0)));
  EXPECT_FALSE(report.equal);
  return report.differences.empty() ? "(no difference)" : report.differences.front();
}

TEST(LessonStudent, TheCorrectFlipPassesLessonFour) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path solutions = source() / "tests" / "script" / "solutions";
  const Outcome o = run_lesson_4(testing::scratch_dir(), shipped_answers(), solutions);
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "");
  EXPECT_NE(o.out.find("  > your turn flip.lua: right\n"), std::string::npos) << o.out;
  ASSERT_GE(o.out.size(), 16u);
  EXPECT_EQ(o.out.substr(o.out.size() - 16), "\n6 steps passed\n");
}

TEST(LessonStudent, AFlipThatForgetsTheFacesIsToldWhatTheExercisesTabSays) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  const fs::path student = student_folder(dir, "flip_forgets_faces");
  const std::string words = "f0.halfedge is h1, but h1.face is f1";
  EXPECT_NE(exercises_tab_diagnosis(student).find(words), std::string::npos) << exercises_tab_diagnosis(student);

  const Outcome o = run_lesson_4(dir, answers_expecting_wrong(dir, words), student);
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("  > your turn flip.lua: wrong: " + exercises_tab_diagnosis(student) + "\n"),
            std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("  (wrong, as the answers expect: going on)\n"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.substr(o.out.size() - 16), "\n6 steps passed\n");

  // The shipped answers expect the right answer: a buggy flip fails the run at the your_turn line, naming the step.
  const Outcome failed = run_lesson_4(dir, shipped_answers(), student);
  EXPECT_EQ(failed.status, 1);
  EXPECT_NE(failed.err.find("4_edge_flip.lua:"), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find(": step 6 'Before and after, pointer by pointer': your_turn should be judged right, but it "
                            "was judged wrong: after your flip_edge the mesh is not valid (2 problems): " + words),
            std::string::npos)
      << failed.err;
}

TEST(LessonStudent, AFlipThatForgetsTheVerticesIsToldWhatTheExercisesTabSays) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  const fs::path student = student_folder(dir, "flip_forgets_vertices");
  const std::string words = "v0.halfedge is h0, but h0 leaves v3";
  EXPECT_NE(exercises_tab_diagnosis(student).find(words), std::string::npos) << exercises_tab_diagnosis(student);

  const Outcome o = run_lesson_4(dir, answers_expecting_wrong(dir, words), student);
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("  > your turn flip.lua: wrong: " + exercises_tab_diagnosis(student) + "\n"), std::string::npos)
      << o.out;

  // Expecting words the diagnosis does not hold fails the run and quotes what it said.
  const Outcome other = run_lesson_4(dir, answers_expecting_wrong(dir, "h2.face"), student);
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.err.find("your_turn should be judged wrong with feedback containing 'h2.face', but its feedback was "
                           "'after your flip_edge the mesh is not valid (2 problems): " + words),
            std::string::npos)
      << other.err;
}

TEST(LessonStudent, AStudentFileThatFailsIsReportedAtItsLine) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "broken");
  std::ofstream(dir / "broken" / "flip.lua") << "function flip_edge(mesh, e)\n  return e.halfedge.nope.twin\nend\n";
  const Outcome o = run_lesson_4(dir, answers_expecting_wrong(dir, "flip.lua:2:"), dir / "broken");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("  > your turn flip.lua: wrong: flip.lua:2: "), std::string::npos) << o.out;
}

TEST(LessonStudent, AMissingStudentFolderIsAUsageError) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  const Outcome o = run_lesson_4(dir, shipped_answers(), dir / "nowhere");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "meshedit: --student " + (dir / "nowhere").string() + ": no such folder (see meshedit --help)\n");
}

}  // namespace
}  // namespace meshedit
