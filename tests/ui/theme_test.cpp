// apply_theme() sets ImGui's colours and the palette the panels and the patch overlay draw with (ui/theme.h).
#include <gtest/gtest.h>

#include <imgui.h>

#include "core/palette.h"
#include "document/bezier_mine.h"
#include "ui/patch_view.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

glm::vec4 opaque(glm::vec3 rgb) { return glm::vec4(rgb, 1.0f); }

// Leaves the process's panel palette dark, as the other tests expect.
class UiTheme : public ::testing::Test {
 protected:
  void TearDown() override { apply_theme(style_, Theme::Dark); }
  ImGuiStyle style_;
};

BezierPatch raised_patch() {
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = glm::dvec3(c, r, (r * 4 + c) % 3);
  }
  return patch;
}

glm::vec4 colour_of(const std::vector<PatchOverlayItem>& items, OverlayKind kind) {
  for (const PatchOverlayItem& item : items) {
    if (item.kind == kind) return item.colour;
  }
  ADD_FAILURE() << "no item of that kind";
  return glm::vec4(-1.0f);
}

TEST_F(UiTheme, ApplyingAThemeSetsThePanelsPalette) {
  apply_theme(style_, Theme::Light);
  EXPECT_EQ(&ui_palette(), &palette_for(Theme::Light));
  const ImVec4 window = style_.Colors[ImGuiCol_WindowBg];
  const glm::vec3 panel = palette_for(Theme::Light).neutrals.panel;
  EXPECT_EQ(glm::vec3(window.x, window.y, window.z), panel);
  EXPECT_LT(style_.Colors[ImGuiCol_Text].x, 0.2f);  // ImGui's light style has dark text

  apply_theme(style_, Theme::Dark);
  EXPECT_EQ(&ui_palette(), &palette_for(Theme::Dark));
  EXPECT_GT(style_.Colors[ImGuiCol_Text].x, 0.8f);
}

TEST_F(UiTheme, ThePatchOverlayFollowsTheTheme) {
  PatchViewState state = make_patch_view({raised_patch()});
  for (Theme theme : {Theme::Dark, Theme::Light}) {
    apply_theme(style_, theme);
    const Palette& palette = palette_for(theme);
    const auto items = patch_view_overlay(state);
    EXPECT_EQ(colour_of(items, OverlayKind::SurfacePoint), opaque(palette.final_point));
    EXPECT_EQ(colour_of(items, OverlayKind::ColumnCurve), opaque(palette.curve));
    EXPECT_EQ(colour_of(items, OverlayKind::RowCurve), opaque(palette.row_curve));
    EXPECT_EQ(colour_of(items, OverlayKind::ControlNet), opaque(palette.probed_net));
  }
}

TEST_F(UiTheme, YourPointAgainstTheReferencesInThePatchOverlay) {
  PatchViewState state = make_patch_view({raised_patch()});
  const Palette& palette = palette_for(Theme::Light);
  apply_theme(style_, Theme::Light);
  PatchMinePoint mine;
  mine.ran = true;
  mine.equal = true;
  mine.mine = mine.reference = evaluate_patch(state.patches[0], state.u, state.v);
  auto items = patch_view_overlay(state, &mine);
  EXPECT_EQ(colour_of(items, OverlayKind::MinePoint), opaque(palette.mine));
  EXPECT_EQ(colour_of(items, OverlayKind::SurfacePoint), opaque(palette.final_point));

  // Yours differs: drawn in the wrong colour, and P(u, v) becomes the reference's, in the reference colour.
  mine.equal = false;
  mine.mine += glm::dvec3(0.5, 0.0, 0.0);
  items = patch_view_overlay(state, &mine);
  EXPECT_EQ(colour_of(items, OverlayKind::MinePoint), opaque(palette.wrong));
  EXPECT_EQ(colour_of(items, OverlayKind::SurfacePoint), opaque(palette.reference));
}

}  // namespace
}  // namespace meshedit
