// The lessons for parts 1-3 (lessons/1_de_casteljau.lua, 2_bezier_patches.lua, 3_halfedge_walks.lua): each
// passes every step headless with its answers file and the correct solutions as the student's folder (each ends
// with your_turn), says the numbers the core computes, names each likely wrong answer, and marks the elements its
// walks really reach (checked against the core mesh's own pointers through HeadlessHost). Also lesson_file(), which the
// teapot lesson uses to find assets/teapot.bez.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/bezier.h"
#include "core/mesh_build.h"
#include "core/palette.h"
#include "core/primitives.h"
#include "io/bez_io.h"
#include "lesson/headless_host.h"
#include "lesson/lesson_headless.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Headless {
  HeadlessOutcome outcome;
  std::string text;
};

Headless run(const std::string& stem) {
  const auto source = testing::source_dir();
  std::ostringstream out;
  Headless result;
  result.outcome = run_lesson_headless(source / "lessons" / (stem + ".lua"),
                                       source / "tests" / "lesson" / "lessons" / (stem + "_answers.lua"), out,
                                       LessonRunner::default_limits(), source / "tests" / "exercise" / "solutions");
  result.text = out.str();
  return result;
}

std::filesystem::path lesson_path(const std::string& stem) {
  return testing::source_dir() / "lessons" / (stem + ".lua");
}

TEST(LessonsA, DeCasteljauPassesEveryStep) {
  const Headless r = run("1_de_casteljau");
  ASSERT_EQ(r.outcome.failure, "") << r.text;
  EXPECT_EQ(r.outcome.steps, 10u);
  EXPECT_EQ(r.outcome.passed, 10u);
  // The levels of (0,0) (1,2) (3,2) (4,0) at the view's t, live: at t = 0.5 first, then at 0.25 after the move.
  EXPECT_TRUE(contains(r.text, "- level 1: (0.5, 1), (2, 2), (3.5, 1)\n")) << r.text;
  EXPECT_TRUE(contains(r.text, "- level 2: (1.25, 1.5), (2.75, 1.5)\n")) << r.text;
  EXPECT_TRUE(contains(r.text, "- level 3: (2, 1.5)\n")) << r.text;
  EXPECT_TRUE(contains(r.text, "  > curve t = 0.25\n  [live] t = 0.25\n")) << r.text;
  // B(0.25) = 27/64 P0 + 27/64 P1 + 9/64 P2 + 1/64 P3 = (0.90625, 1.125).
  EXPECT_TRUE(contains(r.text, "- level 3: (0.90625, 1.125)")) << r.text;
  EXPECT_TRUE(contains(r.text, "Yes, C(0.25) = (0.90625, 1.125).")) << r.text;
  // Each wrong answer is told what it is (the answers file also checks the words).
  EXPECT_TRUE(contains(r.text,
                       "> answer 0.75, 1.5: wrong: (0.75, 1.5) is three quarters of the way: t and 1 - t "
                       "swapped."))
      << r.text;
  EXPECT_TRUE(contains(r.text, "> choose 4: wrong: 4 is level 1, after one step: off by one.")) << r.text;
  EXPECT_TRUE(contains(r.text, "> answer 2, 1: wrong: (2, 1) is the average of the four control points")) << r.text;
  // The split follows the view's t, and the first points of the levels are its left half.
  EXPECT_TRUE(contains(r.text,
                       "At t = 0.50: left (0, 0), (0.5, 1), (1.25, 1.5), (2, 1.5); right (2, 1.5), "
                       "(2.75, 1.5), (3.5, 1), (4, 0). The first points of the levels are the left half."))
      << r.text;
  EXPECT_TRUE(contains(r.text, "  [live] At t = 0.30: left (0, 0), (0.3, 0.6)")) << r.text;
  EXPECT_FALSE(contains(r.text, "are NOT")) << r.text;
  EXPECT_TRUE(contains(r.text, "[plot Bernstein weights: B0, B1, B2, B3 for x from 0 to 1, marker at 0.5]")) << r.text;
  // The derivative: C'(0) = 3 (P1 - P0); the tangent from the level-2 points; the hodograph at 0.25.
  EXPECT_TRUE(contains(r.text, "> answer 3, 6: right")) << r.text;
  EXPECT_TRUE(contains(r.text,
                       "the level-2 points are (1.25, 1.5) and (2.75, 1.5): C'(t) = 3 x their difference = "
                       "(4.5, 0)."))
      << r.text;
  EXPECT_TRUE(contains(r.text, "= (3, 6), (6, 0), (3, -6).")) << r.text;
  EXPECT_TRUE(contains(r.text, "Yes: C'(0.25) = (4.125, 3)")) << r.text;
  // The last step runs the student's evaluate_step, then points to the view's own check and to the grader.
  EXPECT_TRUE(contains(r.text, "> your turn curve.lua: right\n\n  Your evaluate_step gives the reference's level 1."))
      << r.text;
  EXPECT_TRUE(contains(r.text, "meshedit grade --suite tests/grading/suites/curve.lua")) << r.text;
}

