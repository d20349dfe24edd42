// InputRoom: the mouse and the keys of the window (see input_room.h). What a key press runs is the command table's
// (document/command_table.h, which keeps the course viewers' letters): editor_commands.cpp.
#include "app/input_room.h"

#include <imgui.h>

#include "app/document_room.h"
#include "app/view_room.h"
#include "ui/key_pressed.h"

namespace meshedit {

std::vector<std::pair<int, KeyMods>> InputRoom::keys_pressed() {
  std::vector<std::pair<int, KeyMods>> pressed;
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return pressed;
  const KeyMods mods{io.KeyCtrl, io.KeyShift};
  for (int key : bound_keys()) {
    if (glfw_key_pressed(key, false)) pressed.emplace_back(key, mods);
  }
  return pressed;
}

void InputRoom::hover(int x, int y) {
  if (view_.mode() != ViewMode::Mesh) return;
  document_.selection().hovered = view_.pick(x, y);
}

std::optional<glm::ivec2> InputRoom::read_mouse() {
  const ImGuiIO& io = ImGui::GetIO();
  Selection& selection = document_.selection();
  if (io.WantCaptureMouse || view_.mode() == ViewMode::Curve) {
    dragging_ = false;
    selection.hovered = {};  // the panels set it again while a link or row is under the mouse
    return std::nullopt;
  }
  // ImGui gives window coordinates; the renderer wants framebuffer pixels of the view.
  const std::optional<glm::ivec2> in_view = view_.mouse_in_view();
  const int x = in_view ? in_view->x : -1, y = in_view ? in_view->y : -1;
  const glm::vec2 scale = view_.pixels_per_point();
  const ImVec2 delta(io.MouseDelta.x * scale.x, io.MouseDelta.y * scale.y);
  OrbitCamera& camera = view_.camera();
  if (io.MouseWheel != 0.0f && in_view) camera.zoom(io.MouseWheel);

  const bool panning =
      ImGui::IsMouseDragging(ImGuiMouseButton_Middle) || (io.KeyShift && ImGui::IsMouseDragging(ImGuiMouseButton_Left));
  if (panning) {
    camera.pan(delta.x, delta.y, view_.viewport());
  } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left) || ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
    camera.orbit(delta.x, delta.y);
    dragging_ = true;
  }
  std::optional<glm::ivec2> clicked;
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    if (!dragging_ && !io.KeyShift && in_view) clicked = glm::ivec2(x, y);
    dragging_ = false;
  }
  if (!in_view && !dragging_ && !panning) {
    selection.hovered = {};
    hover_pending_ = false;
    return clicked;
  }
  const bool moving_camera = panning || dragging_;
  const bool mouse_moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
  const double now = ImGui::GetTime();
  if (moving_camera) {
    hover_pending_ = false;
  } else if (mouse_moved) {
    if (view_.pick_is_cheap()) {
      hover(x, y);
      hover_pending_ = false;
    } else {
      hover_pending_ = true;
      mouse_moved_at_ = now;
    }
  } else if (hover_pending_ && now - mouse_moved_at_ >= kHoverRestSeconds) {
    hover(x, y);
    hover_pending_ = false;
  }
  return clicked;
}

}  // namespace meshedit
