// What File > Check my work reads: the grader's check report (grade/report_json.h) round trip and refusals, a failed
// mesh check's input as a case (grade/failing_case.h) that builds back to the same element, and `meshedit grade
// --report FILE --progress` end to end through the built binary.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "grade/failing_case.h"
#include "grade/report_json.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::grading_dir;
using testing::Outcome;
using testing::read_text;
using testing::run_meshedit;
using testing::write_text;

GradeReport sample() {
  GradeReport report;
  report.suite_name = "flip";
  report.score = 2.5;
  report.max_score = 4;
  report.extra_points = 1;
  report.execution_time = 1.25;
  report.output = "Suite flip: 2 tests.\nMissing: split.lua (the tests that need it fail).\n";
  report.not_shown = {{"after_due_date", 2, 3.0}};
  TestResult passed;
  passed.number = "4.1";
  passed.name = "flip: interior edge";
  passed.visibility = "visible";
  passed.score = passed.max_score = 2;
  passed.passed = true;
  passed.output = "Passed: 3 checks.\n";
  TestResult failed = passed;
  failed.number = "4.2";
  failed.tags = {"flip"};
  failed.score = 0.5;
  failed.passed = false;
  failed.end = RunEnd::Timeout;
  failed.failure = "h3.next is h4";
  failed.output = "FAILED: h3.next is h4 \xff\n";
  failed.output_markdown = "**FAILED**";
  failed.failing_case = FailingCase{"flip_edge", "e2 of a mesh with 2 faces", "input records", "e2", "mine records"};
  report.tests = {passed, failed};
  return report;
}

TEST(CheckReport, TravelsAsJsonWithEveryField) {
  const GradeReport back = decode_grade_report(encode_grade_report(sample()));
  EXPECT_EQ(back.suite_name, "flip");
  EXPECT_EQ(back.score, 2.5);
  EXPECT_EQ(back.max_score, 4);
  EXPECT_EQ(back.extra_points, 1);
  EXPECT_EQ(back.output, sample().output);
  ASSERT_EQ(back.not_shown.size(), 1u);
  EXPECT_EQ(back.not_shown[0].visibility, "after_due_date");
  EXPECT_EQ(back.not_shown[0].tests, 2u);
  EXPECT_EQ(back.not_shown[0].points, 3.0);
  ASSERT_EQ(back.tests.size(), 2u);
  EXPECT_TRUE(back.tests[0].passed);
  EXPECT_FALSE(back.tests[0].failing_case);
  const TestResult& t = back.tests[1];
  EXPECT_EQ(t.number, "4.2");
  EXPECT_EQ(t.tags, std::vector<std::string>{"flip"});
  EXPECT_EQ(t.end, RunEnd::Timeout);
  EXPECT_EQ(t.output, "FAILED: h3.next is h4 \xEF\xBF\xBD\n");  // the invalid byte replaced
  EXPECT_EQ(t.output_markdown, "**FAILED**");
  ASSERT_TRUE(t.failing_case);
  EXPECT_EQ(t.failing_case->exercise, "flip_edge");
  EXPECT_EQ(t.failing_case->mesh, "input records");
  EXPECT_EQ(t.failing_case->element, "e2");
  EXPECT_EQ(t.failing_case->mine, "mine records");
}

TEST(CheckReport, AnotherTextIsRefusedWithASentence) {
  const auto refusal = [](const std::string& text) {
    try {
      decode_grade_report(text);
    } catch (const GradeError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal("{\"score\": 3, \"tests\": []}").find("not a MeshEdit check report"), std::string::npos);
  EXPECT_NE(refusal("not json").find("malformed check report"), std::string::npos);
  std::string newer = encode_grade_report(sample());
  newer.replace(newer.find("\"version\":1"), 11, "\"version\":7");
  EXPECT_EQ(refusal(newer), "a check report of version 7; this MeshEdit reads version 1");
  std::string cut = encode_grade_report(sample());
  EXPECT_NE(refusal(cut.substr(0, cut.size() / 2)).find("malformed check report"), std::string::npos);
}

// A mesh with dead slots and ids no builder gives (a split and flips made it).
std::shared_ptr<HalfedgeMesh> edited_grid() {
  auto mesh = std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_grid(3, 3)));
  std::vector<EdgeId> interior;
  for (const EdgeId e : mesh->edges()) {
    if (!mesh->is_boundary(e)) interior.push_back(e);
  }
  EXPECT_GE(interior.size(), 6u);
  EXPECT_TRUE(split(*mesh, interior[0]).ok());
  EXPECT_TRUE(flip(*mesh, interior[3]).ok());
  EXPECT_TRUE(flip(*mesh, interior[5]).ok());
  mesh->delete_element(FaceId::face(2));  // a dead slot, pointed to still: what a student's code leaves
  return mesh;
}

