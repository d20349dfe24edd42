// The curve and patch views with "mine" (bezier_mine.h) on: the patch overlay puts the student's point where it is,
// with a segment to the reference's when they differ, and nothing for a student file that fails; both views draw the
// switch, the wrong level and the errors headless.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/bezier.h"
#include "core/value_format.h"
#include "document/bezier_mine.h"
#include "document/bezier_mine_test_support.h"
#include "support/test_support.h"
#include "ui/curve_editor.h"
#include "ui/patch_view.h"
#include "ui/ui_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

using namespace document_testing;

// ---- the patch probe's overlay ---------------------------------------------------------------------------

TEST(BezierMine, SwappedUAndVAreNamedWithBothPoints) {
  const fs::path folder = testing::scratch_dir();
  write_file(folder, "patch.lua",
             solution_with("patch.lua",
                           "column[row + 1] = evaluate_1d({ p[base + 1], p[base + 2], p[base + 3], p[base + 4] }, u)",
                           "column[row + 1] = evaluate_1d({ p[row + 1], p[row + 5], p[row + 9], p[row + 13] }, u)"));
  BezierMine mine(folder);
  const PatchMinePoint& got = mine.patch_point(hill(), 0.3, 0.8);
  EXPECT_TRUE(got.ran);
  EXPECT_FALSE(got.equal);
  EXPECT_TRUE(testing::near(got.mine, evaluate_patch(hill(), 0.8, 0.3), 1e-12));  // the point at (v, u)
  EXPECT_EQ(got.reference, evaluate_patch(hill(), 0.3, 0.8));
  EXPECT_EQ(got.message, "P(0.3, 0.8): yours is " + format_position(got.mine) + ", the reference's is " +
                             format_position(got.reference));
  ASSERT_EQ(got.details.size(), 1u);
  EXPECT_NE(got.details[0].find("u and v are swapped"), std::string::npos) << got.details[0];

  // The overlay: the reference's P(u, v) as before, then a segment from yours to it and yours, in that order.
  PatchViewState state = make_patch_view({hill()});
  set_probe(state, 0.3, 0.8);
  const std::vector<PatchOverlayItem> items = patch_view_overlay(state, &got);
  ASSERT_GE(items.size(), 3u);
  const PatchOverlayItem& dot = items.back();
  const PatchOverlayItem& segment = items[items.size() - 2];
  EXPECT_EQ(dot.kind, OverlayKind::MinePoint);
  EXPECT_TRUE(dot.points_only);
  ASSERT_EQ(dot.points.size(), 1u);
  EXPECT_EQ(dot.points[0], got.mine);
  EXPECT_EQ(segment.kind, OverlayKind::MinePoint);
  ASSERT_EQ(segment.points.size(), 2u);
  EXPECT_EQ(segment.points[1], evaluate_patch(hill(), 0.3, 0.8));
  EXPECT_EQ(items[items.size() - 3].kind, OverlayKind::SurfacePoint);
  EXPECT_EQ(patch_view_overlay(state).size(), items.size() - 2);  // without mine: the probe alone
}

TEST(BezierMine, APatchErrorKeepsFileAndLineAndDrawsNoPoint) {
  const fs::path folder = testing::scratch_dir();
  write_file(folder, "patch.lua", "function evaluate(patch, u, v)\n  return patch.points[17] * u\nend\n");
  BezierMine mine(folder);
  const PatchMinePoint& got = mine.patch_point(hill(), 0.5, 0.5);
  EXPECT_FALSE(got.ran);
  EXPECT_EQ(got.error.rfind("patch.lua:2:", 0), 0u) << got.error;
  EXPECT_EQ(got.message, got.error);
  PatchViewState state = make_patch_view({hill()});
  EXPECT_EQ(patch_view_overlay(state, &got).size(), patch_view_overlay(state).size());
}

// ---- the views, drawn headless ---------------------------------------------------------------------------

TEST(BezierMine, TheViewsDrawTheSwitchTheWrongLevelAndTheErrors) {
  ui_testing::ImGuiHarness imgui;
  const fs::path folder = testing::scratch_dir();
  write_file(folder, "curve.lua",
             solution_with("curve.lua", kStepLine,
                           kStepLine + "    if i == 2 then result[i] = result[i] + meshedit.vec3(0, 0.25, 0) end\n"));
  write_file(folder, "patch.lua", "function evaluate(patch, u, v)\n  return nil + 1\nend\n");
  BezierMine mine(folder);
  CurveEditorState curve = make_curve_editor(BezierCurve{kCubic});
  const auto draw_curve = [&] {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(900, 700));
    draw_curve_editor(curve, "Curve editor", &mine);
  };
  const int off = imgui.frame(draw_curve);
  EXPECT_TRUE(mine.curve().levels.empty()) << "the switch is off: no student code runs";
  mine.set_curve_on(true);
  step_level(curve);
  step_level(curve);
  const int on = imgui.frame(draw_curve);
  EXPECT_EQ(mine.curve().failed_level, 1);
  EXPECT_NE(on, off);  // the reference level, the ring and the message are drawn
  EXPECT_EQ(mine.curve().message.rfind("level 1, point 2 of 3: yours is ", 0), 0u) << mine.curve().message;

  PatchViewState patches = make_patch_view({hill()});
  mine.set_patch_on(true);
  imgui.frame([&] { draw_patch_view_panel(patches, "Patch view", &mine); });
  EXPECT_EQ(mine.patch().message.rfind("patch.lua:2:", 0), 0u) << mine.patch().message;
}

}  // namespace
}  // namespace meshedit
