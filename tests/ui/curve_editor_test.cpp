// Tests of the curve view's ImGui window, driven headless (no backend: fonts built, frames rendered to draw data)
// with a simulated drag, double click, right click and scroll; the state's own functions are tested in
// tests/document/curve_view_state_test.cpp.
#include "ui/curve_editor.h"
#include "ui_test_support.h"

#include <cmath>

#include <gtest/gtest.h>
#include <imgui.h>

namespace meshedit {
namespace {

using glm::dvec2;

// The course's curve1.bzc numbers (a cubic); the file itself is not read here (ui does not depend on io).
BezierCurve course_cubic() { return BezierCurve{{{0.2, 0.35}, {0.3, 0.6}, {0.8, 0.75}, {0.9, 0.45}}}; }

// ---- ImGui, headless -------------------------------------------------------------------------------

// The shared headless ImGui (ui_test_support.h) at 1024x768, with one frame of the curve editor in a fixed
// 800x600 window and the mouse at `mouse`.
class CurveEditorHarness : public ui_testing::ImGuiHarness {
 public:
  CurveEditorHarness() : ImGuiHarness(ImVec2(1024.0f, 768.0f)) {}

  ImDrawData* frame(CurveEditorState& state, dvec2 mouse, bool left = false, bool right = false, float wheel = 0.0f) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(static_cast<float>(mouse.x), static_cast<float>(mouse.y));
    io.MouseDown[0] = left;
    io.MouseDown[1] = right;
    io.MouseWheel = wheel;
    ImGuiHarness::frame([&] {
      ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
      ImGui::SetNextWindowSize(ImVec2(800.0f, 600.0f));
      draw_curve_editor(state);
    });
    return ImGui::GetDrawData();
  }
};

// A whole pixel near `p`: ImGui 1.86 floors io.MousePos in NewFrame, so tests put the mouse on whole
// pixels and know exactly where ImGui sees it.
dvec2 pixel(dvec2 p) { return {std::round(p.x), std::round(p.y)}; }

TEST(CurveEditorImGui, DrawsTheCanvasAndFitsTheCurveInIt) {
  CurveEditorHarness imgui;
  CurveEditorState state = make_curve_editor(course_cubic());
  state.levels_shown = 3;
  state.show_curve = true;
  state.show_split = true;
  const ImDrawData* data = imgui.frame(state, {1000.0, 700.0});
  ASSERT_NE(data, nullptr);
  EXPECT_TRUE(data->Valid);
  EXPECT_GT(data->CmdListsCount, 0);
  EXPECT_GT(data->TotalVtxCount, 1000);  // the curve, levels, points and the table's text
  EXPECT_GT(state.view.canvas_size.x, 200.0);
  EXPECT_GT(state.view.canvas_size.y, 150.0);
  for (const dvec2& p : state.curve.control_points) {
    const dvec2 s = curve_to_screen(state.view, p);
    EXPECT_GT(s.x, state.view.canvas_min.x);
    EXPECT_LT(s.x, state.view.canvas_min.x + state.view.canvas_size.x);
    EXPECT_GT(s.y, state.view.canvas_min.y);
    EXPECT_LT(s.y, state.view.canvas_min.y + state.view.canvas_size.y);
  }
  EXPECT_EQ(state.hovered, -1);
}

TEST(CurveEditorImGui, DraggingWithTheMouseMovesThatControlPoint) {
  CurveEditorHarness imgui;
  CurveEditorState state = make_curve_editor(course_cubic());
  const BezierCurve before = state.curve;
  imgui.frame(state, {1000.0, 700.0});  // lays out the canvas: state.view is now the real transform
  const dvec2 grab = pixel(curve_to_screen(state.view, before.control_points[1]));

  imgui.frame(state, grab);
  EXPECT_EQ(state.hovered, 1);
  imgui.frame(state, grab, true);
  EXPECT_EQ(state.dragged, 1);
  const dvec2 moved = pixel(grab + dvec2(40.0, -25.0));
  imgui.frame(state, pixel(grab + dvec2(15.0, -5.0)), true);
  imgui.frame(state, moved, true);
  imgui.frame(state, moved, false);
  EXPECT_EQ(state.dragged, -1);

  const dvec2 expected =
      before.control_points[1] + screen_to_curve(state.view, moved) - screen_to_curve(state.view, grab);
  EXPECT_NEAR(state.curve.control_points[1].x, expected.x, 1e-12);
  EXPECT_NEAR(state.curve.control_points[1].y, expected.y, 1e-12);
  EXPECT_GT(state.curve.control_points[1].y, before.control_points[1].y);  // up on screen is up in y
  for (int i : {0, 2, 3}) EXPECT_EQ(state.curve.control_points[i], before.control_points[i]) << "point " << i;
}

TEST(CurveEditorImGui, DoubleClickAddsRightClickRemovesScrollMovesT) {
  CurveEditorHarness imgui;
  CurveEditorState state = make_curve_editor(course_cubic());
  imgui.frame(state, {1000.0, 700.0});
  // Just inside the canvas's bottom-right corner: far from every control point.
  const dvec2 empty = pixel(state.view.canvas_min + state.view.canvas_size - dvec2(30.0, 40.0));
  ASSERT_EQ(hit_test(state, empty), -1);
  imgui.frame(state, empty);
  imgui.frame(state, empty, true);
  imgui.frame(state, empty, false);
  imgui.frame(state, empty, true);  // second press within the double-click time
  imgui.frame(state, empty, false);
  ASSERT_EQ(state.curve.control_points.size(), 5u);
  const dvec2 added = screen_to_curve(state.view, empty);
  EXPECT_EQ(state.curve.control_points.back(), added);  // beyond the last point: appended

  const dvec2 second = pixel(curve_to_screen(state.view, state.curve.control_points[2]));
  imgui.frame(state, second);
  imgui.frame(state, second, false, true);
  imgui.frame(state, second, false, false);
  ASSERT_EQ(state.curve.control_points.size(), 4u);
  EXPECT_EQ(state.curve.control_points[2], dvec2(0.9, 0.45));

  imgui.frame(state, empty, false, false, 3.0f);
  EXPECT_DOUBLE_EQ(state.t, 0.53);
  imgui.frame(state, {1000.0, 700.0}, false, false, 3.0f);  // outside the window: t stays
  EXPECT_DOUBLE_EQ(state.t, 0.53);
}

}  // namespace
}  // namespace meshedit
