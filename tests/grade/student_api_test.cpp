// One student API for the window and the grader (exercise/student_api.h): a flip_edge that calls mesh:flip is refused
// in both, with the same words; what each exercise may use is the same in the shipped suites as in the window; the
// templates students start from never suggest a call their code cannot make.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/student_api.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::grading_dir;

// A flip_edge that hands the work to the reference operation; line 2 calls it.
constexpr const char* kFlipWithTheReference = "function flip_edge(mesh, e)\n  return mesh:flip(e)\nend\n";

TEST(StudentApi, MeshFlipInsideFlipEdgeIsRefusedAlikeInTheWindowAndInGrading) {
  const std::string refusal = "flip.lua:2: " + hidden_api_message("mesh:flip");
  EXPECT_EQ(refusal,
            "flip.lua:2: mesh:flip is hidden from your code (in the window and in grading): it is what "
            "flip_edge does, so write the pointer updates yourself");

  // The window: the Exercises panel's check of e2 of a 1x1 grid.
  const fs::path file = testing::scratch_dir() / "flip.lua";
  testing::write_text(file, kFlipWithTheReference);
  auto code = load_student_file(file);
  const auto grid = std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_grid(1, 1)));
  const ExerciseReport window = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(grid, EdgeId(2)));
  EXPECT_FALSE(window.mine.ran);
  EXPECT_EQ(window.mine.error, refusal);
  ASSERT_FALSE(window.differences.empty());
  EXPECT_EQ(window.differences[0], refusal);

  // The grader: test 4.1 of the flip suite, the same flip.
  auto suite = Suite::load(grading_dir() / "suites" / "flip.lua");
  const GradeReport report =
      grade(*suite, testing::submission_of({{"flip.lua", kFlipWithTheReference}}), testing::quick_options());
  EXPECT_EQ(report.score, 0.0);
  ASSERT_FALSE(report.tests.empty());
  EXPECT_EQ(report.tests[0].end, RunEnd::Error);
  EXPECT_EQ(report.tests[0].output.rfind("Error: " + refusal + "\n", 0), 0u) << report.tests[0].output;
}

// A patch.lua that calls part 1's evaluate_step, which only curve.lua defines; line 5 calls it.
constexpr const char* kPatchWithPartOnesStep =
    "function evaluate(patch, u, v)\n"
    "  local rows = {}\n"
    "  for r = 0, 3 do\n"
    "    local row = {} for c = 1, 4 do row[c] = patch.points[r * 4 + c] end\n"
    "    while #row > 1 do row = evaluate_step(row, u) end\n"
    "    rows[#rows + 1] = row[1]\n"
    "  end\n"
    "  return rows[1]\n"
    "end\n";

TEST(StudentApi, CallingAnotherExercisesFunctionSaysEachFileRunsAloneInBoth) {
  const std::string error = "patch.lua:5: " + other_file_message("evaluate_step", "curve.lua", "patch.lua");
  EXPECT_EQ(error,
            "patch.lua:5: evaluate_step is curve.lua's function, and each exercise file runs on its own (in the "
            "window and in grading, where patch.lua is loaded alone), so patch.lua cannot call it: copy the "
            "function into patch.lua, as a local function");

  // The window: the patch view's check (and lesson 2's your_turn) of the sheet at (0.25, 0.5).
  const fs::path file = testing::scratch_dir() / "patch.lua";
  testing::write_text(file, kPatchWithPartOnesStep);
  auto code = load_student_file(file);
  EXPECT_FALSE(code->defines(Exercise::CurveStep));  // the guide is no definition
  BezierPatch sheet;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) sheet.at(r, c) = glm::dvec3(c, r, 0.0);
  }
  const ExerciseReport window =
      check_exercise(*code, Exercise::PatchEvaluate, ExerciseInput::patch_point(sheet, 0.25, 0.5));
  EXPECT_FALSE(window.mine.ran);
  EXPECT_EQ(window.mine.error, error);

  // The grader: the patch suite's first test, the same file.
  auto suite = Suite::load(grading_dir() / "suites" / "patch.lua");
  const GradeReport report =
      grade(*suite, testing::submission_of({{"patch.lua", kPatchWithPartOnesStep}}), testing::quick_options());
  EXPECT_EQ(report.score, 0.0);
  ASSERT_FALSE(report.tests.empty());
  EXPECT_EQ(report.tests[0].end, RunEnd::Error);
  EXPECT_EQ(report.tests[0].output.rfind("Error: " + error + "\n", 0), 0u) << report.tests[0].output;
}

