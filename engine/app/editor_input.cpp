// The mouse of the window, and the keys read each frame (see editor_app.h). What a key press runs is the command
// table's (document/command_table.h, which keeps the course viewers' letters): editor_commands.cpp.
#include <imgui.h>

#include "app/commands.h"
#include "app/editor_app.h"
#include "document/document_actions.h"
#include "render/labels.h"

namespace meshedit {

std::optional<ScreenPoint> EditorApp::element_pixel(ElementRef element) const {
  const std::optional<glm::dvec3> anchor = label_anchor(doc_.mesh, element);
  if (!anchor) return std::nullopt;
  const Viewport view = viewport();
  const ScreenPoint p = camera_.project(*anchor, view);
  if (!p.in_front || p.pixel.x < 0.0 || p.pixel.y < 0.0 || p.pixel.x >= view.width || p.pixel.y >= view.height) {
    return std::nullopt;
  }
  return p;
}

void EditorApp::click(int x, int y) {
  if (mode_ != ViewMode::Mesh) return;
  const ElementRef picked = mesh_renderer_->pick(camera_, viewport(), x, y);
  if (picked.valid()) {
    select_element(doc_, selection_, picked);
    reveal_in_tables(tables_, picked);
    if (lesson_->loaded()) lesson_->deliver(LessonEvent::click(picked));
  } else {
    selection_.selected = {};
  }
}

void EditorApp::hover(int x, int y) {
  if (mode_ != ViewMode::Mesh) return;
  selection_.hovered = mesh_renderer_->pick(camera_, viewport(), x, y);
}

void EditorApp::read_mouse_and_keys() {
  ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    const KeyMods mods{io.KeyCtrl, io.KeyShift};
    for (int key : bound_keys()) {
      if (ImGui::IsKeyPressed(key, false)) handle_key(key, mods);
    }
  }
  if (io.WantCaptureMouse || mode_ == ViewMode::Curve) {
    dragging_ = false;
    selection_.hovered = {};  // the panels set it again while a link or row is under the mouse
    return;
  }
  // ImGui gives window coordinates; the renderer wants framebuffer pixels of the view. A drag that started in the
  // view goes on over the columns; a click, a hover or the wheel count only in the view.
  const std::optional<glm::ivec2> in_view = mouse_in_view();
  const int x = in_view ? in_view->x : -1, y = in_view ? in_view->y : -1;
  const ImVec2 delta(io.MouseDelta.x * pixels_per_point_.x, io.MouseDelta.y * pixels_per_point_.y);
  if (io.MouseWheel != 0.0f && in_view) camera_.zoom(io.MouseWheel);

  const bool panning =
      ImGui::IsMouseDragging(ImGuiMouseButton_Middle) || (io.KeyShift && ImGui::IsMouseDragging(ImGuiMouseButton_Left));
  if (panning) {
    camera_.pan(delta.x, delta.y, viewport());
  } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left) || ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
    camera_.orbit(delta.x, delta.y);
    dragging_ = true;
  }
  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    if (!dragging_ && !io.KeyShift && in_view) click(x, y);
    dragging_ = false;
  }
  if (!in_view && !dragging_ && !panning) {
    selection_.hovered = {};
    hover_pending_ = false;
    return;
  }
  // Picking while the camera moves would redraw the whole id buffer every frame; wait for the drag to end. After
  // a camera move the id buffer is stale: when redrawing it is slow (a large mesh on llvmpipe), the hover waits
  // until the mouse rests, so moving across the view right after an orbit drops no frame.
  const bool moving_camera = panning || dragging_;
  const bool mouse_moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
  const double now = ImGui::GetTime();
  if (moving_camera) {
    hover_pending_ = false;
  } else if (mouse_moved) {
    const bool cheap =
        mesh_renderer_->pick_is_cheap(camera_, viewport()) || mesh_renderer_->stats().last_id_pass_ms < kSlowIdPassMs;
    if (cheap) {
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
}

}  // namespace meshedit
