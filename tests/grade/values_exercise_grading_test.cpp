// Exercises defined in Lua on control points or a patch, graded as suites of their own (`meshedit grade --suite
// scripts/exercises/hodograph.lua`, `.../patch_normal.lua`): one test per fixture with its name and points; the
// correct solutions score every point; each buggy submission fails the fixtures its bug shows on, with the diagnosis
// the window's check gives on the same input; the built binary writes the same scores to results.json.
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

fs::path definition(const std::string& name) { return testing::source_dir() / "scripts" / "exercises" / name; }
std::string solution(const std::string& name) {
  return read_text(testing::source_dir() / "tests" / "exercise" / "solutions" / name);
}
std::string buggy(const std::string& name) { return read_text(testing::grading_dir() / "scripted" / name); }

// The window's first difference for `text` as the exercise's file on fixture `index` of the registered `name`.
std::string window_diagnosis(const std::string& name, const std::string& text, size_t index) {
  const std::optional<Exercise> id = find_exercise(name);
  if (!id) return "(not registered)";
  const ScriptedExercise& exercise = *id->definition();
  const fs::path dir = testing::scratch_dir();
  testing::write_text(dir / exercise.info().file, text);
  auto code = load_student_file(dir / exercise.info().file);
  const ExerciseReport report = check_exercise(*code, *id, exercise.input_of(exercise.fixtures().at(index)));
  return report.differences.empty() ? "(no difference)" : report.differences[0];
}

TEST(ValuesExerciseGrading, TheHodographSolutionScoresEveryPoint) {
  auto suite = Suite::load(definition("hodograph.lua"));
  const GradeReport report =
      grade(*suite, testing::submission_of({{"hodograph.lua", solution("hodograph.lua")}}), testing::quick_options());
  EXPECT_EQ(report.suite_name, "hodograph");
  ASSERT_EQ(report.tests.size(), 5u);
  EXPECT_EQ(report.tests[0].name, "a cubic in the plane");
  EXPECT_EQ(report.tests[0].max_score, 2.0);
  EXPECT_EQ(report.tests[4].name, "a single point (degree 0): no control points");
  EXPECT_EQ(report.failed(), 0u) << report.tests[0].output;
  EXPECT_EQ(report.score, 7.0);
  EXPECT_EQ(report.max_score, 7.0);
}

TEST(ValuesExerciseGrading, AForgottenFactorFailsWhereNIsNotOneInTheWindowsWords) {
  auto suite = Suite::load(definition("hodograph.lua"));
  const GradeReport report = grade(
      *suite, testing::submission_of({{"hodograph.lua", buggy("hodograph_no_factor.lua")}}), testing::quick_options());
  ASSERT_EQ(report.tests.size(), 5u);
  EXPECT_EQ(report.score, 2.0) << "the line (n = 1) and the single point pass";
  EXPECT_EQ(report.tests[0].score, 0.0);
  EXPECT_EQ(report.tests[3].score, 1.0);
  const std::string first = window_diagnosis("hodograph", buggy("hodograph_no_factor.lua"), 0);
  EXPECT_EQ(first.rfind("your points are the differences P[i+1] - P[i] without the factor n", 0), 0u) << first;
  EXPECT_NE(report.tests[0].output.find("FAILED: a cubic in the plane: " + first), std::string::npos)
      << report.tests[0].output;
}

TEST(ValuesExerciseGrading, APatchNormalSolutionScoresAndBothBugsFail) {
  auto suite = Suite::load(definition("patch_normal.lua"));
  const GradeReport right = grade(*suite, testing::submission_of({{"patch_normal.lua", solution("patch_normal.lua")}}),
                                  testing::quick_options());
  ASSERT_EQ(right.tests.size(), 4u);
  EXPECT_EQ(right.failed(), 0u) << right.tests[1].output;
  EXPECT_EQ(right.score, 6.0);

  for (const char* bug : {"patch_normal_unnormalised.lua", "patch_normal_flipped.lua"}) {
    const GradeReport wrong =
        grade(*suite, testing::submission_of({{"patch_normal.lua", buggy(bug)}}), testing::quick_options());
    EXPECT_EQ(wrong.score, 0.0) << bug;
    ASSERT_EQ(wrong.tests.size(), 4u);
    const std::string first = window_diagnosis("patch_normal", buggy(bug), 1);
    EXPECT_NE(wrong.tests[1].output.find("FAILED: a bump, off its middle: " + first), std::string::npos)
        << bug << ": " << wrong.tests[1].output;
  }
  const std::string flipped = window_diagnosis("patch_normal", buggy("patch_normal_flipped.lua"), 1);
  EXPECT_EQ(flipped.rfind("your normal (", 0), 0u) << flipped;
  EXPECT_NE(flipped.find(") points the other way: it is along S_v x S_u"), std::string::npos) << flipped;
  const std::string unnormalised = window_diagnosis("patch_normal", buggy("patch_normal_unnormalised.lua"), 1);
  EXPECT_EQ(unnormalised.rfind("your normal has length ", 0), 0u) << unnormalised;
}

TEST(ValuesExerciseGrading, TheCommandLineWritesTheScoresToResultsJson) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  testing::write_text(dir / "submission" / "hodograph.lua", buggy("hodograph_reversed.lua"));
  const std::string command = "'" + std::string(MESHEDIT_BINARY) + "' grade --suite '" +
                              definition("hodograph.lua").string() + "' --submission '" +
                              (dir / "submission").string() + "' --results '" + (dir / "results.json").string() +
                              "' > '" + (dir / "out.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string out = read_text(dir / "out.txt");
  EXPECT_NE(out.find("Score: 1 / 7"), std::string::npos) << out;
  const std::string json = read_text(dir / "results.json");
  EXPECT_NE(json.find("\"max_score\": 7"), std::string::npos) << json;
  EXPECT_NE(out.find("your points are n * (P[i] - P[i+1]): the difference is taken backwards"), std::string::npos)
      << out;
  // results.json says it in Markdown, the characters Markdown reads escaped.
  EXPECT_NE(json.find("your points are n \\\\* (P\\\\[i\\\\] - P\\\\[i+1\\\\]): the difference is taken backwards"),
            std::string::npos)
      << json;
}

}  // namespace
}  // namespace meshedit