TEST(StudentApi, UpsampleMayUseTheReferenceFlipAndSplitInBoth) {
  EXPECT_EQ(exercise_api(Exercise::Upsample).allow_api, (std::vector<std::string>{"mesh:flip", "mesh:split"}));
  EXPECT_EQ(exercise_api(Exercise::Upsample).reference, (std::vector<std::string>{"flip_edge", "split_edge"}));
  // The window: an upsample written with the reference flip_edge and split_edge (the template offers both ways).
  const std::string text = testing::read_text(grading_dir() / "students" / "upsample_correct.lua");
  std::string with_functions = text;
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"mesh:split(o.edge)", "split_edge(mesh, o.edge)"},
                                 {"then mesh:flip(e) end", "then flip_edge(mesh, e) end"}}) {
    const size_t at = with_functions.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    with_functions.replace(at, from.size(), to);
  }
  for (const std::string& source : {text, with_functions}) {
    const fs::path file = testing::scratch_dir() / "upsample.lua";
    testing::write_text(file, source);
    auto code = load_student_file(file);
    const auto cube = std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_cube()));
    const ExerciseReport window = check_exercise(*code, Exercise::Upsample, ExerciseInput::whole_mesh(cube));
    EXPECT_TRUE(window.equal) << window.summary();
    auto suite = Suite::load(grading_dir() / "suites" / "upsample.lua");
    const GradeReport report =
        grade(*suite, testing::submission_of({{"upsample.lua", source}}), testing::quick_options());
    EXPECT_EQ(report.score, 11.0);
  }
}

TEST(StudentApi, TheShippedSuitesAllowWhatTheWindowAllows) {
  auto suite = Suite::load(grading_dir() / "suites" / "all.lua");
  for (const TestSpec& spec : suite->tests()) {
    SCOPED_TRACE(spec.number);
    ASSERT_EQ(spec.files.size(), 1u);
    const std::optional<Exercise> exercise = find_exercise(spec.files[0]);
    ASSERT_TRUE(exercise.has_value());
    EXPECT_EQ(spec.allow_api, exercise_api(*exercise).allow_api);
    EXPECT_EQ(spec.reference, exercise_api(*exercise).reference);
  }
}

// A template line naming a call hidden from its exercise must say it is not for the student's code.
TEST(StudentApi, TheTemplatesNeverSuggestAHiddenCall) {
  const std::vector<std::pair<std::string, std::string>> spellings = {{"mesh:flip", "mesh:flip("},
                                                                      {"mesh:split", "mesh:split("},
                                                                      {"mesh:collapse", "mesh:collapse("},
                                                                      {"mesh:loop_subdivide", "mesh:loop_subdivide("},
                                                                      {"mesh:catmull_clark", "mesh:catmull_clark("},
                                                                      {"meshedit.curve", "meshedit.curve("},
                                                                      {"meshedit.patch", "meshedit.patch("}};
  size_t mentions = 0;
  for (const Exercise exercise : builtin_exercises()) {
    const ExerciseInfo& info = exercise.info();
    std::istringstream lines(testing::read_text(testing::source_dir() / "scripts" / "student" / info.file));
    const auto& allowed = exercise_api(exercise).allow_api;
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
      for (const auto& [api, spelled] : spellings) {
        if (line.find(spelled) == std::string::npos) continue;
        if (std::find(allowed.begin(), allowed.end(), api) != allowed.end()) continue;
        ++mentions;
        EXPECT_TRUE(line.find("not for use") != std::string::npos || line.find("hidden") != std::string::npos)
            << info.file << ":" << number << " suggests " << api << ", which is hidden from its code: " << line;
      }
    }
  }
  EXPECT_GT(mentions, 0u);  // the templates do name the references; the check above has lines to hold
}

}  // namespace
}  // namespace meshedit
