// Tests of the patch view: the probe overlay's geometry equals the core's separable evaluation, the
// toggles choose what is drawn, the tessellation cache rebuilds only on change, and the panel draws
// headless (its own ImGui context, no backend).
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

namespace meshedit {
namespace {

using glm::dvec3;

// A bumpy, non-planar patch with distinct control points: at(r, c) = (c, r, z(r, c)).
BezierPatch bumpy_patch(double shift = 0.0) {
  static constexpr double kHeights[16] = {0.0,  0.5,  -0.25, 1.0, 0.75,  2.0,   1.5,  -0.5,
                                          -1.0, 0.25, 3.0,   0.5, 0.125, -0.75, 1.25, 2.5};
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = dvec3(c + shift, r, kHeights[r * 4 + c]);
  }
  return patch;
}

// The plane z = 0 over [0,3]^2: tessellates to (n+1)^2 vertices and 2n^2 triangles.
BezierPatch flat_patch() {
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = dvec3(c, r, 0.0);
  }
  return patch;
}

void expect_same(const dvec3& actual, const dvec3& expected) {
  EXPECT_EQ(actual.x, expected.x);
  EXPECT_EQ(actual.y, expected.y);
  EXPECT_EQ(actual.z, expected.z);
}

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

TEST(PatchView, SettersClamp) {
  PatchViewState state = make_patch_view({bumpy_patch(), bumpy_patch(5.0)});
  set_resolution(state, 0);
  EXPECT_EQ(state.resolution, 1);
  set_resolution(state, 1000);
  EXPECT_EQ(state.resolution, kMaxPatchViewResolution);
  select_patch(state, 7);
  EXPECT_EQ(state.selected_patch, 1);
  select_patch(state, -3);
  EXPECT_EQ(state.selected_patch, 0);
  set_probe(state, 1.5, -0.25);
  EXPECT_EQ(state.u, 1.0);
  EXPECT_EQ(state.v, 0.0);
  set_probe(state, std::nan(""), 0.75);
  EXPECT_EQ(state.u, 1.0);
  EXPECT_EQ(state.v, 0.75);
  EXPECT_EQ(make_patch_view({}).resolution, kDefaultPatchResolution);
}

// ---- tessellation cache ----------------------------------------------------------------------------

TEST(PatchView, TessellationIsRebuiltOnlyWhenPatchesOrResolutionChange) {
  PatchViewState state = make_patch_view({flat_patch()});
  EXPECT_EQ(state.tessellation.rebuilds, 0u);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);
  ASSERT_TRUE(state.tessellation.mesh.has_value());
  EXPECT_EQ(state.tessellation.polygons.num_vertices(), 17u * 17u);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 2u * 16u * 16u);
  EXPECT_TRUE(state.tessellation.error.empty());
  const uint64_t first_version = state.tessellation.mesh->version();

  // Idle frames, and the same data assigned again: nothing is rebuilt.
  EXPECT_FALSE(update_tessellation(state));
  state.patches = {flat_patch()};
  state.u = 0.1;
  state.selected_patch = 0;
  EXPECT_FALSE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);

  set_resolution(state, 4);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 2u);
  EXPECT_EQ(state.tessellation.polygons.num_vertices(), 25u);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 32u);
  expect_same(state.tessellation.polygons.positions[6], dvec3(0.75, 0.75, 0.0));  // vertex j*(n+1)+i at (i/n, j/n)*3
  ASSERT_TRUE(state.tessellation.mesh.has_value());
  const uint64_t second_version = state.tessellation.mesh->version();
  EXPECT_GT(second_version, first_version);  // a renderer caching by version sees the new mesh

  state.patches[0].at(1, 1).z = 0.5;  // one control point moved
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 3u);
  EXPECT_GT(state.tessellation.mesh->version(), second_version);
  EXPECT_FALSE(update_tessellation(state));

  state.patches.push_back(bumpy_patch(10.0));  // a patch added
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 4u);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 2u * 2u * 4u * 4u);
}

TEST(PatchView, NaNPatchesDoNotRebuildEveryFrame) {
  BezierPatch broken = flat_patch();
  broken.at(2, 2).x = std::numeric_limits<double>::quiet_NaN();
  PatchViewState state = make_patch_view({broken});
  set_resolution(state, 2);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_FALSE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);
}

TEST(PatchView, ResolutionWrittenOutOfRangeIsClampedBeforeTessellating) {
  PatchViewState state = make_patch_view({flat_patch()});
  state.resolution = 100000;
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.resolution, kMaxPatchViewResolution);
  EXPECT_EQ(state.tessellation.resolution, kMaxPatchViewResolution);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 2u * 64u * 64u);
}

TEST(PatchView, InconsistentPatchesKeepPolygonsAndSayWhy) {
  // The same flat patch twice, the second with its rows reversed: the shared surface is used twice with
  // opposite orientations, which the tessellator splits apart or the builder refuses; either way nothing
  // throws out of update_tessellation, and the cache says what it has.
  BezierPatch flipped = flat_patch();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) flipped.at(r, c) = flat_patch().at(3 - r, c);
  }
  PatchViewState state = make_patch_view({flat_patch(), flipped});
  set_resolution(state, 2);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);
  EXPECT_EQ(state.tessellation.mesh.has_value(), state.tessellation.error.empty());
  EXPECT_GT(state.tessellation.polygons.num_faces(), 0u);
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