// Every record of both meshes: capacities, alive flags, pointers, positions.
void expect_same_records(const HalfedgeMesh& a, const HalfedgeMesh& b) {
  ASSERT_EQ(a.vertex_capacity(), b.vertex_capacity());
  ASSERT_EQ(a.halfedge_capacity(), b.halfedge_capacity());
  ASSERT_EQ(a.edge_capacity(), b.edge_capacity());
  ASSERT_EQ(a.face_capacity(), b.face_capacity());
  ASSERT_EQ(a.boundary_capacity(), b.boundary_capacity());
  for (uint32_t i = 0; i < a.vertex_capacity(); ++i) {
    EXPECT_EQ(a.alive(VertexId(i)), b.alive(VertexId(i)));
    EXPECT_EQ(a.position(VertexId(i)), b.position(VertexId(i)));
    EXPECT_EQ(a.halfedge(VertexId(i)), b.halfedge(VertexId(i)));
  }
  for (uint32_t i = 0; i < a.halfedge_capacity(); ++i) {
    EXPECT_EQ(a.alive(HalfedgeId(i)), b.alive(HalfedgeId(i)));
    EXPECT_EQ(a.record(HalfedgeId(i)), b.record(HalfedgeId(i))) << "h" << i;
  }
  for (uint32_t i = 0; i < a.edge_capacity(); ++i) EXPECT_EQ(a.halfedge(EdgeId(i)), b.halfedge(EdgeId(i)));
  for (uint32_t i = 0; i < a.face_capacity(); ++i) {
    EXPECT_EQ(a.alive(FaceId::face(i)), b.alive(FaceId::face(i)));
    EXPECT_EQ(a.halfedge(FaceId::face(i)), b.halfedge(FaceId::face(i)));
  }
  for (uint32_t i = 0; i < a.boundary_capacity(); ++i) {
    EXPECT_EQ(a.halfedge(FaceId::boundary(i)), b.halfedge(FaceId::boundary(i)));
  }
}

TEST(FailingCase, KeepsEveryRecordAndId) {
  const std::shared_ptr<HalfedgeMesh> mesh = edited_grid();
  HalfedgeMesh mine = *mesh;
  mine.set_next(HalfedgeId(0), HalfedgeId(7));  // broken as a student's code breaks it
  const EdgeId e = *mesh->edges().begin();
  const std::optional<FailingCase> c = failing_case_of(Exercise::FlipEdge, ExerciseInput::edge(mesh, e), &mine);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->exercise, "flip_edge");
  EXPECT_EQ(c->element, format_id(e));
  const HalfedgeMesh back = case_mesh(*c);
  expect_same_records(back, *mesh);
  EXPECT_EQ(case_element(back, *c), ElementRef(e));
  const std::optional<HalfedgeMesh> yours = case_mine(*c);
  ASSERT_TRUE(yours);
  expect_same_records(*yours, mine);

  const std::optional<FailingCase> whole = failing_case_of(Exercise::Upsample, ExerciseInput::whole_mesh(mesh));
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->element, "");
  EXPECT_FALSE(case_element(case_mesh(*whole), *whole).valid());
  EXPECT_FALSE(case_mine(*whole));
  // Points have no mesh to open.
  EXPECT_FALSE(failing_case_of(Exercise::CurveStep, ExerciseInput::curve_step({{0, 0, 0}, {1, 0, 0}}, 0.5)));
}

// The report the window reads says what the readable report says, test by test, and carries the failing input.
TEST(CliGradeReport, WritesTheWholeVerdictAndItsProgress) {
  const fs::path dir = testing::scratch_dir();
  write_text(dir / "bob" / "flip.lua", read_text(grading_dir() / "students" / "flip_forgets_faces.lua"));
  const Outcome o = run_meshedit(dir, "grade --suite '" + (grading_dir() / "suites" / "flip.lua").string() +
                                          "' --submission bob --visible-only --report check.json --progress");
  ASSERT_EQ(o.status, 0) << o.err;
  const GradeReport report = decode_grade_report(read_text(dir / "check.json"));
  ASSERT_EQ(report.tests.size(), 3u);
  std::string progress;
  for (size_t i = 0; i < 3; ++i) {
    const std::string test = "meshedit grade: test " + std::to_string(i + 1) + " of 3 ";
    progress += test + "running: " + report.tests[i].name + "\n" + test + "done: " + report.tests[i].name + "\n";
  }
  EXPECT_EQ(o.err.substr(0, progress.size()), progress);
  for (const TestResult& t : report.tests) {
    // Word for word what `meshedit grade` printed for the test.
    EXPECT_NE(o.out.find(t.number + " " + t.name), std::string::npos) << t.name;
    if (t.passed) continue;
    std::string indented;
    for (size_t at = 0; at < t.output.size();) {
      const size_t end = t.output.find('\n', at);
      indented += "    " + t.output.substr(at, end - at + 1);
      at = end + 1;
    }
    EXPECT_NE(o.out.find(indented), std::string::npos) << t.output;
  }
  ASSERT_FALSE(report.tests[0].passed);
  ASSERT_TRUE(report.tests[0].failing_case);
  const FailingCase& c = *report.tests[0].failing_case;
  EXPECT_EQ(c.exercise, "flip_edge");
  EXPECT_EQ(c.element, "e2");  // the id the grader's words name
  const HalfedgeMesh input = case_mesh(c);
  EXPECT_EQ(case_element(input, c), ElementRef(EdgeId(2)));
  EXPECT_EQ(report.not_shown.size(), 2u);
  EXPECT_TRUE(case_mine(c));  // the student's mesh, to draw beside the reference's

  // The failed tests' pictures: beside results.json, and in its Markdown (where EGL can draw them).
  const nlohmann::json results = nlohmann::json::parse(read_text(dir / "results.json"));
  if (o.err.find("no pictures") != std::string::npos) GTEST_SKIP() << o.err;
  const std::string png = read_text(dir / "pictures" / "test-4.1.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const std::string markdown = results["tests"][0]["output"];
  EXPECT_NE(markdown.find("](data:image/png;base64,iVBORw0KGgo"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("*Left to right: the input (e2 of a mesh"), std::string::npos) << markdown;
  EXPECT_EQ(results["tests"][2]["output"].get<std::string>().find("data:image"), std::string::npos);  // passed
}

}  // namespace
}  // namespace meshedit