// The few values lesson 1 writes out in its text are the curve's own: C(0.75), the control polygon's length and
// its quarter point, B1(0.5), where B1 peaks, and C'(0.5) from the level-2 points.
TEST(LessonsA, DeCasteljauWorkedValuesAreTheCurvesOwn) {
  const std::vector<glm::dvec2> points = {{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  const Headless r = run("1_de_casteljau");
  const glm::dvec2 three_quarters = evaluate_curve(points, 0.75);
  char text[96];
  std::snprintf(text, sizeof text, "(%.3f, %.3f) is C(0.75)", three_quarters.x, three_quarters.y);
  EXPECT_TRUE(contains(r.text, text)) << text;
  double length = 0.0;
  for (size_t i = 1; i < points.size(); ++i) length += glm::distance(points[i - 1], points[i]);
  const glm::dvec2 quarter = points[0] + (points[1] - points[0]) * (length / 4.0 / glm::distance(points[0], points[1]));
  ASSERT_LT(length / 4.0, glm::distance(points[0], points[1])) << "the quarter point is on the first side";
  std::snprintf(text, sizeof text, "(%.2f long: a quarter of it is still on its first side, near (%.2f, %.2f))", length,
                quarter.x, quarter.y);
  EXPECT_TRUE(contains(r.text, text)) << text << "\n" << r.text;
  const auto b1 = [](double t) { return 3.0 * t * (1.0 - t) * (1.0 - t); };
  EXPECT_DOUBLE_EQ(b1(0.5), 3.0 / 8.0);
  EXPECT_TRUE(contains(r.text, "Yes: 3/8.")) << r.text;
  for (double t : {1.0 / 3.0 - 1e-3, 1.0 / 3.0 + 1e-3}) EXPECT_LT(b1(t), b1(1.0 / 3.0));  // B1 peaks at 1/3
  EXPECT_TRUE(contains(r.text, "Yes, t = 1/3.")) << r.text;
  const auto levels = de_casteljau_levels(std::span<const glm::dvec2>(points), 0.5);
  const glm::dvec2 derivative = 3.0 * (levels[2][1] - levels[2][0]);
  std::snprintf(text, sizeof text, "(%g, %g): the top of the arch", derivative.x, derivative.y);
  EXPECT_TRUE(contains(r.text, text)) << text;
}

TEST(LessonsA, DeCasteljauShowsTheCurveItTypedAndItsHodograph) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("1_de_casteljau"))) << runner.error();
  ASSERT_TRUE(host.shown_curve().has_value());
  EXPECT_EQ(host.shown_curve()->control_points, (std::vector<glm::dvec2>{{0, 0}, {1, 2}, {3, 2}, {4, 0}}));
  // "The hodograph": the derivative's control points, 3 times the differences of the cubic's.
  runner.go_to(8);
  ASSERT_EQ(runner.error(), "");
  ASSERT_TRUE(host.shown_curve().has_value());
  EXPECT_EQ(host.shown_curve()->control_points, (std::vector<glm::dvec2>{{3, 6}, {6, 0}, {3, -6}}));
}

