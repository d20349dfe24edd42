// An exercise defined in Lua alone graded as a suite of its own (`meshedit grade --suite
// scripts/exercises/collapse.lua`): one test per fixture, with the fixture's name and points; the correct solution
// scores every point; a buggy one fails each test with the diagnosis the window's check gives on the same input;
// the built binary prints the same.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/scripted_exercise.h"
#include "grade/grader.h"
#include "grade/suite.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

fs::path definition() { return testing::source_dir() / "scripts" / "exercises" / "collapse.lua"; }
std::string solution() {
  return read_text(testing::source_dir() / "tests" / "exercise" / "solutions" / "collapse.lua");
}
fs::path buggy_file() { return testing::grading_dir() / "scripted" / "collapse_keeps_position.lua"; }

TEST(ScriptedExerciseGrading, EachFixtureIsATestAndTheSolutionScoresEveryPoint) {
  auto suite = Suite::load(definition());
  const GradeReport report =
      grade(*suite, testing::submission_of({{"collapse.lua", solution()}}), testing::quick_options());
  EXPECT_EQ(report.suite_name, "collapse");
  ASSERT_EQ(report.tests.size(), 3u);
  EXPECT_EQ(report.tests[0].number, "1");
  EXPECT_EQ(report.tests[0].name, "an edge of an icosahedron");
  EXPECT_EQ(report.tests[0].max_score, 2.0);
  EXPECT_EQ(report.tests[2].name, "a diagonal of a 2x2 grid's corner square");
  EXPECT_EQ(report.tests[2].max_score, 1.0);
  EXPECT_EQ(report.failed(), 0u) << report.tests[0].output;
  EXPECT_EQ(report.score, 5.0);
  EXPECT_EQ(report.max_score, 5.0);
}

TEST(ScriptedExerciseGrading, ABuggySubmissionIsToldWhatTheWindowSays) {
  auto suite = Suite::load(definition());
  const GradeReport report =
      grade(*suite, testing::submission_of({{"collapse.lua", read_text(buggy_file())}}), testing::quick_options());
  EXPECT_EQ(report.score, 0.0);
  // The window's check of the third fixture, on the registry's own copy of it.
  const std::optional<Exercise> id = find_exercise("collapse");
  ASSERT_TRUE(id.has_value());
  const ScriptedFixture& fixture = id->definition()->fixtures()[2];
  const fs::path dir = testing::scratch_dir();
  fs::copy_file(buggy_file(), dir / "collapse.lua");
  auto code = load_student_file(dir / "collapse.lua");
  const ExerciseReport window = check_exercise(*code, *id, ExerciseInput::element_of(fixture.mesh, fixture.element));
  ASSERT_FALSE(window.differences.empty());
  EXPECT_EQ(window.differences[0],
            "the vertex that remains is still where a was; collapse moves it to the midpoint "
            "of a and b, (0.5, 0.5, 0)");
  ASSERT_EQ(report.tests.size(), 3u);
  EXPECT_NE(report.tests[2].output.find("FAILED: a diagonal of a 2x2 grid's corner square: " + window.differences[0]),
            std::string::npos)
      << report.tests[2].output;
}

// The Catmull-Clark exercise (scripts/exercises/catmull_clark.lua): the correct level scores every point, the one
// that moves vertices as it computes them is told so in the window's words, a mesh with triangles is refused (the
// solution changes nothing), and the core's level is hidden from the student's code.
TEST(ScriptedExerciseGrading, CatmullClarkSolutionScoresAndMovingInPlaceIsNamed) {
  const fs::path cc = testing::source_dir() / "scripts" / "exercises" / "catmull_clark.lua";
  auto suite = Suite::load(cc);
  const std::string correct =
      read_text(testing::source_dir() / "tests" / "exercise" / "solutions" / "catmull_clark.lua");
  const GradeReport right =
      grade(*suite, testing::submission_of({{"catmull_clark.lua", correct}}), testing::quick_options());
  ASSERT_EQ(right.tests.size(), 3u);
  EXPECT_EQ(right.failed(), 0u) << right.tests[0].output << right.tests[1].output << right.tests[2].output;
  EXPECT_EQ(right.score, 5.0);

  const fs::path buggy = testing::grading_dir() / "scripted" / "catmull_clark_moves_in_place.lua";
  const GradeReport wrong =
      grade(*suite, testing::submission_of({{"catmull_clark.lua", read_text(buggy)}}), testing::quick_options());
  EXPECT_EQ(wrong.score, 1.0) << "only the refused pyramid passes";
  const std::optional<Exercise> id = find_exercise("catmull_clark");
  ASSERT_TRUE(id.has_value());
  const ScriptedFixture& cube = id->definition()->fixtures()[0];
  const fs::path dir = testing::scratch_dir();
  fs::copy_file(buggy, dir / "catmull_clark.lua");
  auto code = load_student_file(dir / "catmull_clark.lua");
  const ExerciseReport window = check_exercise(*code, *id, ExerciseInput::whole_mesh(cube.mesh));
  ASSERT_FALSE(window.differences.empty());
  EXPECT_EQ(window.differences[0].rfind("your vertices read neighbours you had already moved", 0), 0u)
      << window.differences[0];
  EXPECT_NE(wrong.tests[0].output.find("FAILED: a cube of six quads: " + window.differences[0]), std::string::npos)
      << wrong.tests[0].output;

  const GradeReport cheat = grade(*suite,
                                  testing::submission_of({{"catmull_clark.lua",
                                                           "function catmull_clark_level(mesh)\n"
                                                           "  return mesh:catmull_clark()\nend\n"}}),
                                  testing::quick_options());
  EXPECT_EQ(cheat.score, 0.0);
  EXPECT_NE(cheat.tests[0].output.find("catmull_clark.lua:2: mesh:catmull_clark is hidden from your code"),
            std::string::npos)
      << cheat.tests[0].output;
}

TEST(ScriptedExerciseGrading, TheCommandLineGradesTheDefinitionFile) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  testing::write_text(dir / "submission" / "collapse.lua", solution());
  const std::string command = "'" + std::string(MESHEDIT_BINARY) + "' grade --suite '" + definition().string() +
                              "' --submission '" + (dir / "submission").string() + "' > '" +
                              (dir / "out.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const std::string out = read_text(dir / "out.txt");
  EXPECT_NE(out.find("PASS 1 an edge of an icosahedron  2/2"), std::string::npos) << out;
  EXPECT_NE(out.find("Score: 5 / 5"), std::string::npos) << out;
}

}  // namespace
}  // namespace meshedit
