// The grading suites of the six parts (tests/grading/suites/*.lua): the correct solutions
// (tests/exercise/solutions, the exercises' own) score full marks on every suite, the extra credit (boundary split,
// boundary Loop) on top of the base points; a correct split allocating its ids in another order scores the same;
// each buggy fixture in tests/grading/students/ loses exactly the tests its mistake breaks, with the window's
// diagnosis of it. (flip.lua's fixtures are in flip_suite_test.cpp; that every fixture's message is the window's is
// window_grader_agreement_test.cpp.)
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "grade/results_writers.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

using testing::grading_dir;
using testing::read_text;

GradeReport grade_with(const std::string& suite_name, const Submission& submission) {
  auto suite = Suite::load(grading_dir() / "suites" / (suite_name + ".lua"));
  return grade(*suite, submission, testing::quick_options());
}

GradeReport grade_fixture(const std::string& part, const std::string& fixture, double time_limit_cap = 0) {
  auto suite = Suite::load(grading_dir() / "suites" / (part + ".lua"));
  GradeOptions options = testing::quick_options();
  options.time_limit_cap = time_limit_cap;
  return grade(*suite, testing::submission_of({{part + ".lua", read_text(grading_dir() / "students" / fixture)}}),
               options);
}

std::map<std::string, double> failed(const GradeReport& report) {
  std::map<std::string, double> out;
  for (const auto& t : report.tests) {
    if (!t.passed) out[t.number] = t.score;
  }
  return out;
}

std::string output_of(const GradeReport& report, const std::string& number) {
  for (const auto& t : report.tests) {
    if (t.number == number) return t.output;
  }
  return "(no test " + number + ")";
}

TEST(PartSuites, TheCorrectSolutionsScoreFullMarksEverywhere) {
  const Submission solutions = Submission::read(testing::source_dir() / "tests" / "exercise" / "solutions");
  struct Points {
    double base, extra;
  };
  const std::map<std::string, Points> points = {{"curve", {9, 0}}, {"patch", {7, 0}}, {"normals", {9, 0}},
                                                {"flip", {10, 0}}, {"split", {9, 1}}, {"upsample", {10, 1}}};
  for (const auto& [part, p] : points) {
    SCOPED_TRACE(part);
    const GradeReport report = grade_with(part, solutions);
    EXPECT_EQ(report.max_score, p.base);
    EXPECT_EQ(report.extra_points, p.extra);
    EXPECT_EQ(report.score, p.base + p.extra);
    EXPECT_EQ(report.failed(), 0u) << text_report(report);
  }
}

TEST(PartSuites, TheWholeAssignmentInOneSuite) {
  const Submission solutions = Submission::read(testing::source_dir() / "tests" / "exercise" / "solutions");
  auto suite = Suite::load(grading_dir() / "suites" / "all.lua");
  EXPECT_EQ(suite->name(), "meshedit");
  const GradeReport report = grade(*suite, solutions, testing::quick_options());
  EXPECT_EQ(report.tests.size(), 29u);
  EXPECT_EQ(report.max_score, 54.0);
  EXPECT_EQ(report.extra_points, 2.0);
  EXPECT_EQ(report.score, 56.0) << text_report(report);
  // A submission with only a correct flip.lua: part 4 full, every other test fails to load its file.
  const GradeReport flip_only =
      grade(*suite, testing::submission_of({{"flip.lua", read_text(grading_dir() / "students" / "flip_correct.lua")}}),
            testing::quick_options());
  EXPECT_EQ(flip_only.score, 10.0);
  EXPECT_EQ(summary_line(flip_only), "5 passed, 24 failed");
}

TEST(PartSuites, ADeCasteljauStepThatDropsTheLastPoint) {
  const GradeReport r = grade_fixture("curve", "curve_drops_last.lua");
  EXPECT_EQ(r.score, 1.0);
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"1.1", 0}, {"1.2", 0}, {"1.4", 0}, {"1.5", 0}}));
  EXPECT_EQ(output_of(r, "1.1"),
            "FAILED: evaluate_step(cubic, 0.5): point 3 of the step is missing (got 2 points, "
            "expected 3): n points give n - 1, so the loop runs i = 1, ..., n - 1\n"
            "0 checks of 1 passed.\n");
}

TEST(PartSuites, ADeCasteljauStepWithSwappedWeights) {
  const GradeReport r = grade_fixture("curve", "curve_swapped_weights.lua");
  EXPECT_EQ(r.score, 4.428571);  // t = 0.5 cannot tell the weights apart: 1.1 passes, and so do 1.4's steps at 0.5
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"1.2", 0}, {"1.4", 1.428571}, {"1.5", 0}}));
  EXPECT_EQ(output_of(r, "1.2").rfind("FAILED: evaluate_step of 2 points at t = 0: the weights are swapped: point i of "
                                      "the step must be (1 - t) * p_i + t * p_(i+1), and yours are t * p_i + (1 - t) * "
                                      "p_(i+1)",
                                      0),
            0u)
      << output_of(r, "1.2");
}

