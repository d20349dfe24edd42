// EditorApp's fixed layout (see editor_app.h and document/window_layout.h): the columns, the console strip, the
// splitters that resize them, and the view rectangle the 3D, patch and curve views draw into.
//
// The columns are borderless ImGui windows that cannot move, resize or collapse by themselves: their rectangles come
// from compute_layout every frame, so no panel can cover the lesson or the view. What each column holds:
//   left   the lesson while one runs; else the inspector over the list of lessons (the list alone outside the mesh
//          view);
//   right  mesh view: tabs Pointers, Inspector (while a lesson has the left column) and Exercises;
//          curve view: the curve's controls and its levels; patch view: the patch controls and the evaluation table.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/editor_app.h"
#include "render/gl_api.h"

namespace meshedit {
namespace {

constexpr ImGuiWindowFlags kColumnFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                          ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                          ImGuiWindowFlags_NoBringToFrontOnFocus;

void place_next_window(const ScreenRect& rect) {
  ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
  ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height));
}

// A strip the mouse drags to resize a panel; returns the drag in pixels this frame (0 when not dragged).
ImVec2 splitter(const char* id, const ScreenRect& rect, bool horizontal) {
  if (rect.empty()) return ImVec2(0, 0);
  place_next_window(rect);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImVec2 drag(0, 0);
  if (ImGui::Begin(id, nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoSavedSettings |
                       ImGuiWindowFlags_NoMove)) {
    ImGui::InvisibleButton("##drag", ImVec2(rect.width, rect.height));
    const bool active = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
    if (active || hovered) {
      ImGui::SetMouseCursor(horizontal ? ImGuiMouseCursor_ResizeNS : ImGuiMouseCursor_ResizeEW);
      ImGui::GetWindowDrawList()->AddRectFilled(
          ImVec2(rect.x, rect.y), ImVec2(rect.right(), rect.bottom()),
          ImGui::GetColorU32(active ? ImGuiCol_SeparatorActive : ImGuiCol_SeparatorHovered));
    }
    if (active) drag = ImGui::GetIO().MouseDelta;
  }
  ImGui::End();
  ImGui::PopStyleVar(3);
  return drag;
}

}  // namespace

