// The window's themes (see theme.h).
#include "ui/theme.h"

namespace meshedit {

void apply_theme(ImGuiStyle& style, Theme theme) {
  if (theme == Theme::Light) {
    ImGui::StyleColorsLight(&style);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.97f, 0.97f, 0.96f, 1.0f);
  } else {
    ImGui::StyleColorsDark(&style);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.09f, 0.09f, 0.10f, 1.0f);  // opaque: the columns are not overlays
  }
  style.WindowRounding = 0.0f;  // columns meet the view edge to edge
  style.WindowBorderSize = 1.0f;
}

ImVec4 view_background(Theme theme) {
  return theme == Theme::Light ? ImVec4(0.84f, 0.85f, 0.87f, 1.0f) : ImVec4(0.13f, 0.14f, 0.16f, 1.0f);
}

}  // namespace meshedit