TEST(PartSuites, APatchEvaluatedColumnsFirst) {
  const GradeReport r = grade_fixture("patch", "patch_columns_first.lua");
  EXPECT_EQ(r.score, 0.733333);
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"2.1", 0}, {"2.2", 0.333333}, {"2.3", 0.4}}));
  EXPECT_EQ(output_of(r, "2.1").rfind("FAILED: corner at (u, v) = (1, 0): your point (0, 3, -0.30000000000000004) is "
                                      "the surface point at (u, v) = (0, 1), not (1, 0): u and v are swapped.",
                                      0),
            0u)
      << output_of(r, "2.1");
}

TEST(PartSuites, NormalsAveragingUnitFaceNormals) {
  const GradeReport r = grade_fixture("normals", "normals_unit_average.lua");
  EXPECT_EQ(r.score, 3.0);  // on a cube every face around a vertex has the same area: 3.1 passes
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"3.2", 0}, {"3.4", 0}, {"3.5", 0}}));
  EXPECT_EQ(output_of(r, "3.2").rfind("FAILED: the centre of the fan v0: your normal (-0.07154604533836022, "
                                      "0.19450565544319706, 0.9782886656795394) is the average of the faces' unit "
                                      "normals; the reference (-0.16197821539494556, ",
                                      0),
            0u)
      << output_of(r, "3.2");
}

TEST(PartSuites, CorrectSplitsAndUpsamplesScoreFullMarksWhateverIdsTheyAllocate) {
  for (const char* fixture : {"split_correct.lua", "split_reordered.lua"}) {
    SCOPED_TRACE(fixture);
    const GradeReport r = grade_fixture("split", fixture);
    EXPECT_EQ(r.score, 10.0);  // 9 base points and the extra credit of 5.4
    EXPECT_EQ(r.failed(), 0u) << text_report(r);
  }
  EXPECT_EQ(grade_fixture("upsample", "upsample_correct.lua").score, 11.0);
}

TEST(PartSuites, WithoutTheBoundaryCasesAllTheBasePointsAndNoExtraCredit) {
  const GradeReport split = grade_fixture("split", "split_without_boundary.lua");
  EXPECT_EQ(split.score, 9.0);
  EXPECT_EQ(split.max_score, 9.0);
  EXPECT_EQ(failed(split), (std::map<std::string, double>{{"5.4", 0}}));
  const GradeReport upsample = grade_fixture("upsample", "upsample_without_boundary.lua");
  EXPECT_EQ(upsample.score, 10.0);
  EXPECT_EQ(upsample.max_score, 10.0);
  EXPECT_EQ(failed(upsample), (std::map<std::string, double>{{"6.4", 0}}));
  for (const GradeReport* r : {&split, &upsample}) {
    const TestResult& extra = r->tests[3];  // 5.4 and 6.4
    EXPECT_EQ(extra.max_score, 0.0);
    EXPECT_EQ(extra.extra_points, 1.0);
    EXPECT_EQ(extra.tags, std::vector<std::string>{"extra credit"});
    EXPECT_NE(extra.name.find("(extra credit)"), std::string::npos) << extra.name;
    EXPECT_NE(extra.output.find("Extra credit: 0 of 1 point, added on top of the base score."), std::string::npos)
        << extra.output;
  }
}

TEST(PartSuites, ASplitVertexAtTheAverageOfTheCorners) {
  const GradeReport r = grade_fixture("split", "split_corner_average.lua");
  EXPECT_EQ(r.score, 5.0);  // on the square of 5.1 the corners' average is the midpoint; so it is on a cube's diagonals
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"5.2", 1.0}, {"5.4", 0}, {"5.5", 0}}));
  EXPECT_EQ(
      output_of(r, "5.2").rfind("FAILED: split_edge(e0) of a cube: your new vertex v8 is at (-0.25, 0.25, -0.25), "
                                "the average of the corners v0 v2 v3 v6; it belongs at the midpoint of v0 and v2, "
                                "(-0.5, 0, -0.5)",
                                0),
      0u)
      << output_of(r, "5.2");
}

