// The window's two looks: dark (the default) and light (for projectors). apply_theme() sets ImGui's style colours and
// makes the theme's palette (core/palette.h) the one the panels draw with (ui_palette()); the 3D view's background
// and the renderer's colours come from the same palette (palette_for(theme), core/palette.h).
//
// Invariant: ui_palette() is the palette of the theme last given to apply_theme(), the dark one before any; like
// ImGui's style, it is one for the whole process.
#pragma once

#include <imgui.h>

#include "core/palette.h"
#include "document/settings.h"

namespace meshedit {

// Sets `style`'s colours for the theme (its sizes are left as they are) and the panels' palette.
void apply_theme(ImGuiStyle& style, Theme theme);
// The palette the panels, the curve view and the patch view's overlay draw with.
const Palette& ui_palette();
// The theme of ui_palette(): what swatch_in_theme takes to show a lesson's colour in the panels.
Theme ui_theme();

// Palette colours as ImGui takes them.
inline ImVec4 im_colour(glm::vec3 rgb, float alpha = 1.0f) { return ImVec4(rgb.r, rgb.g, rgb.b, alpha); }
inline ImVec4 im_colour(glm::vec4 rgba) { return ImVec4(rgba.r, rgba.g, rgba.b, rgba.a); }
inline ImU32 im_colour_u32(glm::vec3 rgb, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(im_colour(rgb, alpha));
}
inline ImU32 im_colour_u32(glm::vec4 rgba) { return ImGui::ColorConvertFloat4ToU32(im_colour(rgba)); }

}  // namespace meshedit
