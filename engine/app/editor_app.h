// EditorApp: the window's application, as rooms with one job each, and one frame of it. It owns the rooms and wires
// them; each room's header says what it owns:
//   DocumentRoom  (document_room.h)    the open document, its selection and its files: title, recent list, repairs
//   ViewRoom      (view_room.h)        the mesh, curve and patch views, the camera, the renderers, the up axis
//   ExerciseRoom  (exercise_room.h)    the Exercises tab and the student's code (Your code)
//   CheckRoom     (check_room.h)       File > Check my work: the grader run beside the window, and the Check tab
//   WriteupRoom   (writeup_room.h)     File > Write-up: `meshedit writeup` beside the window, the view it uses
//   BugReportRoom (bug_report_room.h)  Help > Save a bug report: what the window shows, for a TA
//   LessonRoom    (lesson_room.h)      the lesson being run, its panel and what it lays over the view
//   InputRoom     (input_room.h)       the mouse and the keys
//   PanelsRoom    (panels_room.h)      the columns, the console, the settings and the look
// What crosses rooms is here: opening files (editor_files.cpp), the commands of the menus, keys and scripted verbs
// (editor_commands.cpp, editor_menus.cpp), the dialogs, your_turn's mine vs reference (editor_your_turn.cpp), closing.
//
// Invariants:
// - One input path: real keys and clicks (read from ImGui's io each frame) and scripted actions (scripted_actions.h)
//   both call handle_key / click / hover, so GUI tests exercise what users do; a menu item, a key and a scripted verb
//   run a command of the table (document/command_table.h) through the one run_command.
// - Opening a file is whole or nothing: the document (or the curve or patch view), the view mode, the window title
//   and the recent list all change to the file's, or none does and the status line says why, memory running out
//   included. open(), save(), write_pending_screenshot() and finish_pending_writeup() never throw.
// - The window starts with the default cube (show_start_mesh). When memory runs out making or showing it, the window
//   opens all the same, empty (no mesh, the title "MeshEdit"), with an Error in the status line that says memory ran
//   out. Only running out while the app itself is made (its renderers, shaders and panels: the constructor) ends the
//   program, before the window shows anything, with the error on stderr (cli.cpp).
// - An exception that escapes a frame's handlers is an Error in the status line (ui/frame_guard.h), never thrown.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/bug_report_room.h"
#include "app/check_room.h"
#include "app/commands.h"
#include "app/document_room.h"
#include "app/exercise_room.h"
#include "app/input_room.h"
#include "app/lesson_room.h"
#include "app/panels_room.h"
#include "app/view_room.h"
#include "app/writeup_room.h"

namespace meshedit {

class EditorApp {
 public:
  EditorApp();  // needs a current OpenGL 3.3 core context (throws RenderError if the shaders are missing)
  ~EditorApp();
  EditorApp(const EditorApp&) = delete;
  EditorApp& operator=(const EditorApp&) = delete;

  DocumentRoom& document_room() { return document_; }
  const DocumentRoom& document_room() const { return document_; }
  ViewRoom& view() { return view_; }
  const ViewRoom& view() const { return view_; }
  ExerciseRoom& exercise_room() { return exercises_; }
  CheckRoom& check_room() { return check_; }
  WriteupRoom& writeup_room() { return writeup_; }
  BugReportRoom& bug_report_room() { return bug_report_; }
  LessonRoom& lessons() { return lessons_; }
  InputRoom& input() { return input_; }
  PanelsRoom& panels() { return panels_; }
  const PanelsRoom& panels() const { return panels_; }
  // What most callers want of the rooms.
  MeshDocument& document() { return document_.doc(); }
  Selection& selection() { return document_.selection(); }
  LessonRunner& lesson() { return lessons_.runner(); }
  ExerciseSession& exercises() { return exercises_.session(); }
  ViewMode mode() const { return view_.mode(); }
  const std::string& title() const { return document_.title(); }
  const Settings& settings() const { return panels_.settings(); }

  // Opens any supported file (a .lua as a lesson): shows it, names it in the title and puts it first in the recent
  // list, or keeps all of them as they were and reports the error. Returns whether it opened.
  bool open(const std::filesystem::path& path);
  // Opens a repaired copy (core/mesh_repair.h) of the last mesh file open() refused as not a manifold, whole or nothing
  // as open(): the status line gives the repair's summary and the Repairs tab (in front) lists every change, its spots
  // highlighted in the view. The copy is named "FILE (repaired)"; the file itself is not touched.
  bool open_repaired();
  // Opens a bug report (document/bug_report.h) as the student saw it (editor_bug_report.cpp): its lesson at its step,
  // its mesh with its ids and selection, and its code in a folder of its own that the Exercises tab then runs; a run
  // the mesh is still the result of is run again on its input. Refused with an Error naming the file (and its line)
  // with the window as it was; never throws.
  bool open_bug_report(const std::filesystem::path& path);
  // The Repairs tab's row `row` clicked: selects its first spot; refused with a Warning
  // (DocumentRoom::click_repair_row).
  bool click_repair_row(size_t row);
  bool repair_spots_current() const;  // the spots are the shown mesh's: highlighted, and the rows select
  // The files dropped on the window, each opened as open() does. Never throws.
  void open_dropped(const std::vector<std::string>& paths);
  // The files a page's student picked or dropped: a student file replaces its file (ExerciseRoom::take_received_file,
  // Your code then in front); the rest open as dropped files do.
  void receive_files(const std::vector<std::string>& paths);
  // Shows `mesh` as a new document named `name` ("untitled" in the title when empty), or throws with nothing changed.
  void show_mesh(HalfedgeMesh mesh, const std::string& name);
  // The default cube, as the window starts. Never throws: out of memory, the window starts empty with an Error.
  void show_start_mesh();
  // The lesson panel's "Show mine vs reference" (editor_your_turn.cpp): the run of the your_turn the step waits on
  // with a wrong answer, shown where the window compares runs. Refused (a Warning) when there is none; never throws.
  Check show_your_turn_mine();
  // The Check tab's "Open in Exercises" of row `row` (editor_check.cpp): the failed test's input as a new document,
  // its element selected, and the student's function run on it in the Exercises tab. Refused (a Warning) when the row
  // has no case; never throws.
  Check open_failing_case(size_t row);