TEST(PartSuites, ASplitWithAWrongFaceOnANewHalfedge) {
  const GradeReport r = grade_fixture("split", "split_wrong_face.lua");
  EXPECT_EQ(r.score, 2.0);
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"5.1", 0}, {"5.2", 0}, {"5.4", 0}, {"5.5", 0}}));
  EXPECT_EQ(
      output_of(r, "5.1").rfind("FAILED: split_edge(e2) of a 1x1 grid: after your split_edge the mesh is not valid "
                                "(1 problem): h12.face is f0, but h12 is in f2's next-cycle\n",
                                0),
      0u)
      << output_of(r, "5.1");
}

TEST(PartSuites, UpsampleFlippingEdgesWithOnlyOneEndpointChecked) {
  const GradeReport r = grade_fixture("upsample", "upsample_flip_one_check.lua");
  EXPECT_EQ(r.score, 4.0);  // valid and the right counts: 40% of each base test
  EXPECT_EQ(failed(r),
            (std::map<std::string, double>{{"6.1", 1.2}, {"6.2", 1.2}, {"6.3", 0.8}, {"6.4", 0}, {"6.5", 0.8}}));
  EXPECT_NE(
      output_of(r, "6.1").find("FAILED: tetrahedron: 3 of your edges join two original vertices, e.g. e13 (v0 v1): "
                               "a new edge whose ends were both new was flipped"),
      std::string::npos)
      << output_of(r, "6.1");
}

TEST(PartSuites, UpsampleFlippingHalvesOfSplitEdges) {
  const GradeReport r = grade_fixture("upsample", "upsample_flips_split_halves.lua");
  EXPECT_EQ(r.score, 4.0);
  EXPECT_NE(
      output_of(r, "6.1").find("FAILED: tetrahedron: 2 of your edges join two new vertices where the reference has "
                               "none, e.g. e1 (v9 v4): an edge that was not new (a half of a split edge) was "
                               "flipped"),
      std::string::npos)
      << output_of(r, "6.1");
}

TEST(PartSuites, UpsampleWritingPositionsToTheWrongVertices) {
  const GradeReport r = grade_fixture("upsample", "upsample_wrong_vertices.lua");
  EXPECT_EQ(r.score, 4.0);
  EXPECT_NE(
      output_of(r, "6.1").find("FAILED: tetrahedron: 4 of your original vertices sit where the reference puts new "
                               "vertices, e.g. v0 at (0, 0, 0.5), where the reference puts the new vertex v7: a "
                               "position computed for a new vertex (step 2) was written to an original one"),
      std::string::npos)
      << output_of(r, "6.1");
}

TEST(PartSuites, UpsampleSplittingTheEdgesItCreatesNeverEnds) {
  const GradeReport r = grade_fixture("upsample", "upsample_splits_new_edges.lua", 0.5);
  EXPECT_EQ(r.score, 0.0);
  for (const auto& t : r.tests) {
    EXPECT_TRUE(t.end == RunEnd::Timeout || t.end == RunEnd::Memory) << t.number << ": " << run_end_name(t.end);
    EXPECT_NE(t.output.find("\nupsample did not finish: split only the edges of the original mesh (list them before "
                            "the first split)"),
              std::string::npos)
        << t.output;
  }
}

TEST(PartSuites, UpsampleWithIntegerDivisionWeights) {
  const GradeReport r = grade_fixture("upsample", "upsample_integer_division.lua");
  EXPECT_EQ(r.score,
            5.0);  // 6.4 (extra credit) passes: a grid's vertices are all on the boundary, where no weight is 3 // 16
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"6.1", 1.2}, {"6.2", 1.2}, {"6.3", 0.8}, {"6.5", 0.8}}));
  EXPECT_NE(
      output_of(r, "6.1").find("FAILED: tetrahedron: your weight u is 0 for degree 3 (in Lua 3 // 16 is 0, an integer "
                               "division: write 3 / 16): 4 of the 4 original vertices kept their old positions while "
                               "your new vertices moved"),
      std::string::npos)
      << output_of(r, "6.1");
}

TEST(PartSuites, UpsampleWithTheWrongWeightForDegreeThree) {
  const GradeReport r = grade_fixture("upsample", "upsample_wrong_weight.lua");
  EXPECT_EQ(r.score, 9.2);  // only the tetrahedron has vertices of degree 3
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"6.1", 1.2}}));
  EXPECT_NE(
      output_of(r, "6.1").find("FAILED: tetrahedron: your original vertex v0 (degree 3) moved as if u = 0.125 (4 "
                               "original vertices moved by a wrong weight); the course's u for degree 3 is 3/16 = "
                               "0.1875 (yours is 3 / (8 n) with n = 3: degree 3 is the exception, u = 3/16)"),
      std::string::npos)
      << output_of(r, "6.1");
}

}  // namespace
}  // namespace meshedit
