// The grading suites of the six parts (tests/grading/suites/*.lua): the correct solutions
// (tests/script/solutions, the exercises' own) score full marks on every suite, and each buggy fixture in
// tests/grading/students/ loses exactly the tests its mistake breaks, with a message pointing at it.
// (flip.lua's fixtures are in flip_suite_test.cpp.)
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
  const Submission solutions = Submission::read(testing::source_dir() / "tests" / "script" / "solutions");
  const std::map<std::string, double> max_scores = {{"curve", 9},  {"patch", 7}, {"normals", 9},
                                                    {"flip", 10},  {"split", 10}, {"upsample", 11}};
  for (const auto& [part, max_score] : max_scores) {
    SCOPED_TRACE(part);
    const GradeReport report = grade_with(part, solutions);
    EXPECT_EQ(report.max_score, max_score);
    EXPECT_EQ(report.score, max_score);
    EXPECT_EQ(report.failed(), 0u) << text_report(report);
  }
}

TEST(PartSuites, TheWholeAssignmentInOneSuite) {
  const Submission solutions = Submission::read(testing::source_dir() / "tests" / "script" / "solutions");
  auto suite = Suite::load(grading_dir() / "suites" / "all.lua");
  EXPECT_EQ(suite->name(), "meshedit");
  const GradeReport report = grade(*suite, solutions, testing::quick_options());
  EXPECT_EQ(report.tests.size(), 29u);
  EXPECT_EQ(report.max_score, 56.0);
  EXPECT_EQ(report.score, 56.0) << text_report(report);
  // A submission with only a correct flip.lua: part 4 full, every other test fails to load its file.
  const GradeReport flip_only = grade(
      *suite, testing::submission_of({{"flip.lua", read_text(grading_dir() / "students" / "flip_correct.lua")}}),
      testing::quick_options());
  EXPECT_EQ(flip_only.score, 10.0);
  EXPECT_EQ(summary_line(flip_only), "5 passed, 24 failed");
}

TEST(PartSuites, ADeCasteljauStepThatDropsTheLastPoint) {
  const GradeReport r = grade_fixture("curve", "curve_drops_last.lua");
  EXPECT_EQ(r.score, 1.0);
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"1.1", 0}, {"1.2", 0}, {"1.4", 0}, {"1.5", 0}}));
  EXPECT_EQ(output_of(r, "1.1"), "FAILED: evaluate_step(cubic, 0.5): expected 3 items, got 2\n0 checks of 1 passed.\n");
}

TEST(PartSuites, ADeCasteljauStepWithSwappedWeights) {
  const GradeReport r = grade_fixture("curve", "curve_swapped_weights.lua");
  EXPECT_EQ(r.score, 3.666667);  // t = 0.5 cannot tell the weights apart: 1.1 passes
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"1.2", 0}, {"1.4", 0.666667}, {"1.5", 0}}));
  EXPECT_EQ(output_of(r, "1.2").rfind("FAILED: evaluate_step of 2 points at t = 0: [1]: expected (0, 0, 0), got (2, 1, 0), "
                                      "2.23606797749979 away (tolerance 1e-12)\n",
                                      0),
            0u)
      << output_of(r, "1.2");
}

TEST(PartSuites, APatchEvaluatedColumnsFirst) {
  const GradeReport r = grade_fixture("patch", "patch_columns_first.lua");
  EXPECT_EQ(r.score, 0.733333);
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"2.1", 0}, {"2.2", 0.333333}, {"2.3", 0.4}}));
  EXPECT_EQ(output_of(r, "2.1").rfind("FAILED: corner at (u, v) = (1, 0): expected (3, 0, 2.6999999999999997), got "
                                      "(0, 3, -0.30000000000000004)",
                                      0),
            0u)
      << output_of(r, "2.1");
}

TEST(PartSuites, NormalsAveragingUnitFaceNormals) {
  const GradeReport r = grade_fixture("normals", "normals_unit_average.lua");
  EXPECT_EQ(r.score, 3.0);  // on a cube every face around a vertex has the same area: 3.1 passes
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"3.2", 0}, {"3.4", 0}, {"3.5", 0}}));
  EXPECT_EQ(output_of(r, "3.2").rfind("FAILED: the centre of the fan v0: expected (-0.16197821539494556, ", 0), 0u)
      << output_of(r, "3.2");
}

