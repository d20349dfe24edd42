// The flip_edge grading suite (tests/grading/suites/flip.lua) over the flip fixtures in
// tests/grading/students/: the correct flip written with pointer writes scores 10/10; each buggy one loses
// exactly the points of the tests its mistake breaks, with the window's diagnosis naming the element that is wrong.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "grade/results_writers.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

using testing::grading_dir;
using testing::read_text;

GradeReport grade_flip(const std::string& fixture) {
  auto suite = Suite::load(grading_dir() / "suites" / "flip.lua");
  return grade(*suite, testing::submission_of({{"flip.lua", read_text(grading_dir() / "students" / fixture)}}),
               testing::quick_options());
}

// number -> score of the tests that failed.
std::map<std::string, double> failed(const GradeReport& report) {
  std::map<std::string, double> out;
  for (const auto& t : report.tests) {
    if (!t.passed) out[t.number] = t.score;
  }
  return out;
}

const TestResult& test_numbered(const GradeReport& report, const std::string& number) {
  for (const auto& t : report.tests) {
    if (t.number == number) return t;
  }
  throw std::runtime_error("no test " + number);
}

TEST(FlipSuite, TheCorrectFlipScoresFullMarks) {
  const GradeReport report = grade_flip("flip_correct.lua");
  EXPECT_EQ(report.score, 10.0);
  EXPECT_EQ(report.max_score, 10.0);
  EXPECT_EQ(summary_line(report), "5 passed, 0 failed");
  for (const auto& t : report.tests) EXPECT_EQ(t.output.rfind("Passed: ", 0), 0u) << t.number << ": " << t.output;
}

TEST(FlipSuite, ForgettingTheFacesHalfedgesLosesPointsNamingTheFace) {
  const GradeReport report = grade_flip("flip_forgets_faces.lua");
  EXPECT_EQ(report.score, 2.0);
  EXPECT_EQ(failed(report), (std::map<std::string, double>{{"4.1", 0.0}, {"4.2", 1.0}, {"4.4", 0.0}, {"4.5", 0.0}}));
  EXPECT_NE(test_numbered(report, "4.1")
                .output.find("FAILED: flip_edge(e2) of a 1x1 grid: after your flip_edge the mesh is not valid (1 "
                             "problem): f0.halfedge "
                             "is h0, but h0.face is f1\n"),
            std::string::npos)
      << test_numbered(report, "4.1").output;
  // One check per edge of the cube: the six edges whose faces keep a halfedge of their own pass.
  EXPECT_NE(test_numbered(report, "4.2").output.find("6 checks of 18 passed."), std::string::npos);
}

TEST(FlipSuite, ForgettingTheVerticesHalfedgesLosesPointsNamingTheVertex) {
  const GradeReport report = grade_flip("flip_forgets_vertices.lua");
  EXPECT_EQ(report.score, 2.666667);
  EXPECT_EQ(failed(report),
            (std::map<std::string, double>{{"4.1", 0.0}, {"4.2", 1.666667}, {"4.4", 0.0}, {"4.5", 0.0}}));
  // The 1x1 grid's vertices keep halfedges of their own; in the middle of the big grid a vertex points at h0.
  EXPECT_NE(test_numbered(report, "4.1")
                .output.find("in the middle of an 80x70 grid (11200 triangles): after your flip_edge the mesh is not "
                             "valid (1 problem): v2957.halfedge is h17042, but h17042 leaves v2956"),
            std::string::npos)
      << test_numbered(report, "4.1").output;
  EXPECT_NE(
      test_numbered(report, "4.2")
          .output.find(
              "FAILED: flip_edge(e0) of a cube: after your flip_edge the mesh is not valid (1 problem): v0.halfedge is "
              "h0, but h0 leaves v6"),
      std::string::npos)
      << test_numbered(report, "4.2").output;
}

TEST(FlipSuite, FlippingABoundaryEdgeLosesOnlyThatTest) {
  const GradeReport report = grade_flip("flip_boundary.lua");
  EXPECT_EQ(report.score, 9.0);
  EXPECT_EQ(failed(report), (std::map<std::string, double>{{"4.3", 0.0}}));
  EXPECT_NE(test_numbered(report, "4.3")
                .output.find(
                    "FAILED: flip_edge(e0) on the boundary of a 2x2 grid: the reference does not flip e0 (e0 is on the "
                    "boundary (b0); only interior edges can be flipped), but your flip_edge changed the mesh: "),
            std::string::npos)
      << test_numbered(report, "4.3").output;
  EXPECT_NE(test_numbered(report, "4.3").output.find("yours returned e0"), std::string::npos);
}

TEST(FlipSuite, ANextPointerLeftAsItWasBreaksTheFaceCycleAndIsNamed) {
  const GradeReport report = grade_flip("flip_breaks_face_cycle.lua");
  EXPECT_EQ(report.score, 1.0);  // only the boundary refusals (4.3) pass
  EXPECT_EQ(failed(report), (std::map<std::string, double>{{"4.1", 0.0}, {"4.2", 0.0}, {"4.4", 0.0}, {"4.5", 0.0}}));
  EXPECT_NE(
      test_numbered(report, "4.1")
          .output.find(
              "FAILED: flip_edge(e2) of a 1x1 grid: h5.next is still h3 after your flip_edge, as before the call; the "
              "reference changes it: that pointer breaks the face cycle; after your flip_edge the mesh is not valid"),
      std::string::npos)
      << test_numbered(report, "4.1").output;
}

}  // namespace
}  // namespace meshedit
