// The menu bar, the open/save dialog (a small file browser with a recent list) and the key help. The two dialogs are
// modal and centred on the window: nothing else takes input while one is open.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "app/editor_app.h"
#include "app/key_bindings.h"
#include "app/mesh_loading.h"
#include "app/window_host.h"
#include "document/document_actions.h"
#include "document/subdivision_actions.h"
#include "io/mesh_file.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

// ImGui 1.86 has no std::string input without imgui_stdlib; a fixed buffer is enough for a path.
bool input_path(const char* label, std::string& text) {
  char buffer[1024];
  const size_t n = std::min(text.size(), sizeof buffer - 1);
  std::copy_n(text.data(), n, buffer);
  buffer[n] = '\0';
  const bool entered = ImGui::InputText(label, buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  text = buffer;
  return entered;
}

}  // namespace

Check EditorApp::run_loop(bool one_phase) {
  const Check check = one_phase ? loop_subdivide_step(doc_, selection_, loop_weights_)
                                : loop_subdivide_all(doc_, selection_, loop_weights_);
  if (check) tell_lesson_command(subdivide_command(SubdivisionScheme::Loop, one_phase));
  return check;
}

Check EditorApp::run_subdivide_command(SubdivisionScheme scheme, bool one_phase) {
  exercises_.finish_replay(doc_);
  if (scheme == SubdivisionScheme::Loop) {  // as L and Shift+L, which a lesson may wait for as keys too
    const Check check = run_loop(one_phase);
    tell_lesson_key(GLFW_KEY_L, {false, one_phase});
    return check;
  }
  const bool catmull_clark = scheme == SubdivisionScheme::CatmullClark;
  Check check;
  if (one_phase) check = subdivision_step(doc_, selection_, catmull_clark ? catmull_clark_stepper_ : linear_stepper_);
  else check = catmull_clark ? catmull_clark_all(doc_, selection_) : linear_subdivide_all(doc_, selection_);
  if (check) tell_lesson_command(subdivide_command(scheme, one_phase));
  return check;
}

void EditorApp::press(KeyCommand command) {
  for (const KeyBinding& b : key_bindings()) {
    if (b.command == command && b.help) {
      handle_key(b.key, {b.ctrl, b.shift});
      return;
    }
  }
}

void EditorApp::key_menu_item(const char* label, KeyCommand command, bool enabled, bool checked) {
  if (ImGui::MenuItem(label, shortcut_of(command), checked, enabled)) press(command);
}

void EditorApp::draw_menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  draw_file_menu();
  draw_edit_menu();
  draw_subdivide_menu();
  draw_view_menu();
  draw_help_menu();
  ImGui::EndMainMenuBar();
}

