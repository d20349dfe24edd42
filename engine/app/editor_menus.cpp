// The menu bar, the open/save dialog (a small file browser with a recent list) and the key help. The menus are the
// command table's (document/command_table.h): its menus in its order, each item with its key beside it, running its
// command as the key and a scripted verb do (EditorApp::run_command); what the table cannot say (an item's check
// mark, whether it is enabled, a label made this frame, a submenu's items) is drawn here. The dialogs are modal and
// centred on the window: nothing else takes input while one is open.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "app/commands.h"
#include "app/editor_app.h"
#include "app/mesh_loading.h"
#include "app/window_host.h"
#include "core/translation.h"
#include "document/document_actions.h"
#include "document/mesh_edits.h"
#include "io/mesh_file.h"
#include "ui/dialog.h"
#include "ui/theme.h"

namespace meshedit {

namespace {

// What a menu item shows besides the table's row: whether it is there at all (the page's own items), enabled,
// checked, and a label made this frame (the next phase's, the student file's) in place of the table's.
struct MenuItemLook {
  bool shown = true;
  bool enabled = true;
  bool checked = false;
  char label[128] = "";  // on the stack: a menu item's label needs no memory
};

// "Subdivide" from "Subdivide > Loop subdivision", as a C string for ImGui.
struct MenuTitle {
  explicit MenuTitle(const Command& c) {
    const std::string_view title = menu_title(c);
    const size_t n = std::min(title.size(), sizeof text - 1);
    std::copy_n(title.data(), n, text);
    text[n] = '\0';
  }
  char text[32];
};

}  // namespace

void EditorApp::draw_menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  std::string_view drawn;  // the menu whose items come now
  bool open = false;
  for (const Command& c : commands()) {
    const std::string_view title = menu_title(c);
    if (title.empty()) continue;
    if (title != drawn) {
      if (open) ImGui::EndMenu();
      drawn = title;
      // Edit and Subdivide act on a mesh: off while the curve or the patch view is on screen.
      const bool on_a_mesh = title == "Edit" || title == "Subdivide";
      const MenuTitle name(c);
      open = ImGui::BeginMenu(tr_label(name.text), !on_a_mesh || mode() == ViewMode::Mesh);
      panels_.probe().record_last_item(std::string("menu:") + name.text);  // where the title is (tests click it)
    }
    if (open) draw_menu_item(c);
  }
  if (open) ImGui::EndMenu();
  ImGui::EndMainMenuBar();
}