TEST(LessonsA, BezierPatchesPassesEveryStepAndShowsTheTeapot) {
  const Headless r = run("2_bezier_patches");
  ASSERT_EQ(r.outcome.failure, "") << r.text;
  EXPECT_EQ(r.outcome.steps, 7u);
  EXPECT_EQ(r.outcome.passed, 7u);
  // The hill at u = 0.25: rows 0 and 3 are flat (z 0), rows 1 and 2 reach z 1.125 at x 0.75; the column
  // (0, 1.125, 1.125, 0) at v = 0.5 is 0.84375.
  EXPECT_TRUE(contains(r.text,
                       "The four row points at u = 0.25 are (0.75, 0, 0), (0.75, 1, 1.125), (0.75, 2, 1.125), "
                       "(0.75, 3, 0)."))
      << r.text;
  EXPECT_TRUE(contains(r.text, "Yes: P(0.25, 0.5) = (0.75, 1.5, 0.84375).")) << r.text;
  // u and v swapped, and rows and columns swapped, are named as such.
  EXPECT_TRUE(contains(r.text,
                       "> answer 1.5, 0.75, 0.84375: wrong: (1.5, 0.75, 0.84375) is P(0.5, 0.25): u and v "
                       "swapped."))
      << r.text;
  EXPECT_TRUE(contains(r.text,
                       "> choose 10: wrong: 10 = 2 * 4 + 1 + 1 is row 2, column 1: rows and columns "
                       "swapped."))
      << r.text;
  EXPECT_TRUE(contains(r.text,
                       "> choose the first column's four points: wrong: The first column is the edge u = 0: "
                       "rows and columns swapped."))
      << r.text;
  EXPECT_TRUE(contains(r.text, "> your turn patch.lua: right\n\n  Your evaluate gives the reference's P(0.25, 0.5)."))
      << r.text;
  EXPECT_TRUE(contains(r.text, "meshedit grade --suite tests/grading/suites/patch.lua")) << r.text;
  EXPECT_TRUE(contains(r.text, "made of 32 Bézier patches")) << r.text;
  EXPECT_TRUE(contains(r.text, "only 512 control points")) << r.text;
  EXPECT_TRUE(contains(r.text, "The same point.")) << r.text;
  EXPECT_FALSE(contains(r.text, "They differ!")) << r.text;
}

// The normals lesson 2 states are the patch's own: dP/du x dP/dv of the core's evaluation (central differences),
// normalised, at the top of the hill and at the probe the answers move to.
TEST(LessonsA, BezierPatchesNormalIsTheCrossProductOfTheCoresTangents) {
  BezierPatch hill;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) hill.at(r, c) = glm::dvec3(c, r, (r == 1 || r == 2) && (c == 1 || c == 2) ? 2.0 : 0.0);
  }
  const auto normal = [&](double u, double v) {
    constexpr double h = 1e-6;
    const glm::dvec3 du = (evaluate_patch(hill, u + h, v) - evaluate_patch(hill, u - h, v)) / (2 * h);
    const glm::dvec3 dv = (evaluate_patch(hill, u, v + h) - evaluate_patch(hill, u, v - h)) / (2 * h);
    return glm::normalize(glm::cross(du, dv));
  };
  const Headless r = run("2_bezier_patches");
  ASSERT_EQ(r.outcome.failure, "") << r.text;
  char text[160];
  for (const auto& [u, v] : {std::pair{0.5, 0.5}, std::pair{0.2, 0.6}}) {
    const glm::dvec3 n = glm::round(normal(u, v) * 1000.0) / 1000.0 + 0.0;  // no "-0.000" from a difference's noise
    std::snprintf(text, sizeof text, "(%.3f, %.3f, %.3f)", n.x, n.y, n.z);
    EXPECT_TRUE(contains(r.text, text)) << text << "\n" << r.text;
  }
  std::snprintf(text, sizeof text, "  > patch u, v = 0.2, 0.6\n  [live] At the probe (u, v) = (0.20, 0.60):");
  EXPECT_TRUE(contains(r.text, text)) << r.text;
  const glm::dvec3 slope = normal(0.2, 0.6);
  EXPECT_LT(slope.x, 0.0);  // "Away from the top" is the right answer because the normal really leans that way
  EXPECT_TRUE(contains(r.text, "> choose Away from the top, toward u = 0: right")) << r.text;
}

