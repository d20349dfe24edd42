// Tests of the curve view's state: the pure functions behind E, C, scroll, add/remove, hit testing, the view
// transform and one frame of mouse input, with exact numbers.
#include "document/curve_view_state.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace meshedit {
namespace {

using glm::dvec2;

// The course's curve1.bzc numbers (a cubic); the file itself is not read here (the test needs no file).
BezierCurve course_cubic() { return BezierCurve{{{0.2, 0.35}, {0.3, 0.6}, {0.8, 0.75}, {0.9, 0.45}}}; }

// A unit square's corners, in order: easy nearest-segment arithmetic for add_point.
BezierCurve square_curve() { return BezierCurve{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}}; }

void expect_points_eq(const std::vector<dvec2>& actual, const std::vector<dvec2>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual[i].x, expected[i].x) << "point " << i;
    EXPECT_EQ(actual[i].y, expected[i].y) << "point " << i;
  }
}

// ---- levels, E and C ---------------------------------------------------------------------------------

TEST(CurveEditor, StepLevelCyclesThroughEveryLevelOfACubic) {
  CurveEditorState state = make_curve_editor(course_cubic());
  EXPECT_EQ(state.levels_shown, 0);
  EXPECT_EQ(state.t, 0.5);
  ASSERT_EQ(shown_levels(state).size(), 1u);
  expect_points_eq(shown_levels(state)[0], course_cubic().control_points);

  step_level(state);
  EXPECT_EQ(state.levels_shown, 1);
  auto levels = shown_levels(state);
  ASSERT_EQ(levels.size(), 2u);
  ASSERT_EQ(levels[1].size(), 3u);
  EXPECT_DOUBLE_EQ(levels[1][0].x, 0.25);
  EXPECT_DOUBLE_EQ(levels[1][0].y, 0.475);
  EXPECT_DOUBLE_EQ(levels[1][1].x, 0.55);
  EXPECT_DOUBLE_EQ(levels[1][1].y, 0.675);
  EXPECT_DOUBLE_EQ(levels[1][2].x, 0.85);
  EXPECT_DOUBLE_EQ(levels[1][2].y, 0.6);

  step_level(state);
  EXPECT_EQ(state.levels_shown, 2);
  EXPECT_EQ(shown_levels(state).size(), 3u);
  EXPECT_EQ(shown_levels(state)[2].size(), 2u);

  step_level(state);
  EXPECT_EQ(state.levels_shown, 3);
  levels = shown_levels(state);
  ASSERT_EQ(levels.size(), 4u);
  ASSERT_EQ(levels[3].size(), 1u);
  const dvec2 c = evaluate_curve(state.curve, 0.5);
  EXPECT_EQ(levels[3][0].x, c.x);
  EXPECT_EQ(levels[3][0].y, c.y);
  // By hand: level 2 = (0.4, 0.575), (0.7, 0.6375); C(0.5) = (0.55, 0.60625).
  EXPECT_DOUBLE_EQ(c.x, 0.55);
  EXPECT_DOUBLE_EQ(c.y, 0.60625);

  step_level(state);  // the fourth press returns to the control polygon, as in the course viewer
  EXPECT_EQ(state.levels_shown, 0);
  EXPECT_EQ(shown_levels(state).size(), 1u);
}

TEST(CurveEditor, ShownLevelsAreTheCoreLevels) {
  CurveEditorState state = make_curve_editor(course_cubic());
  set_t(state, 0.3);
  state.levels_shown = 3;
  const auto core = de_casteljau_levels(std::span<const dvec2>(state.curve.control_points), 0.3);
  const auto shown = shown_levels(state);
  ASSERT_EQ(shown.size(), core.size());
  for (size_t k = 0; k < core.size(); ++k) expect_points_eq(shown[k], core[k]);
  EXPECT_EQ(all_levels(state).size(), 4u);
}