void EditorApp::draw_menu_item(const Command& c) {
  using I = CommandId;
  const MeshDocument& doc = document_.doc();
  const ViewOptions& view_options = view_.options();
  const Settings& settings = panels_.settings();
  MenuItemLook look;
  switch (c.id) {
    // A page reaches the student's disk only through the browser's picker; Open... lists the packaged files there.
    case I::OpenFromComputer: look.shown = host_has_file_picker(); break;
    case I::OpenRecent: look.enabled = !document_.recent_files().empty(); break;
    case I::OpenRepaired: look.enabled = document_.can_open_repaired(); break;
    case I::SaveAs: look.enabled = mode() == ViewMode::Mesh; break;
    // A page's student files live in the browser: these take them to and from the student's disk for submission.
    case I::DownloadCode:
      look.shown = !host_files_on_users_disk();
      std::snprintf(
          look.label, sizeof look.label, "%s",
          tr_format("Download your {file}", {{"file", exercises_.session().file().filename().string()}}).c_str());
      break;
    case I::UploadCode: look.shown = !host_files_on_users_disk(); break;
    case I::CheckMyWork:
      look.shown = CheckRoom::available();
      look.enabled = !check_.running();
      break;
    case I::Writeup:
      if (writeup_.running()) std::snprintf(look.label, sizeof look.label, "%s", tr("Stop making the write-up"));
      break;
    case I::Undo: look.enabled = doc.history.can_undo(); break;
    case I::Redo: look.enabled = doc.history.can_redo(); break;
    case I::LoopPhase:
      std::snprintf(look.label, sizeof look.label, "%s",
                    tr_format("Loop: {phase}", {{"phase", tr(next_loop_phase_label(doc))}}).c_str());
      break;
    case I::CatmullClarkPhase:
    case I::LinearPhase: {
      const SubdivisionScheme scheme =
          c.id == I::LinearPhase ? SubdivisionScheme::Linear : SubdivisionScheme::CatmullClark;
      const std::string phase = tr(next_phase_label(scheme, doc, document_.mesh_edits()));
      std::snprintf(look.label, sizeof look.label, "%s", phase.c_str());
      break;
    }
    case I::LoopWeights: look.checked = document_.mesh_edits().loop_weights == LoopWeights::Loop; break;
    case I::Wireframe: look.checked = view_options.wireframe; break;
    case I::Shading: look.checked = view_options.smooth_shading; break;
    case I::Vertices: look.checked = view_options.show_vertices; break;
    case I::HalfedgeArrows: look.checked = view_options.show_halfedges; break;
    case I::Boundary: look.checked = view_options.show_boundary; break;
    case I::IdLabels: look.checked = view_.show_labels(); break;
    case I::AnimateEdits: look.checked = settings.animate_edits; break;
    case I::FoldLeft: look.checked = settings.layout.left_open; break;
    case I::FoldRight: look.checked = settings.layout.right_open; break;
    case I::Inspector: look.checked = panels_.inspector().open; break;
    case I::PointerTables: look.checked = panels_.tables().open; break;
    case I::Exercises: look.checked = exercises_.panel().open; break;
    case I::YourCode: look.checked = exercises_.editor().open; break;
    case I::Console: look.checked = panels_.console_panel().open; break;
    default: break;
  }
  if (!look.shown) return;
  if (c.separator_before) ImGui::Separator();
  // The table's label in the window's language (the path's end ends the C string too); one made this frame as is.
  const char* label = look.label[0] ? look.label : tr_label(menu_label(c).data());
  if (c.submenu) {
    const bool open = ImGui::BeginMenu(label, look.enabled);
    panels_.probe().record_last_item(std::string("menu-item:") + c.name);
    if (open) {
      draw_submenu(c.id);
      ImGui::EndMenu();
    }
    return;
  }
  const bool clicked = ImGui::MenuItem(label, c.key, look.checked, look.enabled);
  panels_.probe().record_last_item(std::string("menu-item:") + c.name);  // each item drawn, where (tests click it)
  if (clicked) run_command(c.id, CommandStart::Menu);
}

void EditorApp::draw_submenu(CommandId id) {
  if (id == CommandId::OpenRecent) {
    for (const std::string& path : std::deque<std::string>(document_.recent_files())) {
      if (ImGui::MenuItem(path.c_str())) open(path);
    }
  } else if (id == CommandId::UpAxis) {  // radio items; each refits the view
    const std::pair<const char*, UpAxisChoice> choices[] = {
        {"From the file", UpAxisChoice::FromFile}, {"Y up", UpAxisChoice::Y}, {"Z up", UpAxisChoice::Z}};
    for (const auto& [label, choice] : choices) {
      if (ImGui::MenuItem(tr_label(label), nullptr, view_.up_axis_choice() == choice)) view_.choose_up_axis(choice);
    }
  } else if (id == CommandId::Language) {
    for (const Language language : kLanguages) {
      if (ImGui::MenuItem(language_name(language), nullptr, text_language() == language))
        panels_.set_language(language);
    }
  } else if (id == CommandId::Theme) {
    constexpr std::pair<const char*, Theme> kThemes[] = {{"Dark", Theme::Dark}, {"Light (projectors)", Theme::Light}};
    for (const auto& [name, theme] : kThemes) {
      if (ImGui::MenuItem(tr_label(name), nullptr, settings().theme == theme) && settings().theme != theme)
        panels_.set_theme(theme);
    }
  }
}

