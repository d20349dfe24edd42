// PanelsRoom: the columns, the console strip and the splitters that resize them, and the look (see panels_room.h).
#include "app/panels_room.h"

#include <imgui.h>

#include <algorithm>

#include "app/check_room.h"
#include "app/document_room.h"
#include "app/exercise_room.h"
#include "app/lesson_room.h"
#include "app/view_room.h"
#include "app/window_host.h"
#include "core/translation.h"
#include "ui/curve_editor.h"
#include "ui/fonts.h"
#include "ui/lesson_panel.h"
#include "ui/lesson_question_view.h"
#include "ui/patch_view.h"
#include "ui/theme.h"

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

void PanelsRoom::lay_out(float menu_height, float status_height) {
  const ImGuiIO& io = ImGui::GetIO();
  font_pixels_ = ImGui::GetFontSize();
  layout_ = compute_layout(io.DisplaySize.x, io.DisplaySize.y, menu_height, status_height, settings_.layout,
                           font_pixels_, console_panel_.open);
}

void PanelsRoom::bring_forward(RightTab tab) {
  select_tab_ = tab;
  settings_.layout.right_open = true;
}

void PanelsRoom::draw_columns() {
  MeshDocument& doc = document_.doc();
  if (view_.mode() == ViewMode::Mesh) {
    exercises_.session().sync(doc);  // also while its tab is closed: the session notices edits made elsewhere
  }
  draw_left_column();
  draw_right_column();
  draw_console_strip();
  draw_splitters();
  keep_if_alive(document_.selection(), doc.mesh);  // a panel may have deleted what was selected (a console line)
}

void PanelsRoom::draw_left_column() {
  if (layout_.left.empty()) return;
  place_next_window(layout_.left);
  LessonRunner& runner = lessons_.runner();
  LessonPanelState& panel = lessons_.panel();
  const bool lesson = runner.loaded();
  const std::string title =
      (lesson ? lesson_text(runner, runner.title()) : std::string(tr("Lessons"))) + "###left column";
  panel.probe = &probe_;
  // A lesson's new translations the fonts cannot draw yet (a lesson from outside lessons/): loaded at the next frame.
  if (text_language() != Language::English && runner.texts().size() != glyphs_checked_) {
    glyphs_checked_ = runner.texts().size();
    if (!fonts_cover(runner.texts().all_in(text_language()))) look_changed_ = true;
  }
  if (ImGui::Begin(title.c_str(), nullptr, kColumnFlags)) {
    if (!lesson && view_.mode() == ViewMode::Mesh && inspector_.open) {
      ImGui::BeginChild("inspector", ImVec2(0, ImGui::GetContentRegionAvail().y * 0.55f), true);
      ImGui::TextDisabled("%s", tr("Inspector (I)"));
      draw_inspector_contents(document_.doc(), document_.selection(), inspector_);
      ImGui::EndChild();
      ImGui::TextDisabled("%s", tr("Start a lesson:"));
    }
    draw_lesson_panel_contents(runner, panel);
  }
  ImGui::End();
  panel.probe = nullptr;
  lessons_.take_request();
}

void PanelsRoom::draw_right_column() {
  if (layout_.right.empty()) return;
  place_next_window(layout_.right);
  if (!ImGui::Begin("###right column", nullptr, kColumnFlags | ImGuiWindowFlags_NoTitleBar)) {
    ImGui::End();
    return;
  }
  if (view_.mode() == ViewMode::Mesh) {
    draw_right_tabs();
  } else if (!check_.panel().open) {
    draw_bezier_panel();
  } else if (ImGui::BeginTabBar("bezier panels")) {  // the curve or the patches beside the Check tab
    if (ImGui::BeginTabItem(view_.mode() == ViewMode::Curve ? tr_label("Curve") : tr_label("Patches"), nullptr,
                            select_tab_ == RightTab::Tables ? ImGuiTabItemFlags_SetSelected : 0)) {
      draw_bezier_panel();
      ImGui::EndTabItem();
    }
    check_tab();
    ImGui::EndTabBar();
  }
  select_tab_ = RightTab::None;
  ImGui::End();
}

void PanelsRoom::draw_bezier_panel() {
  if (view_.mode() == ViewMode::Curve) {
    ImGui::TextDisabled("%s", tr("Curve"));
    draw_curve_controls(view_.curve(), &view_.bezier_mine());
    ImGui::Separator();
    ImGui::BeginChild("levels");
    draw_curve_levels(view_.curve(), &view_.bezier_mine());
    ImGui::EndChild();
  } else {
    ImGui::TextDisabled("%s", tr("Patches"));
    draw_patch_view_panel_contents(view_.patches(), &view_.bezier_mine());
  }
}