TEST(CurveEditor, StepLevelRepairsAnOutOfRangeLevelAndHandlesTinyCurves) {
  CurveEditorState state = make_curve_editor(course_cubic());
  state.levels_shown = 17;  // written directly, out of range
  EXPECT_EQ(shown_levels(state).size(), 4u);
  step_level(state);  // from the clamped 3
  EXPECT_EQ(state.levels_shown, 0);

  CurveEditorState one = make_curve_editor(BezierCurve{{{0.5, 0.5}}});
  step_level(one);
  EXPECT_EQ(one.levels_shown, 0);
  ASSERT_EQ(shown_levels(one).size(), 1u);
}

TEST(CurveEditor, EmptyCurveBecomesTheDefaultCubic) {
  const CurveEditorState state = make_curve_editor(BezierCurve{});
  expect_points_eq(state.curve.control_points, default_curve().control_points);
  EXPECT_EQ(state.curve.control_points.size(), 4u);
}

TEST(CurveEditor, ToggleCurveAndSplit) {
  CurveEditorState state = make_curve_editor(course_cubic());
  EXPECT_FALSE(state.show_curve);
  toggle_curve(state);
  EXPECT_TRUE(state.show_curve);
  toggle_curve(state);
  EXPECT_FALSE(state.show_curve);
  EXPECT_FALSE(state.show_split);
  toggle_split(state);
  EXPECT_TRUE(state.show_split);
}

// ---- t ---------------------------------------------------------------------------------------------