void EditorApp::draw_open_panel() {
  const float em = ImGui::GetFontSize();
  if (!begin_dialog(tr_label("Open or save"), show_open_panel_, ImVec2(40 * em, 30 * em))) return;
  std::string& open_path = document_.open_path_input();
  std::string& save_path = document_.save_path_input();
  if (open_path.empty()) open_path = std::filesystem::current_path().string();
  if (input_path(tr_label("path"), open_path) || ImGui::Button(tr_label("Open"))) {
    if (std::filesystem::is_directory(open_path)) {
      // Entering a folder just lists it.
    } else if (open(open_path)) {
      show_open_panel_ = false;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button(tr_label("Assets"))) open_path = assets_dir().string();
  if (host_has_file_picker()) {
    ImGui::SameLine();
    if (ImGui::Button(tr_label("From this computer..."))) {
      host_show_file_picker();
      show_open_panel_ = false;
    }
  }
  if (mode() == ViewMode::Mesh) {
    input_path(tr_label("save as"), save_path);
    ImGui::SameLine();
    if (ImGui::Button(tr_label("Save")) && !save_path.empty()) document_.save(save_path);
    ImGui::TextDisabled("%s", list_extensions(writable_extensions(), ", ", " or ").c_str());
  }
  ImGui::Separator();

  // The folder of the path typed so far (or the path itself if it is a folder).
  std::filesystem::path folder = open_path;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) folder = folder.parent_path();
  ImGui::BeginChild("listing", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 4));
  if (ImGui::Selectable("..")) open_path = folder.parent_path().string();
  std::vector<std::filesystem::directory_entry> entries;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    if (entry.is_directory(ec) || is_readable(entry.path())) entries.push_back(entry);
  }
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.path() < b.path(); });
  for (const auto& entry : entries) {
    const bool is_dir = entry.is_directory(ec);
    const std::string label = entry.path().filename().string() + (is_dir ? "/" : "");
    if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_AllowDoubleClick)) {
      open_path = entry.path().string();
      if (!is_dir && ImGui::IsMouseDoubleClicked(0) && open(entry.path())) show_open_panel_ = false;
    }
  }
  ImGui::EndChild();
  ImGui::TextDisabled("%s", tr("Recent:"));
  for (const std::string& path : std::deque<std::string>(document_.recent_files())) {
    if (ImGui::Selectable(path.c_str()) && open(path)) show_open_panel_ = false;
  }
  end_dialog(show_open_panel_);
}

void EditorApp::draw_help_panel() {
  const float em = ImGui::GetFontSize();
  if (!begin_dialog(tr_label("Keys"), show_help_, ImVec2(36 * em, 34 * em))) return;
  // The mouse, then the command table's keys (document/command_table.h) under a heading per view; the texts in the
  // window's language, the key names as the table writes them.
  static const char* const kMouse[][2] = {
      {"click", "select the vertex, edge, halfedge or face under the cursor"},
      {"drag / right drag", "orbit;  middle or Shift+drag: pan;  wheel: zoom"},
  };
  static const std::pair<CommandView, const char*> kHeadings[] = {{CommandView::Mesh, "Mesh view"},
                                                                  {CommandView::Curve, "Curve view"},
                                                                  {CommandView::Patches, "Patch view"},
                                                                  {CommandView::Everywhere, "Every view"}};
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
    const auto row = [](const char* keys, const char* text) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(keys);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", tr(text));
    };
    for (const auto& [keys, text] : kMouse) row(tr(keys), text);
    for (const auto& [view, heading] : kHeadings) {
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", tr(heading));
      ImGui::TableNextColumn();
      for (const Command& c : commands()) {
        if (c.view == view && c.key) row(c.key, c.help);
      }
    }
    ImGui::EndTable();
  }
  end_dialog(show_help_);
}

void EditorApp::draw_unsaved_code_dialog() {
  const float em = ImGui::GetFontSize();
  // Closed by its X: the student keeps editing.
  if (!begin_dialog(tr_label("Unsaved code"), show_unsaved_code_, ImVec2(30 * em, 8 * em))) return;
  ImGui::TextWrapped("%s", tr_format("Your code has changes you have not saved: {files}.",
                                     {{"files", exercises_.unsaved_student_files()}})
                               .c_str());
  std::optional<UnsavedCodeAnswer> answer;
  if (ImGui::Button(tr_label("Save and quit"))) answer = UnsavedCodeAnswer::SaveAndQuit;
  ImGui::SameLine();
  if (ImGui::Button(tr_label("Quit without saving"))) answer = UnsavedCodeAnswer::QuitWithoutSaving;
  ImGui::SameLine();
  if (ImGui::Button(tr_label("Keep editing"))) answer = UnsavedCodeAnswer::KeepEditing;
  if (answer) answer_unsaved_code(*answer);
  end_dialog(show_unsaved_code_);
}

}  // namespace meshedit
