// A RenderStyle takes its colours from the palette of a theme, and keeps its sizes and limits when they change.
#include <gtest/gtest.h>

#include "core/palette.h"
#include "render/view_options.h"

namespace meshedit {
namespace {

glm::vec4 opaque(glm::vec3 rgb) { return glm::vec4(rgb, 1.0f); }

TEST(RenderStyle, ADefaultStyleHasTheDarkPalette) {
  const RenderStyle style;
  const Palette& dark = palette_for(Theme::Dark);
  EXPECT_EQ(style.background, opaque(dark.neutrals.view));
  EXPECT_EQ(style.face, opaque(dark.neutrals.face));
  EXPECT_EQ(style.selected, opaque(dark.selected));
  EXPECT_EQ(style.changed, opaque(dark.changed));
}

TEST(RenderStyle, EveryColourFollowsTheTheme) {
  const RenderStyle style = render_style_for(Theme::Light);
  const Palette& light = palette_for(Theme::Light);
  EXPECT_EQ(style.background, opaque(light.neutrals.view));
  EXPECT_EQ(style.face, opaque(light.neutrals.face));
  EXPECT_EQ(style.back_face, opaque(light.neutrals.back_face));
  EXPECT_EQ(style.wire, opaque(light.neutrals.wire));
  EXPECT_EQ(style.boundary, opaque(light.boundary));
  EXPECT_EQ(style.vertex, opaque(light.vertex));
  EXPECT_EQ(style.arrow, opaque(light.arrow));
  EXPECT_EQ(style.selected, opaque(light.selected));
  EXPECT_EQ(style.hovered, opaque(light.hovered));
  EXPECT_EQ(style.changed, opaque(light.changed));
  EXPECT_NE(style.background, RenderStyle().background);
}

TEST(RenderStyle, SettingColoursKeepsSizesAndLimits) {
  RenderStyle style;
  style.wire_width = 2.0f;
  style.large_mesh_triangles = 7;
  style.max_buffer_texels = 1000;
  set_render_colours(style, palette_for(Theme::Light));
  EXPECT_EQ(style.wire_width, 2.0f);
  EXPECT_EQ(style.large_mesh_triangles, 7u);
  EXPECT_EQ(style.max_buffer_texels, 1000u);
  EXPECT_EQ(style.selected, opaque(palette_for(Theme::Light).selected));
  set_render_colours(style, palette_for(Theme::Dark));
  EXPECT_EQ(style.selected, opaque(palette_for(Theme::Dark).selected));
}

}  // namespace
}  // namespace meshedit