TEST(CurveEditor, SetTClampsAndIgnoresNaN) {
  CurveEditorState state = make_curve_editor(course_cubic());
  set_t(state, 0.25);
  EXPECT_EQ(state.t, 0.25);
  set_t(state, 1.5);
  EXPECT_EQ(state.t, 1.0);
  set_t(state, -2.0);
  EXPECT_EQ(state.t, 0.0);
  set_t(state, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(state.t, 0.0);
  set_t(state, std::numeric_limits<double>::infinity());
  EXPECT_EQ(state.t, 1.0);
}

TEST(CurveEditor, ScrollMovesTByOneHundredthPerNotchClamped) {
  CurveEditorState state = make_curve_editor(course_cubic());
  scroll_t(state, 3.0);
  EXPECT_DOUBLE_EQ(state.t, 0.53);
  scroll_t(state, -1.0);
  EXPECT_DOUBLE_EQ(state.t, 0.52);
  set_t(state, 0.99);
  scroll_t(state, 5.0);
  EXPECT_EQ(state.t, 1.0);
  set_t(state, 0.02);
  scroll_t(state, -4.0);
  EXPECT_EQ(state.t, 0.0);
}

// ---- split -----------------------------------------------------------------------------------------

TEST(CurveEditor, SplitHalvesAreSplitCurve) {
  CurveEditorState state = make_curve_editor(course_cubic());
  set_t(state, 0.3);
  const CurveSplit<dvec2> halves = split_halves(state);
  const CurveSplit<dvec2> core = split_curve(std::span<const dvec2>(state.curve.control_points), 0.3);
  expect_points_eq(halves.left, core.left);
  expect_points_eq(halves.right, core.right);
  // The halves meet at C(t) and keep the curve's ends.
  const dvec2 c = evaluate_curve(state.curve, 0.3);
  EXPECT_EQ(halves.left.back(), c);
  EXPECT_EQ(halves.right.front(), c);
  EXPECT_EQ(halves.left.front(), state.curve.control_points.front());
  EXPECT_EQ(halves.right.back(), state.curve.control_points.back());
}

TEST(CurveEditor, SampleCurveHasEndpointsAndCount) {
  const BezierCurve curve = course_cubic();
  const auto samples = sample_curve(curve.control_points, 4);
  ASSERT_EQ(samples.size(), 5u);
  EXPECT_EQ(samples.front(), curve.control_points.front());
  EXPECT_EQ(samples.back(), curve.control_points.back());
  EXPECT_EQ(samples[2], evaluate_curve(curve, 0.5));
  EXPECT_EQ(sample_curve(curve.control_points).size(), static_cast<size_t>(kCurveSamples) + 1);
  EXPECT_TRUE(sample_curve({}, 10).empty());
}

// ---- add / remove / drag ---------------------------------------------------------------------------

TEST(CurveEditor, AddPointGoesNextToTheNearestSegment) {
  CurveEditorState state = make_curve_editor(square_curve());
  // Below the bottom segment (p0, p1): inserted between them.
  EXPECT_EQ(add_point(state, {0.5, -0.1}), 1);
  expect_points_eq(state.curve.control_points, {{0, 0}, {0.5, -0.1}, {1, 0}, {1, 1}, {0, 1}});

  // Right of the right segment (now p2, p3): between them, at index 3.
  EXPECT_EQ(add_point(state, {1.2, 0.5}), 3);
  expect_points_eq(state.curve.control_points, {{0, 0}, {0.5, -0.1}, {1, 0}, {1.2, 0.5}, {1, 1}, {0, 1}});
}

TEST(CurveEditor, AddPointBeyondAnEndExtendsTheCurve) {
  CurveEditorState state = make_curve_editor(square_curve());
  EXPECT_EQ(add_point(state, {-0.5, -0.2}), 0);  // nearest polygon point is p0 itself: prepend
  EXPECT_EQ(state.curve.control_points.front(), dvec2(-0.5, -0.2));
  EXPECT_EQ(add_point(state, {-0.4, 1.3}), 5);  // nearest is the last point: append
  EXPECT_EQ(state.curve.control_points.back(), dvec2(-0.4, 1.3));
  EXPECT_EQ(state.curve.control_points.size(), 6u);
}

TEST(CurveEditor, AddPointKeepsHoveredAndDraggedOnTheirPoints) {
  CurveEditorState state = make_curve_editor(square_curve());
  state.hovered = 1;
  state.dragged = 3;
  state.levels_shown = 2;
  EXPECT_EQ(add_point(state, {1.2, 0.5}), 2);
  EXPECT_EQ(state.hovered, 1);  // before the insertion: unchanged
  EXPECT_EQ(state.dragged, 4);  // after it: shifted
  EXPECT_EQ(state.curve.control_points[4], dvec2(0.0, 1.0));
  EXPECT_EQ(state.levels_shown, 2);
}

TEST(CurveEditor, AddPointOnShortCurvesAppends) {
  CurveEditorState state = make_curve_editor(BezierCurve{{{0.5, 0.5}}});
  EXPECT_EQ(add_point(state, {0.1, 0.1}), 1);
  EXPECT_EQ(state.curve.control_points[1], dvec2(0.1, 0.1));
  EXPECT_EQ(add_point(state, {std::nan(""), 0.0}), -1);
  EXPECT_EQ(add_point(state, {0.0, std::numeric_limits<double>::infinity()}), -1);
  EXPECT_EQ(state.curve.control_points.size(), 2u);
}

TEST(CurveEditor, AddPointDefaultSplitsTheLastSegment) {
  CurveEditorState state = make_curve_editor(square_curve());
  EXPECT_EQ(add_point_default(state), 3);
  EXPECT_EQ(state.curve.control_points[3], dvec2(0.5, 1.0));
  EXPECT_EQ(state.curve.control_points[4], dvec2(0.0, 1.0));
}

TEST(CurveEditor, RemovePointFixesIndicesAndLevels) {
  CurveEditorState state = make_curve_editor(BezierCurve{{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}});
  state.levels_shown = 4;
  state.hovered = 1;
  state.dragged = 3;
  EXPECT_TRUE(remove_point(state, 1));
  expect_points_eq(state.curve.control_points, {{0, 0}, {2, 0}, {3, 0}, {4, 0}});
  EXPECT_EQ(state.hovered, -1);  // its point is gone
  EXPECT_EQ(state.dragged, 2);   // still on (3, 0)
  EXPECT_EQ(state.levels_shown, 3);

  EXPECT_FALSE(remove_point(state, 4));
  EXPECT_FALSE(remove_point(state, -1));
  EXPECT_TRUE(remove_point(state, 3));
  EXPECT_EQ(state.dragged, 2);
  EXPECT_TRUE(remove_point(state, 0));
  EXPECT_EQ(state.dragged, 1);
  expect_points_eq(state.curve.control_points, {{2, 0}, {3, 0}});
  EXPECT_EQ(state.levels_shown, 1);
  EXPECT_FALSE(remove_point(state, 0));  // never below two points
  EXPECT_EQ(state.curve.control_points.size(), 2u);
}

TEST(CurveEditor, DragPointMovesOnlyThatPoint) {
  CurveEditorState state = make_curve_editor(course_cubic());
  EXPECT_TRUE(drag_point(state, 2, {0.7, 0.1}));
  expect_points_eq(state.curve.control_points, {{0.2, 0.35}, {0.3, 0.6}, {0.7, 0.1}, {0.9, 0.45}});
  EXPECT_FALSE(drag_point(state, 4, {0.0, 0.0}));
  EXPECT_FALSE(drag_point(state, 0, {std::nan(""), 0.0}));
  EXPECT_EQ(state.curve.control_points[0], dvec2(0.2, 0.35));
}

// ---- view and hit testing --------------------------------------------------------------------------

TEST(CurveEditor, ViewMapsYUpIntoTheCanvasCentred) {
  const CurveView view = view_for(CurveRegion{{0.0, 0.0}, {1.0, 1.0}}, {100.0, 50.0}, {400.0, 300.0});
  EXPECT_EQ(view.scale, 300.0);  // the height limits
  EXPECT_EQ(view.centre, dvec2(0.5, 0.5));
  EXPECT_EQ(curve_to_screen(view, {0.0, 0.0}), dvec2(150.0, 350.0));  // bottom-left of the square
  EXPECT_EQ(curve_to_screen(view, {1.0, 1.0}), dvec2(450.0, 50.0));   // top-right
  EXPECT_EQ(curve_to_screen(view, {0.5, 0.5}), dvec2(300.0, 200.0));  // canvas centre
  EXPECT_EQ(screen_to_curve(view, {300.0, 50.0}), dvec2(0.5, 1.0));
}

TEST(CurveEditor, ScreenAndCurveCoordinatesRoundTrip) {
  const CurveView view = view_for(CurveRegion{{-0.3, 0.1}, {2.7, 1.6}}, {13.0, 77.0}, {640.0, 480.0});
  const dvec2 points[] = {{0.0, 0.0}, {0.123, 0.456}, {-3.5, 9.25}, {2.7, 1.6}};
  for (const dvec2& p : points) {
    const dvec2 back = screen_to_curve(view, curve_to_screen(view, p));
    EXPECT_NEAR(back.x, p.x, 1e-12);
    EXPECT_NEAR(back.y, p.y, 1e-12);
  }
  const dvec2 s{321.5, 99.25};
  const dvec2 s_back = curve_to_screen(view, screen_to_curve(view, s));
  EXPECT_NEAR(s_back.x, s.x, 1e-9);
  EXPECT_NEAR(s_back.y, s.y, 1e-9);
}

TEST(CurveEditor, FitRegionPadsTheControlPoints) {
  const BezierCurve curve = course_cubic();
  const CurveRegion region = fit_region(curve.control_points, 0.1);
  // Box [0.2, 0.9] x [0.35, 0.75]; the larger side 0.7 gives a 0.07 margin.
  EXPECT_DOUBLE_EQ(region.min.x, 0.13);
  EXPECT_DOUBLE_EQ(region.min.y, 0.28);
  EXPECT_DOUBLE_EQ(region.max.x, 0.97);
  EXPECT_DOUBLE_EQ(region.max.y, 0.82);

  const dvec2 same[] = {{2.0, 3.0}, {2.0, 3.0}};
  const CurveRegion unit = fit_region(same);
  EXPECT_EQ(unit.min, dvec2(1.5, 2.5));
  EXPECT_EQ(unit.max, dvec2(2.5, 3.5));
  const CurveRegion none = fit_region({});
  EXPECT_EQ(none.min, dvec2(0.0, 0.0));
  EXPECT_EQ(none.max, dvec2(1.0, 1.0));
}

TEST(CurveEditor, HitTestFindsTheNearestPointWithinTheRadius) {
  CurveEditorState state = make_curve_editor(square_curve());
  state.view = view_for(CurveRegion{{0.0, 0.0}, {1.0, 1.0}}, {100.0, 50.0}, {400.0, 300.0});
  // p0 (0,0) is at (150, 350), p1 (1,0) at (450, 350), p3 (0,1) at (150, 50).
  EXPECT_EQ(hit_test(state, {150.0, 350.0}), 0);
  EXPECT_EQ(hit_test(state, {156.0, 342.0}), 0);   // 10 px away: on the radius
  EXPECT_EQ(hit_test(state, {157.0, 342.0}), -1);  // just outside
  EXPECT_EQ(hit_test(state, {445.0, 352.0}), 1);
  EXPECT_EQ(hit_test(state, {150.0, 55.0}), 3);
  EXPECT_EQ(hit_test(state, {300.0, 200.0}), -1);
  EXPECT_EQ(hit_test(state, {165.0, 350.0}, 20.0), 0);

  add_point(state, {0.0, 0.0});  // a second point exactly on p0 (prepended): the later one wins
  EXPECT_EQ(state.curve.control_points[0], dvec2(0.0, 0.0));
  EXPECT_EQ(hit_test(state, {150.0, 350.0}), 1);
}

// ---- mouse, without ImGui --------------------------------------------------------------------------

TEST(CurveEditor, CanvasInputDragsKeepingTheGrabOffset) {
  CurveEditorState state = make_curve_editor(square_curve());
  state.view = view_for(CurveRegion{{0.0, 0.0}, {1.0, 1.0}}, {100.0, 50.0}, {400.0, 300.0});
  CanvasInput input;
  input.hovered = true;
  input.mouse = {453.0, 347.0};  // 3 px right of and 3 px above p1 (450, 350)
  handle_canvas_input(state, input);
  EXPECT_EQ(state.hovered, 1);
  EXPECT_EQ(state.dragged, -1);

  input.left_pressed = true;
  input.left_down = true;
  handle_canvas_input(state, input);
  EXPECT_EQ(state.dragged, 1);
  EXPECT_EQ(state.curve.control_points[1], dvec2(1.0, 0.0));  // grabbing does not move it

  input.left_pressed = false;
  input.mouse = {453.0 - 60.0, 347.0 - 30.0};  // 0.2 left and 0.1 up in curve units
  handle_canvas_input(state, input);
  EXPECT_NEAR(state.curve.control_points[1].x, 0.8, 1e-12);
  EXPECT_NEAR(state.curve.control_points[1].y, 0.1, 1e-12);

  input.hovered = false;  // off the canvas: the drag goes on while the button is held
  input.mouse = {453.0 + 300.0, 347.0};
  handle_canvas_input(state, input);
  EXPECT_NEAR(state.curve.control_points[1].x, 2.0, 1e-12);
  EXPECT_NEAR(state.curve.control_points[1].y, 0.0, 1e-12);

  input.left_down = false;
  handle_canvas_input(state, input);
  EXPECT_EQ(state.dragged, -1);
  EXPECT_EQ(state.hovered, -1);
  expect_points_eq({state.curve.control_points[0], state.curve.control_points[2], state.curve.control_points[3]},
                   {{0, 0}, {1, 1}, {0, 1}});
}

TEST(CurveEditor, CanvasInputAddsRemovesAndScrolls) {
  CurveEditorState state = make_curve_editor(square_curve());
  state.view = view_for(CurveRegion{{0.0, 0.0}, {1.0, 1.0}}, {100.0, 50.0}, {400.0, 300.0});
  CanvasInput input;
  input.hovered = true;
  input.mouse = {300.0, 380.0};  // (0.5, -0.1): below the bottom segment
  input.left_pressed = input.left_down = input.left_double_clicked = true;
  handle_canvas_input(state, input);
  ASSERT_EQ(state.curve.control_points.size(), 5u);
  EXPECT_NEAR(state.curve.control_points[1].x, 0.5, 1e-12);
  EXPECT_NEAR(state.curve.control_points[1].y, -0.1, 1e-12);
  EXPECT_EQ(state.hovered, 1);
  EXPECT_EQ(state.dragged, -1);  // a double click that adds does not also start a drag

  input = CanvasInput{};
  input.hovered = true;
  input.mouse = {450.0, 50.0};  // p (1,1), now index 3
  input.right_pressed = true;
  handle_canvas_input(state, input);
  expect_points_eq({state.curve.control_points[2], state.curve.control_points[3]}, {{1, 0}, {0, 1}});
  EXPECT_EQ(state.curve.control_points.size(), 4u);
  EXPECT_EQ(state.hovered, -1);

  input = CanvasInput{};
  input.hovered = true;
  input.mouse = {300.0, 200.0};
  input.right_pressed = true;  // on empty canvas: nothing
  input.wheel = -2.0;
  handle_canvas_input(state, input);
  EXPECT_EQ(state.curve.control_points.size(), 4u);
  EXPECT_DOUBLE_EQ(state.t, 0.48);

  input.hovered = false;  // the wheel elsewhere does not touch t
  handle_canvas_input(state, input);
  EXPECT_DOUBLE_EQ(state.t, 0.48);
}

TEST(CurveEditor, APressAwayFromThePointsIsAClickForWhoeverAnswersIt) {
  CurveEditorState state = make_curve_editor(square_curve());
  state.view = view_for(CurveRegion{{0.0, 0.0}, {1.0, 1.0}}, {100.0, 50.0}, {400.0, 300.0});
  CanvasInput input;
  input.hovered = input.left_pressed = input.left_down = true;
  input.mouse = {450.0, 350.0};  // on p1: a drag, no click
  handle_canvas_input(state, input);
  EXPECT_EQ(state.dragged, 1);
  EXPECT_FALSE(state.clicked);

  state = make_curve_editor(square_curve());
  state.view = view_for(CurveRegion{{0.0, 0.0}, {1.0, 1.0}}, {100.0, 50.0}, {400.0, 300.0});
  input.mouse = {300.0, 200.0};  // (0.5, 0.5), away from every point
  handle_canvas_input(state, input);
  ASSERT_TRUE(state.clicked);
  EXPECT_NEAR(state.clicked->x, 0.5, 1e-12);
  EXPECT_NEAR(state.clicked->y, 0.5, 1e-12);
  EXPECT_EQ(state.curve.control_points.size(), 4u);  // a single click adds nothing

  state.clicked.reset();
  input.left_double_clicked = true;  // the second press of a double click adds a point and is no click
  handle_canvas_input(state, input);
  EXPECT_FALSE(state.clicked);
  EXPECT_EQ(state.curve.control_points.size(), 5u);

  input = CanvasInput{};
  input.left_pressed = input.left_down = true;  // off the canvas
  input.mouse = {300.0, 200.0};
  state.clicked.reset();
  handle_canvas_input(state, input);
  EXPECT_FALSE(state.clicked);
}

TEST(CurveEditor, TheTangentToggles) {
  CurveEditorState state = make_curve_editor(square_curve());
  EXPECT_FALSE(state.show_tangent);
  toggle_tangent(state);
  EXPECT_TRUE(state.show_tangent);
  toggle_tangent(state);
  EXPECT_FALSE(state.show_tangent);
}

}  // namespace
}  // namespace meshedit