TEST(LessonsA, BezierPatchesShowsTheTeapotFileItself) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("2_bezier_patches"))) << runner.error();
  ASSERT_EQ(host.shown_patches().size(), 1u);
  EXPECT_EQ(host.shown_patches()[0].points[5], glm::dvec3(1, 1, 2));  // row 1, column 1: raised
  EXPECT_EQ(host.shown_patches()[0].points[4], glm::dvec3(0, 1, 0));  // row 1, column 0: flat edge
  runner.go_to(4);                                                    // "The Utah teapot"
  ASSERT_EQ(runner.error(), "");
  const std::vector<BezierPatch> teapot = read_bez(testing::source_dir() / "assets" / "teapot.bez");
  ASSERT_EQ(teapot.size(), 32u);
  ASSERT_EQ(host.shown_patches().size(), teapot.size());
  for (size_t i = 0; i < teapot.size(); ++i) EXPECT_EQ(host.shown_patches()[i].points, teapot[i].points) << i;
}

TEST(LessonsA, HalfedgeWalksPassesEveryStep) {
  const Headless r = run("3_halfedge_walks");
  ASSERT_EQ(r.outcome.failure, "") << r.text;
  EXPECT_EQ(r.outcome.steps, 7u);
  EXPECT_EQ(r.outcome.passed, 7u);
  // Each question names the mistakes the answers file makes.
  EXPECT_TRUE(contains(r.text, "  > click h14: wrong: That is h.twin: the same edge the other way")) << r.text;
  EXPECT_TRUE(contains(r.text, "  > answer 4: wrong: 4 triangles touch v5, but the list does not say which 4"))
      << r.text;
  EXPECT_TRUE(contains(r.text, "  > click h8: wrong: That is h.next: it goes on around h's own face")) << r.text;
  EXPECT_TRUE(contains(r.text, "After 3 steps of next the walk is back at the start: f5 is a triangle.")) << r.text;
  EXPECT_TRUE(contains(r.text, "  > click f5\n")) << r.text;
  EXPECT_TRUE(contains(r.text, "You clicked f5.")) << r.text;
  EXPECT_TRUE(contains(r.text, "so v5 has degree 4 (the mesh agrees: v:degree() is 4)")) << r.text;
  // A 3x2 grid has 2 * (3 + 2) = 10 boundary edges.
  EXPECT_TRUE(contains(r.text, ": 10 steps around the grid and back to the start")) << r.text;
  // The boundary condition stays false for a vertex and an interior edge, and holds for e0.
  EXPECT_TRUE(contains(r.text, "  > selection v1 (not awaited")) << r.text;
  EXPECT_TRUE(contains(r.text, "  > selection e1 (not awaited")) << r.text;
  EXPECT_TRUE(contains(r.text, "  Yes: e0 is on the boundary.")) << r.text;
  // The fan: the plain average of the unit face normals points straight up; area weighting leans it towards the
  // big faces on the right.
  EXPECT_TRUE(contains(r.text, "It points straight up, (0.000, 0.000, 1.000).")) << r.text;
  EXPECT_TRUE(contains(r.text, "The orange arrow is the area-weighted normal, (0.346, 0.000, 0.938)")) << r.text;
  EXPECT_TRUE(contains(r.text, "  > key Q\n")) << r.text;
}

