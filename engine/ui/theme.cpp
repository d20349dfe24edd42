// The window's themes (see theme.h).
#include "ui/theme.h"

namespace meshedit {
namespace {

Theme panel_theme = Theme::Dark;

}  // namespace

void apply_theme(ImGuiStyle& style, Theme theme) {
  const Palette& palette = palette_for(theme);
  if (theme == Theme::Light) {
    ImGui::StyleColorsLight(&style);
  } else {
    ImGui::StyleColorsDark(&style);
  }
  style.Colors[ImGuiCol_WindowBg] = im_colour(palette.neutrals.panel);  // opaque: the columns are not overlays
  style.WindowRounding = 0.0f;                                          // columns meet the view edge to edge
  style.WindowBorderSize = 1.0f;
  panel_theme = theme;
}

const Palette& ui_palette() { return palette_for(panel_theme); }

Theme ui_theme() { return panel_theme; }

}  // namespace meshedit