bool PanelsRoom::check_tab() {
  CheckPanelState& panel = check_.panel();
  if (!panel.open) return false;
  const ImGuiTabItemFlags flags = select_tab_ == RightTab::Check ? ImGuiTabItemFlags_SetSelected : 0;
  if (!ImGui::BeginTabItem(tr_label("Check"), &panel.open, flags)) return false;
  probe_.record_last_item("tab:Check");
  check_.draw_tab(probe_);
  ImGui::EndTabItem();
  return true;
}

void PanelsRoom::draw_right_tabs() {
  if (!ImGui::BeginTabBar("panels")) return;
  const auto tab = [&](const char* label, RightTab which, bool* open) {
    const ImGuiTabItemFlags flags = select_tab_ == which ? ImGuiTabItemFlags_SetSelected : 0;
    return ImGui::BeginTabItem(label, open, flags);
  };
  MeshDocument& doc = document_.doc();
  Selection& selection = document_.selection();
  if (tables_.open && tab(tr_label("Pointers"), RightTab::Tables, &tables_.open)) {
    ImGui::PushFont(mono_font());
    draw_pointer_tables_contents(doc, selection, tables_);
    ImGui::PopFont();
    ImGui::EndTabItem();
  }
  if (lessons_.runner().loaded() && inspector_.open &&
      tab(tr_label("Inspector"), RightTab::Inspector, &inspector_.open)) {
    draw_inspector_contents(doc, selection, inspector_);
    ImGui::EndTabItem();
  }
  ExercisePanelState& exercise_panel = exercises_.panel();
  if (exercise_panel.open && tab(tr_label("Exercises"), RightTab::Exercises, &exercise_panel.open)) {
    exercises_.draw_exercises_tab(probe_);
    ImGui::EndTabItem();
  }
  // In a page (no editor of the student's own), opening the Exercises tab opens "Your code" beside it.
  StudentEditorState& editor = exercises_.editor();
  if (exercises_.exercises_just_opened() && !host_files_on_users_disk()) editor.open = true;
  if (editor.open && tab(tr_label("Your code"), RightTab::Code, &editor.open)) {
    exercises_.draw_student_code_tab(probe_);
    ImGui::EndTabItem();
  }
  bool& repairs_open = document_.repairs_tab_open();
  if (!document_.repair_marks().empty() && repairs_open && tab(tr_label("Repairs"), RightTab::Repairs, &repairs_open)) {
    document_.draw_repairs_tab(view_.mode() == ViewMode::Mesh, settings_.theme);
    ImGui::EndTabItem();
  }
  check_tab();
  ImGui::EndTabBar();
}

void PanelsRoom::draw_console_strip() {
  if (layout_.console.empty()) return;
  place_next_window(layout_.console);
  const std::string title = std::string(tr("Lua console (`)")) + "###console";
  if (ImGui::Begin(title.c_str(), &console_panel_.open, kColumnFlags)) {
    draw_console_panel_contents(console_, console_panel_, document_.doc(), document_.selection());
  }
  ImGui::End();
}

void PanelsRoom::draw_splitters() {
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

void PanelsRoom::change_font_size(int steps) {
  settings_.font_px = steps == 0 ? Settings::kDefaultFontPx : stepped_font_px(settings_.font_px, steps);
  look_changed_ = true;
}

void PanelsRoom::apply_settings(const Settings& settings) {
  settings_ = settings;
  set_theme(settings.theme);
  const std::optional<Language> chosen = language_by_code(settings.language);
  set_language(chosen.value_or(system_language()));
  if (!chosen) settings_.language.clear();  // still the system's: the settings file keeps following it
}

void PanelsRoom::set_language(Language language) {
  settings_.language = language_code(language);
  if (language == text_language()) return;
  for (const std::string& problem : set_text_language(language)) document_.message(Severity::Warning, problem);
  look_changed_ = true;  // the fonts again, with the glyphs the language needs
}

void PanelsRoom::set_theme(Theme theme) {
  settings_.theme = theme;
  view_.set_theme(theme);
  look_changed_ = true;  // the window applies ImGui's colours and the panels' palette before the next frame
}

void PanelsRoom::fonts_applied(const FontsLoaded& fonts) {
  if (!fonts.warning.empty()) document_.message(Severity::Warning, fonts.warning);
}

}  // namespace meshedit
