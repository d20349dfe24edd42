// Tests of the patch view's drawing: the probe overlay's geometry equals the core's separable evaluation, the
// toggles choose what is drawn, and the panel draws headless (its own ImGui context, no backend); the state and its
// tessellation cache are tested in tests/document/patch_view_state_test.cpp.
#include "ui/patch_view.h"
#include "ui_test_support.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <imgui.h>

#include "support/test_patches.h"

namespace meshedit {
namespace {

using glm::dvec3;

using testing::bumpy_patch;
using testing::expect_same;
using testing::flat_patch;

std::vector<PatchOverlayItem> of_kind(const std::vector<PatchOverlayItem>& items, OverlayKind kind) {
  std::vector<PatchOverlayItem> out;
  std::copy_if(items.begin(), items.end(), std::back_inserter(out),
               [kind](const PatchOverlayItem& item) { return item.kind == kind; });
  return out;
}

// ---- probe geometry --------------------------------------------------------------------------------

TEST(PatchProbe, ControlNetIsEightPolylinesOfFourPoints) {
  const BezierPatch patch = bumpy_patch();
  const auto items = build_probe_overlay(patch, 0.3, 0.7);
  const auto net = of_kind(items, OverlayKind::ControlNet);
  ASSERT_EQ(net.size(), 8u);
  for (int r = 0; r < 4; ++r) {
    ASSERT_EQ(net[r].points.size(), 4u);
    EXPECT_FALSE(net[r].points_only);
    for (int c = 0; c < 4; ++c) expect_same(net[r].points[c], patch.at(r, c));
    EXPECT_EQ(net[r].label, "control net row " + std::to_string(r));
  }
  for (int c = 0; c < 4; ++c) {
    ASSERT_EQ(net[4 + c].points.size(), 4u);
    for (int r = 0; r < 4; ++r) expect_same(net[4 + c].points[r], patch.at(r, c));
    EXPECT_EQ(net[4 + c].label, "control net column " + std::to_string(c));
  }
}

TEST(PatchProbe, RowPointsAndSurfacePointAreTheCoreEvaluation) {
  const BezierPatch patch = bumpy_patch();
  const double u = 0.3;
  const double v = 0.7;
  const auto items = build_probe_overlay(patch, u, v);
  const PatchEvaluation eval = evaluate_patch_steps(patch, u, v);

  const auto rows = of_kind(items, OverlayKind::RowPoints);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_TRUE(rows[0].points_only);
  ASSERT_EQ(rows[0].points.size(), 4u);
  for (int r = 0; r < 4; ++r) expect_same(rows[0].points[r], eval.row_points[r]);

  const auto polygon = of_kind(items, OverlayKind::ColumnPolygon);
  ASSERT_EQ(polygon.size(), 1u);
  ASSERT_EQ(polygon[0].points.size(), 4u);
  for (int r = 0; r < 4; ++r) expect_same(polygon[0].points[r], eval.row_points[r]);

  const auto levels = of_kind(items, OverlayKind::ColumnLevel);
  ASSERT_EQ(levels.size(), 2u);
  ASSERT_EQ(levels[0].points.size(), 3u);
  ASSERT_EQ(levels[1].points.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    for (size_t i = 0; i < levels[k].points.size(); ++i) expect_same(levels[k].points[i], eval.column_levels[k + 1][i]);
  }

  const auto surface = of_kind(items, OverlayKind::SurfacePoint);
  ASSERT_EQ(surface.size(), 1u);
  EXPECT_TRUE(surface[0].points_only);
  ASSERT_EQ(surface[0].points.size(), 1u);
  expect_same(surface[0].points[0], evaluate_patch(patch, u, v));
  expect_same(surface[0].points[0], eval.point);
}

TEST(PatchProbe, RowAndColumnCurvesAreSampledBezierCurves) {
  const BezierPatch patch = bumpy_patch();
  const auto items = build_probe_overlay(patch, 0.25, 0.5, 4);
  ASSERT_EQ(items.size(), 8u + 4u + 1u + 1u + 2u + 1u + 1u);  // the documented order and counts

  const auto rows = of_kind(items, OverlayKind::RowCurve);
  ASSERT_EQ(rows.size(), 4u);
  for (int r = 0; r < 4; ++r) {
    ASSERT_EQ(rows[r].points.size(), 5u);
    const std::span<const dvec3> row(patch.points.data() + r * 4, 4);
    expect_same(rows[r].points.front(), patch.at(r, 0));
    expect_same(rows[r].points.back(), patch.at(r, 3));
    expect_same(rows[r].points[1], evaluate_curve(row, 0.25));  // sample 1 of 4 is at u = 0.25: the row point
    expect_same(rows[r].points[1], evaluate_patch_steps(patch, 0.25, 0.5).row_points[r]);
  }

  const PatchEvaluation eval = evaluate_patch_steps(patch, 0.25, 0.5);
  const auto column = of_kind(items, OverlayKind::ColumnCurve);
  ASSERT_EQ(column.size(), 1u);
  ASSERT_EQ(column[0].points.size(), 5u);
  expect_same(column[0].points.front(), eval.row_points[0]);
  expect_same(column[0].points.back(), eval.row_points[3]);
  expect_same(column[0].points[2], eval.point);  // sample 2 of 4 is at v = 0.5: the surface point
}

TEST(PatchProbe, CornersOfTheProbeAreControlPoints) {
  const BezierPatch patch = bumpy_patch();
  const auto at_corner = [&](double u, double v) {
    return of_kind(build_probe_overlay(patch, u, v), OverlayKind::SurfacePoint)[0].points[0];
  };
  expect_same(at_corner(0.0, 0.0), patch.at(0, 0));
  expect_same(at_corner(1.0, 0.0), patch.at(0, 3));
  expect_same(at_corner(0.0, 1.0), patch.at(3, 0));
  expect_same(at_corner(1.0, 1.0), patch.at(3, 3));
}

// ---- toggles ---------------------------------------------------------------------------------------

TEST(PatchView, OverlayFollowsTheToggles) {
  PatchViewState state = make_patch_view({bumpy_patch(), bumpy_patch(10.0), bumpy_patch(20.0)});
  select_patch(state, 1);

  state.show_probe = false;
  auto items = patch_view_overlay(state);
  ASSERT_EQ(items.size(), 24u);  // three nets
  for (const auto& item : items) EXPECT_EQ(item.kind, OverlayKind::ControlNet);
  expect_same(items[8].points[0], bumpy_patch(10.0).at(0, 0));  // patch order kept
  EXPECT_EQ(items[8].label, "patch 1 row 0");
  EXPECT_GT(items[8].width, items[0].width);  // the selected net stands out

  state.show_probe = true;
  items = patch_view_overlay(state);
  ASSERT_EQ(items.size(), 16u + 18u);  // the other two nets, then the probe with the selected net
  const auto surface = of_kind(items, OverlayKind::SurfacePoint);
  ASSERT_EQ(surface.size(), 1u);
  expect_same(surface[0].points[0], evaluate_patch(bumpy_patch(10.0), 0.5, 0.5));

  state.show_control_net = false;
  items = patch_view_overlay(state);
  EXPECT_EQ(items.size(), 18u);
  EXPECT_EQ(of_kind(items, OverlayKind::ControlNet).size(), 8u);  // the probed patch keeps its net

  state.show_probe = false;
  EXPECT_TRUE(patch_view_overlay(state).empty());
  EXPECT_TRUE(patch_view_overlay(make_patch_view({})).empty());
}

// ---- ImGui, headless -------------------------------------------------------------------------------

TEST(PatchViewImGui, PanelDrawsAndBuildsTheSurface) {
  ui_testing::ImGuiHarness imgui(ImVec2(1024.0f, 768.0f));
  PatchViewState state = make_patch_view({bumpy_patch(), flat_patch()});
  for (int frame = 0; frame < 3; ++frame) {
    ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    imgui.frame([&] {
      ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
      ImGui::SetNextWindowSize(ImVec2(600.0f, 500.0f));
      draw_patch_view_panel(state);
    });
    const ImDrawData* data = ImGui::GetDrawData();
    ASSERT_NE(data, nullptr);
    EXPECT_GT(data->CmdListsCount, 0);
    EXPECT_GT(data->TotalVtxCount, 500);  // sliders, checkboxes and the table's numbers
  }
  EXPECT_EQ(state.tessellation.rebuilds, 1u);  // built by the first frame, then left alone
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 2u * 2u * 16u * 16u);
}

}  // namespace
}  // namespace meshedit
