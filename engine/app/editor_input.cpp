// Keys and mouse of the window (see editor_app.h). Which key does what is app/key_bindings.h's table, which keeps
// the course viewers' letters; here each command is carried out.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>

#include "app/editor_app.h"
#include "app/key_bindings.h"
#include "document/document_actions.h"
#include "render/labels.h"

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
  const KeyView view = mode_ == ViewMode::Mesh    ? KeyView::Mesh
                       : mode_ == ViewMode::Curve ? KeyView::Curve
                                                  : KeyView::Patches;
  const KeyBinding* binding = find_key_binding(key, mods.ctrl, mods.shift, view);
  if (!binding) return false;
  // An edit or an undo in the middle of a replay would leave a half-replayed state in the history.
  if (binding->edits) exercises_.finish_replay(doc_);
  return run_key_command(binding->command);
}

bool EditorApp::run_key_command(KeyCommand command) {
  switch (command) {
    case KeyCommand::ToggleExercises:
      if (exercise_panel_.open) exercise_panel_.open = false;
      else bring_exercises_tab_forward();
      return true;
    case KeyCommand::Quit: quit_requested_ = true; return true;
    case KeyCommand::BiggerText: change_font_size(+1); return true;
    case KeyCommand::SmallerText: change_font_size(-1); return true;
    case KeyCommand::DefaultText: change_font_size(0); return true;
    case KeyCommand::FoldLeft: settings_.layout.left_open = !settings_.layout.left_open; return true;
    case KeyCommand::FoldRight: settings_.layout.right_open = !settings_.layout.right_open; return true;
    case KeyCommand::Open: show_open_panel_ = true; return true;
    case KeyCommand::Help: show_help_ = !show_help_; return true;
    case KeyCommand::Screenshot: request_screenshot(timestamped_screenshot_name()); return true;
    case KeyCommand::ResetView: reset_view(); return true;
    case KeyCommand::Console:
      console_panel_.open = !console_panel_.open;
      console_panel_.focus_input = console_panel_.open;
      return true;
    case KeyCommand::Wireframe: view_options_.wireframe = !view_options_.wireframe; return true;
    case KeyCommand::Shading: view_options_.smooth_shading = !view_options_.smooth_shading; return true;
    case KeyCommand::CurveStep: step_level(curve_); return true;
    case KeyCommand::CurveToggle: toggle_curve(curve_); return true;
    case KeyCommand::CurveMine: bezier_mine_.set_curve_on(!bezier_mine_.curve_on()); return true;
    case KeyCommand::PatchMine: bezier_mine_.set_patch_on(!bezier_mine_.patch_on()); return true;
    case KeyCommand::Undo: return undo_edit(doc_, selection_);
    case KeyCommand::Redo: return redo_edit(doc_, selection_);
    case KeyCommand::Inspector:
      inspector_.open = !inspector_.open;
      if (inspector_.open) {
        select_tab_ = RightTab::Inspector;
        // The inspector is a tab on the right while a lesson has the left column, else on the left: unfold it.
        bool& column_open = lesson_->loaded() ? settings_.layout.right_open : settings_.layout.left_open;
        column_open = true;
      }
      return true;
    case KeyCommand::ClearSelection: selection_.selected = {}; return true;
    case KeyCommand::FlipOrFace:
      // On a halfedge F walks to its face; on an edge (the course's use) it flips.
      if (selection_.selected.valid() && selection_.selected.kind == ElementKind::Halfedge) {
        return navigate_selection(doc_, selection_, NavStep::Face);
      }
      flip_selected(doc_, selection_);
      return true;
    case KeyCommand::Split: split_selected(doc_, selection_); return true;  // the outcome goes to the status line
    case KeyCommand::Collapse: collapse_selected(doc_, selection_); return true;
    case KeyCommand::Loop: run_loop(false); return true;
    case KeyCommand::LoopPhase: run_loop(true); return true;
    case KeyCommand::Next: return navigate_selection(doc_, selection_, NavStep::Next);
    case KeyCommand::Twin: return navigate_selection(doc_, selection_, NavStep::Twin);
    case KeyCommand::Vertex: return navigate_selection(doc_, selection_, NavStep::Vertex);
    case KeyCommand::Edge: return navigate_selection(doc_, selection_, NavStep::Edge);
    case KeyCommand::Halfedge: return navigate_selection(doc_, selection_, NavStep::Halfedge);
  }
  return false;
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
