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
  if (c.edits) exercises_.session().finish_replay(document_.doc());
  Check done = carry_out(id, start);
  if (done && c.lesson_can_wait) lessons_.tell_command(c.name);
  if (start != CommandStart::Key) {
    if (const std::optional<KeyChord> key = command_key(c)) lessons_.tell_key(key->key, key->mods);
  }
  return done;
}

bool EditorApp::handle_key(int key, KeyMods mods) {
  const CommandView view = mode() == ViewMode::Mesh    ? CommandView::Mesh
                           : mode() == ViewMode::Curve ? CommandView::Curve
                                                       : CommandView::Patches;
  const Command* found = find_key_command(key, mods, view);
  if (found) run_command(found->id, CommandStart::Key);
  lessons_.tell_key(key, mods);
  return found != nullptr;
}

// One case per command of the table (document/command_table.h), which -Wswitch holds complete: the dispatch is as
// long as the table, however small each case is.
Check EditorApp::carry_out(CommandId id, CommandStart start) {  // NOLINT(readability-function-size)
  using I = CommandId;
  MeshDocument& doc = document_.doc();
  Selection& selection = document_.selection();
  MeshEditState& mesh_edits = document_.mesh_edits();
  ViewOptions& view_options = view_.options();
  Settings& settings = panels_.settings();
  CurveEditorState& curve = view_.curve();
  BezierMine& bezier_mine = view_.bezier_mine();
  const auto said = [&doc](bool ok) { return ok ? Check::yes() : Check::no(doc.message.text); };
  switch (id) {
    case I::OpenFromComputer:
    case I::UploadCode: host_show_file_picker(); return Check::yes();
    case I::Open:
    case I::SaveAs: show_open_panel_ = true; return Check::yes();
    case I::OpenRecent:
    case I::UpAxis:
    case I::Theme:
    case I::Language: return Check::no(std::string(command(id).menu) + " is a submenu");
    case I::OpenRepaired: return said(open_repaired());
    case I::Screenshot:
      // The menu's name is the one a page's browser downloads; a key press names each picture by its time.
      request_screenshot(start == CommandStart::Key ? timestamped_screenshot_name() : "meshedit-screenshot.png");
      return Check::yes();
    case I::DownloadCode: exercises_.download_student_code(); return Check::yes();
    case I::CheckMyWork: {
      const Check started = check_.start();
      panels_.bring_forward(RightTab::Check);
      return started;
    }
    case I::Writeup:  // while one is being made, the item stops it
      if (writeup_.running()) {
        writeup_.stop();
        return Check::yes();
      }
      return writeup_.start();
    case I::WriteupView: return writeup_.save_view();
    case I::Quit: quit_requested_ = true; return Check::yes();
    case I::Undo: return said(undo_edit(doc, selection));
    case I::Redo: return said(redo_edit(doc, selection));
    case I::Flip:
      // The key F on a halfedge walks to its face; on an edge (the course's use), and from the menu, it flips.
      if (start == CommandStart::Key && selection.selected.valid() &&
          selection.selected.kind == ElementKind::Halfedge) {
        return said(navigate_selection(doc, selection, NavStep::Face));
      }
      return run_mesh_edit(id, doc, selection, mesh_edits);
    case I::Split:
    case I::Collapse:
    case I::Triangulate:
    case I::Loop:
    case I::LoopPhase:
    case I::CatmullClark:
    case I::CatmullClarkPhase:
    case I::Linear:
    case I::LinearPhase: return run_mesh_edit(id, doc, selection, mesh_edits);
    case I::LoopWeights:
      mesh_edits.loop_weights = mesh_edits.loop_weights == LoopWeights::Loop ? LoopWeights::Course : LoopWeights::Loop;
      return Check::yes();
    case I::Wireframe: return toggled(view_options.wireframe);
    case I::Shading: return toggled(view_options.smooth_shading);
    case I::Vertices: return toggled(view_options.show_vertices);
    case I::HalfedgeArrows: return toggled(view_options.show_halfedges);
    case I::Boundary: return toggled(view_options.show_boundary);
    case I::IdLabels: return toggled(view_.show_labels());
    case I::AnimateEdits: return toggled(settings.animate_edits);  // flip, split, collapse, their undo, redo
    case I::FoldLeft: return toggled(settings.layout.left_open);
    case I::FoldRight: return toggled(settings.layout.right_open);
    case I::Inspector: {
      bool& open = panels_.inspector().open;
      open = !open;
      if (open) {
        // The inspector is a tab on the right while a lesson has the left column, else on the left: unfold it.
        if (lesson().loaded()) panels_.bring_forward(RightTab::Inspector);
        else settings.layout.left_open = true;
      }
      return Check::yes();
    }
    case I::PointerTables: return toggled(panels_.tables().open);
    case I::Exercises:
      if (exercises_.panel().open) exercises_.panel().open = false;
      else bring_exercises_tab_forward();
      return Check::yes();
    case I::YourCode:
      if (exercises_.editor().open) exercises_.editor().open = false;
      else show_student_code();
      return Check::yes();
    case I::Console: {
      ConsolePanelState& console = panels_.console_panel();
      console.open = !console.open;
      console.focus_input = console.open;
      return Check::yes();
    }
    case I::BiggerText: panels_.change_font_size(+1); return Check::yes();
    case I::SmallerText: panels_.change_font_size(-1); return Check::yes();
    case I::DefaultText: panels_.change_font_size(0); return Check::yes();
    case I::ResetView: view_.reset_view(); return Check::yes();
    case I::Keys: return toggled(show_help_);
    case I::BugReport: bug_report_.open_dialog(); return Check::yes();
    case I::ClearSelection: selection.selected = {}; return Check::yes();
    case I::Next: return said(navigate_selection(doc, selection, NavStep::Next));
    case I::Twin: return said(navigate_selection(doc, selection, NavStep::Twin));
    case I::Vertex: return said(navigate_selection(doc, selection, NavStep::Vertex));
    case I::Edge: return said(navigate_selection(doc, selection, NavStep::Edge));
    case I::Halfedge: return said(navigate_selection(doc, selection, NavStep::Halfedge));
    case I::CurveStep: step_level(curve); return Check::yes();
    case I::CurveToggle: toggle_curve(curve); return Check::yes();
    case I::CurveMine: bezier_mine.set_curve_on(!bezier_mine.curve_on()); return Check::yes();
    case I::PatchMine: bezier_mine.set_patch_on(!bezier_mine.patch_on()); return Check::yes();
  }
  return Check::no("no such command");
}

}  // namespace meshedit
