// Keys and mouse of the window (see editor_app.h). The key map keeps the course viewers' letters:
//   mesh view   F flip, S split, C collapse, L Loop subdivision (Shift+L: one phase), W wireframe,
//               Q flat/smooth shading, I inspector, Space reset view, Ctrl+Z undo, Ctrl+Y redo,
//               N next, T twin, V vertex, E edge, F face (on a halfedge), H halfedge
//   curve view  E one more de Casteljau level, C the whole curve, M "mine" (levels from scripts/student/curve.lua)
//   patch view  M "mine" (the probe point from scripts/student/patch.lua)
//   everywhere  P screenshot, Ctrl+O open, Ctrl+Q quit, F1 help, Esc clears the selection, [ and ] fold the left
//               and right columns, Ctrl+= Ctrl+- Ctrl+0 text size (bigger, smaller, default), ` console, X exercises
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>

#include "app/editor_app.h"
#include "render/labels.h"
#include "ui/document_actions.h"

namespace meshedit {
namespace {

std::string timestamped_screenshot_name() {
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "meshedit-%Y%m%d-%H%M%S.png", std::localtime(&now));
  return buffer;
}

}  // namespace

bool EditorApp::handle_key(int key, KeyMods mods) {
  const bool handled = apply_key(key, mods);
  tell_lesson_key(key, mods);  // after the key acted, so a lesson that waits for F sees the flipped mesh
  return handled;
}

