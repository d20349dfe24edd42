// glfw_key_pressed: whether a key, named by its GLFW key code (a letter is its ASCII capital: 'S' is GLFW_KEY_S), was
// pressed this frame, asked of the ImGui the build has: 1.86 (Debian 12, Ubuntu 22.04) takes the backend's key index
// as an int; 1.87 and later (Ubuntu 24.04 ships 1.90) take an ImGuiKey, whose legacy native range (0 to 511) the
// GLFW backend keeps filled with those same codes.
#pragma once

#include <imgui.h>

namespace meshedit {

inline bool glfw_key_pressed(int key, bool repeat) {
#if IMGUI_VERSION_NUM >= 18700
  return ImGui::IsKeyPressed(static_cast<ImGuiKey>(key), repeat);
#else
  return ImGui::IsKeyPressed(key, repeat);
#endif
}

}  // namespace meshedit
