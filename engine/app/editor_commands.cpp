// EditorApp and the command table (document/command_table.h): run_command, the one way every command runs, whether
// its menu item was clicked, its key pressed or a scripted verb named it; carry_out, one case per command, is what
// each does; handle_key, the key presses.
//
// Invariants: a command that edits (the table's `edits`) finishes a running exercise replay first, so no edit lands
// in a half-replayed history; a command a lesson can wait for tells the lesson its name when it ran, and every
// command with a key tells the lesson that key (a key press tells it itself, bound or not), after the command acted,
// so a lesson that waits for F sees the flipped mesh. The mesh edits are document/mesh_edits.h's run_mesh_edit, the
// function the headless lesson driver's answers run.
#include <GLFW/glfw3.h>

#include <chrono>
#include <ctime>

#include "app/editor_app.h"
#include "app/window_host.h"
#include "document/document_actions.h"

namespace meshedit {
namespace {

std::string timestamped_screenshot_name() {
  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "meshedit-%Y%m%d-%H%M%S.png", std::localtime(&now));
  return buffer;
}

Check toggled(bool& value) {
  value = !value;
  return Check::yes();
}

}  // namespace

Check EditorApp::run_command(CommandId id, CommandStart start) {
  const Command& c = command(id);
  if (c.edits) exercises_.finish_replay(doc_);
  Check done = carry_out(id, start);
  if (lesson_->loaded()) {
    if (done && c.lesson_can_wait) lesson_->deliver(LessonEvent::command(c.name));
    if (start != CommandStart::Key) {
      if (const std::optional<KeyChord> key = command_key(c)) tell_lesson_key(key->key, key->mods);
    }
  }
  return done;
}

bool EditorApp::handle_key(int key, KeyMods mods) {
  const CommandView view = mode_ == ViewMode::Mesh    ? CommandView::Mesh
                           : mode_ == ViewMode::Curve ? CommandView::Curve
                                                      : CommandView::Patches;
  const Command* found = find_key_command(key, mods, view);
  if (found) run_command(found->id, CommandStart::Key);
  tell_lesson_key(key, mods);
  return found != nullptr;
}

void EditorApp::tell_lesson_key(int key, KeyMods mods) {
  if (!lesson_->loaded()) return;
  const std::string name = lesson_key_name(key, mods);
  if (!name.empty()) lesson_->deliver(LessonEvent::key(name));
}

// One case per command of the table (document/command_table.h), which -Wswitch holds complete: the dispatch is as
// long as the table, however small each case is.
Check EditorApp::carry_out(CommandId id, CommandStart start) {  // NOLINT(readability-function-size)
  using I = CommandId;
  const auto said = [this](bool ok) { return ok ? Check::yes() : Check::no(doc_.message.text); };
  switch (id) {
    case I::OpenFromComputer:
    case I::UploadCode: host_show_file_picker(); return Check::yes();
    case I::Open:
    case I::SaveAs: show_open_panel_ = true; return Check::yes();
    case I::OpenRecent:
    case I::UpAxis:
    case I::Theme: return Check::no(std::string(command(id).menu) + " is a submenu");
    case I::OpenRepaired: return said(open_repaired());
    case I::Screenshot:
      // The menu's name is the one a page's browser downloads; a key press names each picture by its time.
      request_screenshot(start == CommandStart::Key ? timestamped_screenshot_name() : "meshedit-screenshot.png");
      return Check::yes();
    case I::DownloadCode: download_student_code(); return Check::yes();
    case I::Quit: quit_requested_ = true; return Check::yes();
    case I::Undo: return said(undo_edit(doc_, selection_));
    case I::Redo: return said(redo_edit(doc_, selection_));
    case I::Flip:
      // The key F on a halfedge walks to its face; on an edge (the course's use), and from the menu, it flips.
      if (start == CommandStart::Key && selection_.selected.valid() &&
          selection_.selected.kind == ElementKind::Halfedge) {
        return said(navigate_selection(doc_, selection_, NavStep::Face));
      }
      return run_mesh_edit(id, doc_, selection_, mesh_edits_);
    case I::Split:
    case I::Collapse:
    case I::Triangulate:
    case I::Loop:
    case I::LoopPhase:
    case I::CatmullClark:
    case I::CatmullClarkPhase:
    case I::Linear:
    case I::LinearPhase: return run_mesh_edit(id, doc_, selection_, mesh_edits_);
    case I::LoopWeights:
      mesh_edits_.loop_weights =
          mesh_edits_.loop_weights == LoopWeights::Loop ? LoopWeights::Course : LoopWeights::Loop;
      return Check::yes();
    case I::Wireframe: return toggled(view_options_.wireframe);
    case I::Shading: return toggled(view_options_.smooth_shading);
    case I::Vertices: return toggled(view_options_.show_vertices);
    case I::HalfedgeArrows: return toggled(view_options_.show_halfedges);
    case I::Boundary: return toggled(view_options_.show_boundary);
    case I::IdLabels: return toggled(show_labels_);
    case I::AnimateEdits: return toggled(settings_.animate_edits);  // flip, split, collapse, their undo, redo
    case I::FoldLeft: return toggled(settings_.layout.left_open);
    case I::FoldRight: return toggled(settings_.layout.right_open);
    case I::Inspector:
      inspector_.open = !inspector_.open;
      if (inspector_.open) {
        select_tab_ = RightTab::Inspector;
        // The inspector is a tab on the right while a lesson has the left column, else on the left: unfold it.
        bool& column_open = lesson_->loaded() ? settings_.layout.right_open : settings_.layout.left_open;
        column_open = true;
      }
      return Check::yes();
    case I::PointerTables: return toggled(tables_.open);
    case I::Exercises:
      if (exercise_panel_.open) exercise_panel_.open = false;
      else bring_exercises_tab_forward();
      return Check::yes();
    case I::YourCode:
      if (student_editor_.open) student_editor_.open = false;
      else show_student_code();
      return Check::yes();
    case I::Console:
      console_panel_.open = !console_panel_.open;
      console_panel_.focus_input = console_panel_.open;
      return Check::yes();
    case I::BiggerText: change_font_size(+1); return Check::yes();
    case I::SmallerText: change_font_size(-1); return Check::yes();
    case I::DefaultText: change_font_size(0); return Check::yes();
    case I::ResetView: reset_view(); return Check::yes();
    case I::Keys: return toggled(show_help_);
    case I::ClearSelection: selection_.selected = {}; return Check::yes();
    case I::Next: return said(navigate_selection(doc_, selection_, NavStep::Next));
    case I::Twin: return said(navigate_selection(doc_, selection_, NavStep::Twin));
    case I::Vertex: return said(navigate_selection(doc_, selection_, NavStep::Vertex));
    case I::Edge: return said(navigate_selection(doc_, selection_, NavStep::Edge));
    case I::Halfedge: return said(navigate_selection(doc_, selection_, NavStep::Halfedge));
    case I::CurveStep: step_level(curve_); return Check::yes();
    case I::CurveToggle: toggle_curve(curve_); return Check::yes();
    case I::CurveMine: bezier_mine_.set_curve_on(!bezier_mine_.curve_on()); return Check::yes();
    case I::PatchMine: bezier_mine_.set_patch_on(!bezier_mine_.patch_on()); return Check::yes();
  }
  return Check::no("no such command");
}

}  // namespace meshedit