bool EditorApp::apply_key(int key, KeyMods mods) {
  // An edit or an undo in the middle of a replay would leave a half-replayed state in the history.
  for (int edit_key : {GLFW_KEY_F, GLFW_KEY_S, GLFW_KEY_C, GLFW_KEY_L, GLFW_KEY_Z, GLFW_KEY_Y}) {
    if (key == edit_key) exercises_.finish_replay(doc_);
  }
  if (key == GLFW_KEY_X && !mods.ctrl) {
    if (exercise_panel_.open) {
      exercise_panel_.open = false;
    } else {
      bring_exercises_tab_forward();
    }
    return true;
  }
  // Keys that work in every view.
  if (mods.ctrl && key == GLFW_KEY_Q) {
    quit_requested_ = true;
    return true;
  }
  if (mods.ctrl && (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD)) {
    change_font_size(+1);
    return true;
  }
  if (mods.ctrl && (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT)) {
    change_font_size(-1);
    return true;
  }
  if (mods.ctrl && (key == GLFW_KEY_0 || key == GLFW_KEY_KP_0)) {
    change_font_size(0);
    return true;
  }
  if (key == GLFW_KEY_LEFT_BRACKET) {
    settings_.layout.left_open = !settings_.layout.left_open;
    return true;
  }
  if (key == GLFW_KEY_RIGHT_BRACKET) {
    settings_.layout.right_open = !settings_.layout.right_open;
    return true;
  }
  if (mods.ctrl && key == GLFW_KEY_O) {
    show_open_panel_ = true;
    return true;
  }
  if (key == GLFW_KEY_F1) {
    show_help_ = !show_help_;
    return true;
  }
  if (key == GLFW_KEY_P && !mods.ctrl) {
    request_screenshot(timestamped_screenshot_name());
    return true;
  }
  if (key == GLFW_KEY_SPACE) {
    reset_view();
    return true;
  }
  if (key == GLFW_KEY_GRAVE_ACCENT) {
    console_panel_.open = !console_panel_.open;
    console_panel_.focus_input = console_panel_.open;
    return true;
  }

  if (mode_ == ViewMode::Curve) {
    if (key == GLFW_KEY_E) step_level(curve_);
    else if (key == GLFW_KEY_C) toggle_curve(curve_);
    else if (key == GLFW_KEY_M) bezier_mine_.set_curve_on(!bezier_mine_.curve_on());
    else return false;
    return true;
  }
  if (mode_ == ViewMode::Patches && key == GLFW_KEY_M) {
    bezier_mine_.set_patch_on(!bezier_mine_.patch_on());
    return true;
  }
  if (key == GLFW_KEY_W) {
    view_options_.wireframe = !view_options_.wireframe;
    return true;
  }
  if (key == GLFW_KEY_Q) {
    view_options_.smooth_shading = !view_options_.smooth_shading;
    return true;
  }
  if (mode_ != ViewMode::Mesh) return false;

  if (mods.ctrl) {
    if (key == GLFW_KEY_Z && !mods.shift) return undo_edit(doc_, selection_);
    if (key == GLFW_KEY_Y || (key == GLFW_KEY_Z && mods.shift)) return redo_edit(doc_, selection_);
    return false;
  }
  const ElementKind selected_kind = selection_.selected.kind;
  const bool on_halfedge = selection_.selected.valid() && selected_kind == ElementKind::Halfedge;
  switch (key) {
    case GLFW_KEY_I:
      inspector_.open = !inspector_.open;
      if (inspector_.open) {
        select_tab_ = RightTab::Inspector;
        // The inspector is a tab on the right while a lesson has the left column, else on the left: unfold it.
        bool& column_open = lesson_->loaded() ? settings_.layout.right_open : settings_.layout.left_open;
        column_open = true;
      }
      return true;
    case GLFW_KEY_ESCAPE: selection_.selected = {}; return true;
    case GLFW_KEY_S: split_selected(doc_, selection_); return true;  // outcome goes to the status line
    case GLFW_KEY_C: collapse_selected(doc_, selection_); return true;
    case GLFW_KEY_L:
      if (mods.shift) loop_subdivide_step(doc_, selection_, loop_weights_);
      else loop_subdivide_all(doc_, selection_, loop_weights_);
      return true;
    case GLFW_KEY_F:
      // On a halfedge F walks to its face; on an edge (the course's use) it flips.
      if (on_halfedge) return navigate_selection(doc_, selection_, NavStep::Face);
      flip_selected(doc_, selection_);
      return true;
    case GLFW_KEY_N: return navigate_selection(doc_, selection_, NavStep::Next);
    case GLFW_KEY_T: return navigate_selection(doc_, selection_, NavStep::Twin);
    case GLFW_KEY_V: return navigate_selection(doc_, selection_, NavStep::Vertex);
    case GLFW_KEY_E: return navigate_selection(doc_, selection_, NavStep::Edge);
    case GLFW_KEY_H: return navigate_selection(doc_, selection_, NavStep::Halfedge);
    default: return false;
  }
}

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
    for (int key : {GLFW_KEY_F, GLFW_KEY_S, GLFW_KEY_C, GLFW_KEY_L, GLFW_KEY_N, GLFW_KEY_T, GLFW_KEY_V, GLFW_KEY_E,
                    GLFW_KEY_H, GLFW_KEY_W, GLFW_KEY_Q, GLFW_KEY_I, GLFW_KEY_P, GLFW_KEY_O, GLFW_KEY_Z, GLFW_KEY_Y,
                    GLFW_KEY_SPACE, GLFW_KEY_ESCAPE, GLFW_KEY_F1, GLFW_KEY_GRAVE_ACCENT, GLFW_KEY_X, GLFW_KEY_M,
                    GLFW_KEY_LEFT_BRACKET, GLFW_KEY_RIGHT_BRACKET, GLFW_KEY_EQUAL, GLFW_KEY_MINUS, GLFW_KEY_0,
                    GLFW_KEY_KP_ADD, GLFW_KEY_KP_SUBTRACT, GLFW_KEY_KP_0}) {
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

  const bool panning = ImGui::IsMouseDragging(ImGuiMouseButton_Middle) ||
                       (io.KeyShift && ImGui::IsMouseDragging(ImGuiMouseButton_Left));
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
    const bool cheap = mesh_renderer_->pick_is_cheap(camera_, viewport()) ||
                       mesh_renderer_->stats().last_id_pass_ms < kSlowIdPassMs;
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