void EditorApp::draw_file_menu() {
  using K = KeyCommand;
  if (!ImGui::BeginMenu("File")) return;
  // A page reaches the student's disk only through the browser's picker; Open... lists the packaged files there.
  if (host_has_file_picker() && ImGui::MenuItem("Open mesh from this computer...")) host_show_file_picker();
  key_menu_item("Open...", K::Open);
  if (ImGui::BeginMenu("Open recent", !recent_.empty())) {
    for (const std::string& path : std::deque<std::string>(recent_)) {
      if (ImGui::MenuItem(path.c_str())) open(path);
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("Open a repaired copy", nullptr, false, !repairable_path_.empty())) open_repaired();
  if (ImGui::MenuItem("Save as...", nullptr, false, mode_ == ViewMode::Mesh)) show_open_panel_ = true;
  if (ImGui::MenuItem("Screenshot", shortcut_of(K::Screenshot))) request_screenshot("meshedit-screenshot.png");
  // A page's student files live in the browser: these take them to and from the student's disk for submission.
  if (!host_files_on_users_disk()) {
    ImGui::Separator();
    const std::string name = exercises_.file().filename().string();
    if (ImGui::MenuItem(("Download your " + name).c_str())) download_student_code();
    if (ImGui::MenuItem("Upload your .lua from this computer...")) host_show_file_picker();
  }
  ImGui::Separator();
  key_menu_item("Quit", K::Quit);
  ImGui::EndMenu();
}

void EditorApp::draw_edit_menu() {
  using K = KeyCommand;
  if (!ImGui::BeginMenu("Edit", mode_ == ViewMode::Mesh)) return;
  key_menu_item("Undo", K::Undo, doc_.history.can_undo());
  key_menu_item("Redo", K::Redo, doc_.history.can_redo());
  ImGui::Separator();
  if (ImGui::MenuItem("Flip edge", shortcut_of(K::FlipOrFace))) {  // F on a halfedge walks to its face; this flips
    exercises_.finish_replay(doc_);
    flip_selected(doc_, selection_);
  }
  key_menu_item("Split edge", K::Split);
  key_menu_item("Collapse edge", K::Collapse);
  ImGui::Separator();
  if (ImGui::MenuItem("Triangulate")) {  // every face of more than three corners
    exercises_.finish_replay(doc_);
    if (triangulate_all(doc_, selection_)) tell_lesson_command("triangulate");
  }
  ImGui::EndMenu();
}

void EditorApp::draw_subdivide_menu() {
  using K = KeyCommand;
  using S = SubdivisionScheme;
  if (!ImGui::BeginMenu("Subdivide", mode_ == ViewMode::Mesh)) return;
  if (ImGui::MenuItem("Loop subdivision", shortcut_of(K::Loop))) run_subdivide_command(S::Loop, false);
  char phase[96];  // on the stack: the menu item's label needs no memory (the phase labels fit with room to spare)
  std::snprintf(phase, sizeof phase, "Loop: %s", next_loop_phase_label(doc_).c_str());
  if (ImGui::MenuItem(phase, shortcut_of(K::LoopPhase))) run_subdivide_command(S::Loop, true);
  bool loop_beta = loop_weights_ == LoopWeights::Loop;
  if (ImGui::MenuItem("Loop's original weights (beta)", nullptr, &loop_beta)) {
    loop_weights_ = loop_beta ? LoopWeights::Loop : LoopWeights::Course;
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Catmull-Clark subdivision")) run_subdivide_command(S::CatmullClark, false);
  if (ImGui::MenuItem(next_phase_label(doc_, catmull_clark_stepper_).c_str())) {
    run_subdivide_command(S::CatmullClark, true);
  }
  if (ImGui::MenuItem("Linear subdivision")) run_subdivide_command(S::Linear, false);
  if (ImGui::MenuItem(next_phase_label(doc_, linear_stepper_).c_str())) run_subdivide_command(S::Linear, true);
  ImGui::EndMenu();
}

void EditorApp::draw_view_menu() {
  using K = KeyCommand;
  if (!ImGui::BeginMenu("View")) return;
  ImGui::MenuItem("Wireframe", shortcut_of(K::Wireframe), &view_options_.wireframe);
  ImGui::MenuItem("Smooth shading", shortcut_of(K::Shading), &view_options_.smooth_shading);
  ImGui::MenuItem("Vertices", nullptr, &view_options_.show_vertices);
  ImGui::MenuItem("Halfedge arrows", nullptr, &view_options_.show_halfedges);
  ImGui::MenuItem("Boundary", nullptr, &view_options_.show_boundary);
  ImGui::MenuItem("Id labels", nullptr, &show_labels_);
  ImGui::MenuItem("Animate edits", nullptr, &settings_.animate_edits);  // flip, split, collapse, their undo, redo
  ImGui::Separator();
  ImGui::MenuItem("Left column (lesson)", shortcut_of(K::FoldLeft), &settings_.layout.left_open);
  ImGui::MenuItem("Right column (tables)", shortcut_of(K::FoldRight), &settings_.layout.right_open);
  key_menu_item("Inspector", K::Inspector, true, inspector_.open);
  ImGui::MenuItem("Pointer tables", nullptr, &tables_.open);
  key_menu_item("Exercises: mine vs reference", K::ToggleExercises, true, exercise_panel_.open);
  if (ImGui::MenuItem("Your code (the exercise's file)", nullptr, student_editor_.open)) {
    if (student_editor_.open) student_editor_.open = false;
    else show_student_code();
  }
  key_menu_item("Lua console", K::Console, true, console_panel_.open);
  if (ImGui::BeginMenu("Up axis")) {  // radio items; each refits the view
    const std::pair<const char*, UpAxisChoice> choices[] = {
        {"From the file", UpAxisChoice::FromFile}, {"Y up", UpAxisChoice::Y}, {"Z up", UpAxisChoice::Z}};
    for (const auto& [label, choice] : choices) {
      if (ImGui::MenuItem(label, nullptr, up_axis_choice_ == choice)) choose_up_axis(choice);
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  key_menu_item("Bigger text", K::BiggerText);
  key_menu_item("Smaller text", K::SmallerText);
  key_menu_item("Default text size", K::DefaultText);
  if (ImGui::BeginMenu("Theme")) {
    constexpr std::pair<const char*, Theme> kThemes[] = {{"Dark", Theme::Dark}, {"Light (projectors)", Theme::Light}};
    for (const auto& [name, theme] : kThemes) {
      if (ImGui::MenuItem(name, nullptr, settings_.theme == theme) && settings_.theme != theme) set_theme(theme);
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  key_menu_item("Reset view", K::ResetView);
  ImGui::EndMenu();
}

void EditorApp::draw_help_menu() {
  if (!ImGui::BeginMenu("Help")) return;
  if (ImGui::MenuItem("Keys", shortcut_of(KeyCommand::Help))) show_help_ = true;
  ImGui::EndMenu();
}

namespace {

// Opens the modal popup `name` while `shown` holds, centred and at most `size` (within the window). Returns whether
// it is open this frame (then call ImGui::EndPopup).
bool begin_dialog(const char* name, bool& shown, ImVec2 size) {
  if (!shown) return false;
  if (!ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
  const ImGuiViewport* main = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(main->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(size.x, main->Size.x * 0.9f), std::min(size.y, main->Size.y * 0.9f)),
                           ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal(name, &shown)) return true;
  shown = false;  // closed from outside (the popup stack was cleared)
  return false;
}

void end_dialog(bool shown) {
  if (!shown) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace

void EditorApp::draw_open_panel() {
  const float em = ImGui::GetFontSize();
  if (!begin_dialog("Open or save", show_open_panel_, ImVec2(40 * em, 30 * em))) return;
  if (open_path_input_.empty()) open_path_input_ = std::filesystem::current_path().string();
  if (input_path("path", open_path_input_) || ImGui::Button("Open")) {
    if (std::filesystem::is_directory(open_path_input_)) {
      // Entering a folder just lists it.
    } else if (open(open_path_input_)) {
      show_open_panel_ = false;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Assets")) open_path_input_ = assets_dir().string();
  if (host_has_file_picker()) {
    ImGui::SameLine();
    if (ImGui::Button("From this computer...")) {
      host_show_file_picker();
      show_open_panel_ = false;
    }
  }
  if (mode_ == ViewMode::Mesh) {
    input_path("save as", save_path_input_);
    ImGui::SameLine();
    if (ImGui::Button("Save") && !save_path_input_.empty()) save(save_path_input_);
    ImGui::TextDisabled("%s", list_extensions(writable_extensions(), ", ", " or ").c_str());
  }
  ImGui::Separator();

  // The folder of the path typed so far (or the path itself if it is a folder).
  std::filesystem::path folder = open_path_input_;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) folder = folder.parent_path();
  ImGui::BeginChild("listing", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 4));
  if (ImGui::Selectable("..")) open_path_input_ = folder.parent_path().string();
  std::vector<std::filesystem::directory_entry> entries;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    if (entry.is_directory(ec) || is_readable(entry.path())) entries.push_back(entry);
  }
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.path() < b.path(); });
  for (const auto& entry : entries) {
    const bool is_dir = entry.is_directory(ec);
    const std::string label = entry.path().filename().string() + (is_dir ? "/" : "");
    if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_AllowDoubleClick)) {
      open_path_input_ = entry.path().string();
      if (!is_dir && ImGui::IsMouseDoubleClicked(0) && open(entry.path())) show_open_panel_ = false;
    }
  }
  ImGui::EndChild();
  ImGui::TextDisabled("Recent:");
  for (const std::string& path : std::deque<std::string>(recent_)) {
    if (ImGui::Selectable(path.c_str()) && open(path)) show_open_panel_ = false;
  }
  end_dialog(show_open_panel_);
}

void EditorApp::draw_help_panel() {
  const float em = ImGui::GetFontSize();
  if (!begin_dialog("Keys", show_help_, ImVec2(36 * em, 34 * em))) return;
  // The mouse, then the key table (app/key_bindings.h) under a heading per view, a command's other keys beside it.
  const char* const kMouse[][2] = {
      {"click", "select the vertex, edge, halfedge or face under the cursor"},
      {"drag / right drag", "orbit;  middle or Shift+drag: pan;  wheel: zoom"},
  };
  const std::pair<KeyView, const char*> kHeadings[] = {{KeyView::Mesh, "Mesh view"},
                                                       {KeyView::Curve, "Curve view"},
                                                       {KeyView::Patches, "Patch view"},
                                                       {KeyView::Everywhere, "Every view"}};
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
    const auto row = [](const char* keys, const char* text) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(keys);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", text);
    };
    for (const auto& [keys, text] : kMouse) row(keys, text);
    for (const auto& [view, heading] : kHeadings) {
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", heading);
      ImGui::TableNextColumn();
      for (const KeyBinding& b : key_bindings()) {
        if (b.view == view && b.help) row(b.keys, b.help);
      }
    }
    ImGui::EndTable();
  }
  end_dialog(show_help_);
}

void EditorApp::draw_unsaved_code_dialog() {
  const float em = ImGui::GetFontSize();
  // Closed by its X: the student keeps editing.
  if (!begin_dialog("Unsaved code", show_unsaved_code_, ImVec2(30 * em, 8 * em))) return;
  ImGui::TextWrapped("Your code has changes you have not saved: %s.", unsaved_student_files().c_str());
  std::optional<UnsavedCodeAnswer> answer;
  if (ImGui::Button("Save and quit")) answer = UnsavedCodeAnswer::SaveAndQuit;
  ImGui::SameLine();
  if (ImGui::Button("Quit without saving")) answer = UnsavedCodeAnswer::QuitWithoutSaving;
  ImGui::SameLine();
  if (ImGui::Button("Keep editing")) answer = UnsavedCodeAnswer::KeepEditing;
  if (answer) answer_unsaved_code(*answer);
  end_dialog(show_unsaved_code_);
}

}  // namespace meshedit