  // One frame: reads input from ImGui's io, draws the view into the current framebuffer of the given size, and builds
  // the panels. Call between ImGui::NewFrame() and ImGui::Render().
  void frame(int framebuffer_width, int framebuffer_height, float frame_ms);
  // True while something on screen moves by itself (a lesson animation, an edit playing) or a hover waits for the mouse
  // to rest: the window must not sleep.
  bool animating() const;
  bool edits_animate() const { return view_.edits_animate(panels_.settings().animate_edits); }
  // A key press (a GLFW key code): runs the command of that key in the view shown and tells a lesson the key; returns
  // whether some command has that key.
  bool handle_key(int key, KeyMods mods);
  // Runs a command of the table as its menu item, its key or a scripted verb does; returns whether it was done, or why
  // not.
  Check run_command(CommandId id, CommandStart start = CommandStart::Script);
  // A left click at pixel (x, y) of the view (framebuffer pixels, top-left origin): selects what is under it (or
  // clears the selection) and tells a lesson.
  void click(int x, int y);
  // Opens the console and runs `code` in it, as if typed there and Enter pressed.
  void run_console(const std::string& code);
  // View > Your code: opens the tab and the right column, the tab in front next frame.
  void show_student_code();

  // Asks for a PNG of the whole window (view and panels) after the current frame is drawn; the window writes it
  // between ImGui's rendering and the buffer swap.
  void request_screenshot(const std::filesystem::path& path) { screenshot_path_ = path; }
  void write_pending_screenshot(int width, int height);
  // What the window does between ImGui's rendering and the buffer swap: the two below. Never throws.
  void after_rendering(int width, int height) {
    write_pending_screenshot(width, height);
    finish_pending_writeup();
  }
  // A page's write-up its worker made: its pictures drawn and index.html downloaded (WriteupRoom::finish_made), written
  // between ImGui's rendering and the buffer swap as the screenshot is; nothing on the desktop. Never throws.
  void finish_pending_writeup();
  // A new size for the window (the `window-size` action): the window loop applies it before the next frame.
  void request_window_size(int width, int height) { window_size_request_ = {width, height}; }
  std::optional<std::pair<int, int>> take_window_size_request() { return std::exchange(window_size_request_, {}); }

  bool quit_requested() const { return quit_requested_; }
  // Whether the window may close now (its close button, Ctrl+Q, File > Quit). Not while Your code holds unsaved text
  // of a file on the user's disk: then the Unsaved code dialog asks, and the window closes once the student chose. A
  // page never asks: its unsaved text is kept as a draft (window_host.h).
  bool may_close();
  enum class UnsavedCodeAnswer { SaveAndQuit, QuitWithoutSaving, KeepEditing };
  void answer_unsaved_code(UnsavedCodeAnswer answer);
  bool asking_about_unsaved_code() const { return show_unsaved_code_; }

 private:
  void run_frame(int width, int height, float frame_ms);  // frame() without its guard
  void read_input();
  // Switches the window to a prepared file with steps that cannot fail: the view (and the document), then the title,
  // the recent list and the message.
  void take_file(PreparedFile& file) noexcept;
  Check carry_out(CommandId id, CommandStart start);  // what each command does: run_command without its bookkeeping
  void bring_exercises_tab_forward();                 // opens the Exercises tab, in front next frame
  // The menu bar (the command table's menus and items in its order) and the dialogs (editor_menus.cpp).
  void draw_menu_bar();
  void draw_menu_item(const Command& command);
  void draw_submenu(CommandId id);  // Open recent, Up axis, Theme
  void draw_open_panel();
  void draw_help_panel();
  void draw_unsaved_code_dialog();

  DocumentRoom document_;
  ViewRoom view_;
  ExerciseRoom exercises_;
  CheckRoom check_;
  WriteupRoom writeup_;
  LessonRoom lessons_;
  BugReportRoom bug_report_{document_, exercises_, lessons_, view_};
  InputRoom input_;
  PanelsRoom panels_;
  bool show_open_panel_ = false;
  bool show_help_ = false;
  bool show_unsaved_code_ = false;  // the Unsaved code dialog is up (may_close)
  bool close_confirmed_ = false;    // the student chose to quit with (or after saving) the unsaved code
  bool quit_requested_ = false;
  std::optional<std::filesystem::path> screenshot_path_;
  std::optional<std::pair<int, int>> window_size_request_;
};

}  // namespace meshedit