TEST(PartSuites, OurOwnCorrectSplitAndUpsampleScoreFullMarks) {
  EXPECT_EQ(grade_fixture("split", "split_correct.lua").score, 10.0);
  EXPECT_EQ(grade_fixture("upsample", "upsample_correct.lua").score, 11.0);
}

TEST(PartSuites, ASplitVertexAtTheAverageOfTheCorners) {
  const GradeReport r = grade_fixture("split", "split_corner_average.lua");
  EXPECT_EQ(r.score, 7.0);  // on the square of 5.1 the corners' average is the midpoint
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"5.2", 2.333333}, {"5.4", 0.666667}, {"5.5", 0}}));
  EXPECT_EQ(output_of(r, "5.2").rfind("FAILED: split_edge(e0) of a cube: your vertex v8 at (-0.25, 0.25, -0.25) has no "
                                      "match in the reference",
                                      0),
            0u)
      << output_of(r, "5.2");
}

TEST(PartSuites, ASplitWithAWrongFaceOnANewHalfedge) {
  const GradeReport r = grade_fixture("split", "split_wrong_face.lua");
  EXPECT_EQ(r.score, 4.0);
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"5.1", 0}, {"5.2", 1.5}, {"5.4", 0.5}, {"5.5", 0}}));
  EXPECT_EQ(output_of(r, "5.1"),
            "FAILED: split_edge(e2) of a 1x1 grid: the mesh is not valid: h12: h12.face is f0, but h12 is in f2's "
            "next-cycle\n4 checks of 5 passed.\n");
}

TEST(PartSuites, UpsampleFlippingEdgesWithOnlyOneEndpointChecked) {
  const GradeReport r = grade_fixture("upsample", "upsample_flip_one_check.lua");
  EXPECT_EQ(r.score, 4.4);  // valid and the right counts: 40% of each test
  EXPECT_EQ(failed(r),
            (std::map<std::string, double>{{"6.1", 1.2}, {"6.2", 1.2}, {"6.3", 0.8}, {"6.4", 0.4}, {"6.5", 0.8}}));
  EXPECT_NE(output_of(r, "6.1").find("FAILED: tetrahedron: your face f2 (v0 v9 v7) is not in the reference"),
            std::string::npos)
      << output_of(r, "6.1");
}

TEST(PartSuites, UpsampleWritingPositionsToTheWrongVertices) {
  const GradeReport r = grade_fixture("upsample", "upsample_wrong_vertices.lua");
  EXPECT_EQ(r.score, 4.4);
  EXPECT_NE(output_of(r, "6.1").find("FAILED: tetrahedron: your vertex v4 at (1, 0, 0) has no match in the reference"),
            std::string::npos)
      << output_of(r, "6.1");
}

TEST(PartSuites, UpsampleSplittingTheEdgesItCreatesNeverEnds) {
  const GradeReport r = grade_fixture("upsample", "upsample_splits_new_edges.lua", 0.5);
  EXPECT_EQ(r.score, 0.0);
  for (const auto& t : r.tests) {
    EXPECT_EQ(t.end, RunEnd::Timeout) << t.number;
    EXPECT_NE(t.output.find("time limit"), std::string::npos) << t.output;
  }
}

TEST(PartSuites, UpsampleWithIntegerDivisionWeights) {
  const GradeReport r = grade_fixture("upsample", "upsample_integer_division.lua");
  EXPECT_EQ(r.score, 5.0);  // 6.4 passes: a grid's vertices are all on the boundary, where no weight is 3 // 16
  EXPECT_EQ(failed(r), (std::map<std::string, double>{{"6.1", 1.2}, {"6.2", 1.2}, {"6.3", 0.8}, {"6.5", 0.8}}));
  EXPECT_NE(output_of(r, "6.1").find("FAILED: tetrahedron: your vertex v0 at (1, 1, 1) has no match in the reference; the "
                                     "nearest is reference v0 at (0.25, 0.25, 0.25)"),
            std::string::npos)
      << output_of(r, "6.1");
}

}  // namespace
}  // namespace meshedit