TEST(LessonsA, HalfedgeWalksMarkWhatThePointersReach) {
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson_path("3_halfedge_walks"))) << runner.error();
  // Step 1: face f5 (in sight on the front) and its halfedge h; the step asks for h.next before it walks.
  const HalfedgeId h0 = cube.halfedge(FaceId::face(5));
  const HalfedgeId h1 = cube.next(h0), h2 = cube.next(h1);
  EXPECT_EQ(host.labels(), (std::map<ElementRef, std::string>{{ElementRef(h0), "h"}}));
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Pick);
  ASSERT_TRUE(runner.deliver(LessonEvent::click(h1)));
  // Then the three halfedges of its next-loop, labelled in walking order.
  EXPECT_EQ(host.labels(), (std::map<ElementRef, std::string>{
                               {ElementRef(h0), "h"}, {ElementRef(h1), "h.next"}, {ElementRef(h2), "h.next.next"}}));
  EXPECT_EQ(colour_hex(host.highlights().at(ElementRef(h0))), colour_hex(kDarkSwatches.vermillion));
  EXPECT_EQ(colour_hex(host.highlights().at(ElementRef(FaceId::face(5)))), colour_hex(kDarkSwatches.yellow));
  EXPECT_EQ(host.highlights().size(), 4u);

  // Step 3: every halfedge leaving v5 (the front top right corner), numbered in the order h = h.twin.next
  // reaches them, once the student clicked h.twin.next.
  runner.go_to(2);
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Pick);
  const VertexId v0(5);
  ASSERT_TRUE(runner.deliver(LessonEvent::click(cube.next(cube.twin(cube.halfedge(v0))))));
  std::map<ElementRef, std::string> expected{{ElementRef(v0), "v5"}};
  HalfedgeId h = cube.halfedge(v0);
  for (int k = 1; k <= 4; ++k) {
    EXPECT_EQ(cube.vertex(h), v0);
    expected[ElementRef(h)] = std::to_string(k);
    h = cube.next(cube.twin(h));
  }
  EXPECT_EQ(h, cube.halfedge(v0));
  EXPECT_EQ(host.labels(), expected);
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::Key);
  EXPECT_EQ(runner.waiting_for().name, "T");

  // Step 4: the boundary loop of the 3x2 grid, every halfedge of it green.
  runner.go_to(3);
  const HalfedgeMesh grid = build_halfedge_mesh(make_grid(3, 2));
  std::set<ElementRef> loop;
  for (uint32_t i = 0; i < grid.num_halfedges(); ++i) {
    if (grid.is_boundary(HalfedgeId(i))) loop.insert(ElementRef(HalfedgeId(i)));
  }
  ASSERT_EQ(loop.size(), 10u);
  std::set<ElementRef> green;
  for (const auto& [element, colour] : host.highlights()) {
    EXPECT_EQ(colour_hex(colour), colour_hex(kDarkSwatches.bluish_green)) << format_id(element);
    green.insert(element);
  }
  EXPECT_EQ(green, loop);
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::Condition);
  host.set_selection(ElementRef(EdgeId(1)));  // interior: the wait goes on
  runner.update(0.0);
  EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Waiting);
  host.set_selection(ElementRef(EdgeId(0)));
  runner.update(0.0);
  EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Finished) << runner.error();
}

TEST(LessonsA, LessonFileResolvesNextToTheLesson) {
  const std::filesystem::path scratch = testing::scratch_dir();
  const auto dir = scratch / "lessons";
  std::filesystem::create_directories(dir);
  const auto path = dir / "paths.lua";
  std::ofstream(path) << "local top = lesson_file('../assets/x.bez')\n"
                         "step('A', function() say(top) say(lesson_file('y.bzc')) say(lesson_file('/abs/z')) end)\n";
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(path)) << runner.error();
  EXPECT_EQ(runner.said(), (std::vector<std::string>{(scratch / "assets" / "x.bez").lexically_normal().string(),
                                                     (dir / "y.bzc").lexically_normal().string(), "/abs/z"}));
}

}  // namespace
}  // namespace meshedit