void EditorApp::place_view(int framebuffer_width, int framebuffer_height) {
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplaySize.x > 0 ? float(framebuffer_width) / io.DisplaySize.x : 1.0f;
  const float sy = io.DisplaySize.y > 0 ? float(framebuffer_height) / io.DisplaySize.y : 1.0f;
  pixels_per_point_ = {sx, sy};
  const ScreenRect& v = layout_.view;
  const int x0 = int(std::lround(v.x * sx)), y0 = int(std::lround(v.y * sy));
  const int x1 = int(std::lround(v.right() * sx)), y1 = int(std::lround(v.bottom() * sy));
  view_pixels_ = {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
  framebuffer_height_ = std::max(1, framebuffer_height);
}

void EditorApp::begin_view_drawing() {
  const PixelRect& v = view_pixels_;
  const int gl_y = framebuffer_height_ - (v.y + v.height);  // GL counts rows from the bottom
  glViewport(v.x, gl_y, v.width, v.height);
  glScissor(v.x, gl_y, v.width, v.height);
  glEnable(GL_SCISSOR_TEST);
}

void EditorApp::end_view_drawing() { glDisable(GL_SCISSOR_TEST); }

std::optional<glm::ivec2> EditorApp::mouse_in_view() const {
  const ImGuiIO& io = ImGui::GetIO();
  if (!ImGui::IsMousePosValid() || !layout_.view.contains(io.MousePos.x, io.MousePos.y)) return std::nullopt;
  return glm::ivec2(int((io.MousePos.x - layout_.view.x) * pixels_per_point_.x),
                    int((io.MousePos.y - layout_.view.y) * pixels_per_point_.y));
}

void EditorApp::draw_columns() {
  if (mode_ == ViewMode::Mesh) {
    exercises_.sync(doc_);  // also while its tab is closed: the session notices edits made elsewhere
  }
  draw_left_column();
  draw_right_column();
  draw_console_strip();
  draw_splitters();
  keep_if_alive(selection_, doc_.mesh);  // a panel may have deleted what was selected (a console line, a replay)
}

void EditorApp::draw_left_column() {
  if (layout_.left.empty()) return;
  place_next_window(layout_.left);
  const bool lesson = lesson_->loaded();
  const std::string title = (lesson ? lesson_->title() : std::string("Lessons")) + "###left column";
  lesson_panel_.probe = &probe_;
  if (ImGui::Begin(title.c_str(), nullptr, kColumnFlags)) {
    if (!lesson && mode_ == ViewMode::Mesh && inspector_.open) {
      ImGui::BeginChild("inspector", ImVec2(0, ImGui::GetContentRegionAvail().y * 0.55f), true);
      ImGui::TextDisabled("Inspector (I)");
      draw_inspector_contents(doc_, selection_, inspector_);
      ImGui::EndChild();
      ImGui::TextDisabled("Start a lesson:");
    }
    draw_lesson_panel_contents(*lesson_, lesson_panel_);
  }
  ImGui::End();
  lesson_panel_.probe = nullptr;
  take_lesson_request();
}

void EditorApp::draw_right_column() {
  if (layout_.right.empty()) return;
  place_next_window(layout_.right);
  if (!ImGui::Begin("###right column", nullptr, kColumnFlags | ImGuiWindowFlags_NoTitleBar)) {
    ImGui::End();
    return;
  }
  if (mode_ == ViewMode::Curve) {
    ImGui::TextDisabled("Curve");
    draw_curve_controls(curve_, &bezier_mine_);
    ImGui::Separator();
    ImGui::BeginChild("levels");
    draw_curve_levels(curve_, &bezier_mine_);
    ImGui::EndChild();
  } else if (mode_ == ViewMode::Patches) {
    ImGui::TextDisabled("Patches");
    draw_patch_view_panel_contents(patches_, &bezier_mine_);
  } else if (ImGui::BeginTabBar("panels")) {
    auto tab = [&](const char* label, RightTab which, bool* open) {
      const ImGuiTabItemFlags flags = select_tab_ == which ? ImGuiTabItemFlags_SetSelected : 0;
      return ImGui::BeginTabItem(label, open, flags);
    };
    if (tables_.open && tab("Pointers", RightTab::Tables, &tables_.open)) {
      ImGui::PushFont(mono_font());
      draw_pointer_tables_contents(doc_, selection_, tables_);
      ImGui::PopFont();
      ImGui::EndTabItem();
    }
    if (lesson_->loaded() && inspector_.open && tab("Inspector", RightTab::Inspector, &inspector_.open)) {
      draw_inspector_contents(doc_, selection_, inspector_);
      ImGui::EndTabItem();
    }
    if (exercise_panel_.open && tab("Exercises", RightTab::Exercises, &exercise_panel_.open)) {
      probe_.record_last_item("exercises-tab");  // the tab is in front (tests)
      draw_exercise_panel_contents(exercises_, exercise_panel_, doc_, selection_);
      ImGui::EndTabItem();
    }
    open_student_code_with_exercises();
    if (student_editor_.open && tab("Your code", RightTab::Code, &student_editor_.open)) {
      draw_student_code_tab();
      ImGui::EndTabItem();
    }
    if (!repairs_.empty() && repairs_tab_open_ && tab("Repairs", RightTab::Repairs, &repairs_tab_open_)) {
      draw_repairs_tab();
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  select_tab_ = RightTab::None;
  ImGui::End();
}

void EditorApp::draw_console_strip() {
  if (layout_.console.empty()) return;
  place_next_window(layout_.console);
  if (ImGui::Begin("Lua console (`)###console", &console_panel_.open, kColumnFlags)) {
    draw_console_panel_contents(console_, console_panel_, doc_, selection_);
  }
  ImGui::End();
}

void EditorApp::draw_splitters() {
  const float em = std::max(1.0f, font_pixels_);
  LayoutPrefs& prefs = settings_.layout;
  if (const ImVec2 d = splitter("##left splitter", layout_.left_splitter, false); d.x != 0.0f) {
    prefs.left_ems = dragged_ems(layout_.left.width, d.x, em, WindowLayout::kMinColumnEms);
  }
  if (const ImVec2 d = splitter("##right splitter", layout_.right_splitter, false); d.x != 0.0f) {
    prefs.right_ems = dragged_ems(layout_.right.width, -d.x, em, WindowLayout::kMinColumnEms);
  }
  if (const ImVec2 d = splitter("##console splitter", layout_.console_splitter, true); d.y != 0.0f) {
    prefs.console_ems = dragged_ems(layout_.console.height, -d.y, em, WindowLayout::kMinConsoleEms);
  }
}

void EditorApp::draw_curve_canvas_window() {
  const ScreenRect& v = layout_.view;
  if (v.empty()) return;
  place_next_window(v);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  // The wheel belongs to t over the canvas: the window itself must not scroll with it.
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                 ImGuiWindowFlags_NoScrollWithMouse;
  if (ImGui::Begin("###curve view", nullptr, flags)) {
    draw_curve_canvas(curve_, ImVec2(v.width, v.height), &bezier_mine_);
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
  // A click on the curve answers a lesson's pick on the curve; within the pick radius in pixels it is on the curve.
  if (curve_.clicked && lesson_->loaded()) {
    lesson_->deliver(LessonEvent::curve_click(*curve_.clicked, kCurvePickRadius / curve_.view.scale));
  }
  curve_.clicked.reset();
}

void EditorApp::change_font_size(int steps) {
  settings_.font_px = steps == 0 ? Settings::kDefaultFontPx : stepped_font_px(settings_.font_px, steps);
  look_changed_ = true;
}

void EditorApp::apply_settings(const Settings& settings) {
  settings_ = settings;
  set_theme(settings.theme);
}

void EditorApp::set_theme(Theme theme) {
  settings_.theme = theme;
  const Palette& palette = palette_for(theme);
  set_render_colours(mesh_renderer_->style(), palette);
  set_render_colours(patch_renderer_->style(), palette);
  look_changed_ = true;  // the window applies ImGui's colours and the panels' palette before the next frame
}

void EditorApp::fonts_applied(const FontsLoaded& fonts) {
  if (!fonts.warning.empty()) message(Severity::Warning, fonts.warning);
}

}  // namespace meshedit
