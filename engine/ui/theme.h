// The window's two looks: dark (the default) and light (for projectors), as ImGui style colours. The 3D view's
// background follows the theme through view_background().
#pragma once

#include <imgui.h>

#include "ui/settings.h"

namespace meshedit {

// Sets `style`'s colours for the theme (its sizes are left as they are).
void apply_theme(ImGuiStyle& style, Theme theme);
// The view's clear colour under the theme, RGBA in [0, 1].
ImVec4 view_background(Theme theme);

}  // namespace meshedit
