// EditorApp: the window's application state and one frame of it. Owns the document being edited (a mesh,
// a curve or a set of patches), the camera, the renderers and every panel's state; wires the keys and the
// mouse to the core through engine/document's actions.
//
// Invariants:
// - One input path: real keys and clicks (read from ImGui's io each frame) and scripted actions
//   (scripted_actions.h) both call handle_key / click / hover, so GUI tests exercise what users do; a menu item, a
//   key and a scripted verb run a command of the table (document/command_table.h) through the one run_command.
// - Opening a file is whole or nothing: the document (or the curve or patch view), the view mode, the window title
//   and the recent list all change to the file's, or none does and the status line says why, memory running out
//   included (everything that can fail is made before anything changes: editor_files.cpp). show_mesh, show_curve and
//   show_patches are whole or nothing too, and throw what stopped them. A file saved is reported saved and put first
//   in the recent list; one not saved changes neither (saving makes both before writing). open(), save() and
//   write_pending_screenshot() never throw: their report of a failure falls back to kMemoryRanOut, which needs no
//   memory (document/exception_report.h).
// - The window starts with the default cube (show_start_mesh). When memory runs out making or showing it, the window
//   opens all the same, empty (no mesh, the title "MeshEdit"), with an Error in the status line that says memory ran
//   out; it works as usual from there, and a file named on the command line is still opened. Only running out while
//   the app itself is made (its renderers, shaders and panels: the constructor) ends the program, before the window
//   shows anything, with the error on stderr (cli.cpp).
// - A mesh too large to draw (past the GPU's buffer limits) is refused by the renderer once per mesh state: an Error
//   and the status bar say so, the view stays empty, and every panel, key and menu works on (undo brings back a mesh
//   that can be drawn); frames do not retry until the mesh changes.
// - A broken mesh (a Lua script's doing) can be drawn, inspected and validated: nothing here walks
//   the mesh except through the core's and the renderer's bounded walks.
// - GL objects are created after the window's context exists and destroyed before it goes.
// - An edit playing (app/edit_animator.h, only under a policy that allows it: never in tests, pictures or scripted
//   runs) is drawn over the mesh as it is after the edit; meanwhile the selection, changed and lesson highlights wait
//   for it to land.
// - The layout is fixed (document/window_layout.h): menu bar, status bar, the left and right columns, the console
//   strip, and the view in the free centre. The mesh, patch and curve views draw only into the view rectangle (GL
//   viewport and scissor set to it, the camera's aspect and picking in its pixels); no panel is drawn over the view
//   or a column except the modal dialogs (open, keys) and menus. Picking pixels (click, hover) are framebuffer
//   pixels relative to the view's top-left corner.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "app/commands.h"
#include "app/edit_animator.h"
#include "app/repair_marks.h"
#include "app/up_axis_choice.h"
#include "app/view_quality.h"
#include "app/window_lesson_host.h"
#include "core/bezier.h"
#include "document/bezier_mine.h"
#include "document/mesh_document.h"
#include "document/mesh_edits.h"
#include "document/selection.h"
#include "document/settings.h"
#include "document/student_edit.h"
#include "document/window_layout.h"
#include "lesson/lesson_runner.h"
#include "render/camera.h"
#include "render/label_placement.h"
#include "render/mesh_renderer.h"
#include "render/overlay_renderer.h"
#include "render/shader_library.h"
#include "render/view_options.h"
#include "ui/curve_editor.h"
#include "ui/exercise_panel.h"
#include "ui/fonts.h"
#include "ui/inspector.h"
#include "ui/lesson_panel.h"
#include "ui/patch_view.h"
#include "ui/pointer_tables.h"
#include "ui/script_console.h"
#include "ui/status_bar.h"
#include "ui/student_editor.h"

namespace meshedit {

enum class ViewMode { Mesh, Curve, Patches };

class EditorApp {
 public:
  EditorApp();  // needs a current OpenGL 3.3 core context (throws RenderError if the shaders are missing)
  ~EditorApp();

  // Opens any supported file: shows it, names it in the title and puts it first in the recent list. On failure
  // keeps all of them as they were and reports the error. Returns whether it opened.
  bool open(const std::filesystem::path& path);
  // Opens a repaired copy (core/mesh_repair.h) of the last mesh file open() refused as not a manifold, whole or
  // nothing as open(): the status line gives the repair's summary and the Repairs tab (in front) lists every change
  // with the file's numbers, its spots highlighted in the view. The copy is named "FILE (repaired)"; the file itself
  // is not touched. Returns whether it opened.
  bool open_repaired();
  // The Repairs tab's row `row` (0: the first change) clicked: selects the row's first spot (a vertex, else a face) in
  // the repaired mesh. Refused (false, a Warning in the status line, the selection kept) when there is no such row,
  // the row has no spot, or the spots are stale (app/repair_marks.h: another file, or the mesh edited).
  bool click_repair_row(size_t row);
  const RepairMarks& repair_marks() const { return repairs_; }
  bool repair_spots_current() const;  // the spots are the shown mesh's: highlighted, and the rows select
  // Opens the files dropped on the window, in turn, each as open() does: the status line tells the last one's outcome.
  // Never throws: what escapes opening a file is an Error in the status line (document/exception_report.h).
  void open_dropped(const std::vector<std::string>& paths);
  // Shows `mesh` as a new document named `name` ("untitled" in the title when empty), or throws with nothing changed.
  void show_mesh(HalfedgeMesh mesh, const std::string& name);
  // What the window shows as it starts, before the file it was given (if any) is opened: the default cube. Never
  // throws: out of memory, the window starts empty, with an Error that says so (see the invariants).
  void show_start_mesh();
  // What lessons show (window_lesson_host.h): a mesh (fitting the camera only when asked; `up` as show{up=} says, else
  // Z), a curve, patches. Each is whole or nothing, as show_mesh: what stops it (memory running out) is thrown with
  // the window unchanged.
  void show_lesson_mesh(const HalfedgeMesh& mesh, bool fit, std::optional<UpAxis> up = std::nullopt);
  void show_curve(const BezierCurve& curve);
  void show_patches(const std::vector<BezierPatch>& patches);
  // A lesson's view{...}: turns the parts it names on or off.
  void apply_view_request(const ViewRequest& request);

  // Loads a lesson file into the lesson panel (also what open() does with a .lua file), whole or nothing: the lesson
  // runs, the title names it and the status line says so; or the lesson that ran goes on under its title, and the
  // status line and the panel say why not (file:line, or that memory ran out). Never throws. Returns whether it
  // loaded.
  bool open_lesson(const std::filesystem::path& path);
  // Loads the running lesson's file again at its step (the panel's Reload and hot reload), whole or nothing: the new
  // version runs and, while the window is titled after the lesson, the title follows its new lesson{title=}; or the
  // version that ran goes on under its title, and the panel says why (file:line, or that memory ran out; the status
  // line says so when memory ran out making the title). Never throws.
  ReloadOutcome reload_lesson();
  // The lesson panel's "Lessons": leaves the lesson for the list of lessons, with a fresh runner, whole or nothing:
  // the lesson, its highlights and labels all go, or (memory ran out making the runner) all stay and the exception is
  // thrown (the frame guard reports it).
  void show_lesson_list();
  // The lesson panel's "Show mine vs reference" (app/editor_your_turn.cpp): the run of the your_turn the step waits on
  // with a wrong answer, shown where the window compares runs: for a mesh exercise its input in the document, its
  // element selected, mine run on it by the Exercises tab, brought to the front; for the curve and patch exercises its
  // input in the view with "mine" on. Refused (a Warning) when the step waits on no wrong your_turn; never throws.
  Check show_your_turn_mine();
  LessonRunner& lesson() { return *lesson_; }
  const LessonMarks& lesson_marks() const { return lesson_host_->marks(); }  // the lesson's highlights and labels
  // True while something on screen moves by itself (a lesson animation, an edit playing) or a hover waits for the mouse
  // to rest: the window must not sleep.
  bool animating() const;
  // Whether flips, splits and collapses, and their undo and redo, play for a quarter second (app/edit_animator.h):
  // never (the default: tests, pictures and scripted runs), as View > Animate edits says (the interactive window), or
  // always (a scripted run's `animate-edits on`).
  enum class EditAnimationPolicy { Never, AsSettingSays, Always };
  void set_edit_animation_policy(EditAnimationPolicy policy) { edit_animation_policy_ = policy; }
  // The mesh view at full quality whatever its frames cost (true), or the quality governor's choice (false).
  void hold_full_quality(bool hold) { view_quality_.hold_full(hold, view_options_); }
  bool edits_animate() const;
  const EditAnimator& edit_animator() const { return edit_animator_; }

  // One frame: reads input from ImGui's io, draws the 3D view into the current framebuffer of the given
  // size, and builds the panels. Call between ImGui::NewFrame() and ImGui::Render(). An exception that escapes
  // the frame's handlers is shown as an Error in the status line (ui/frame_guard.h), never thrown from here.
  void frame(int framebuffer_width, int framebuffer_height, float frame_ms);

  // A key press (a GLFW key code): runs the command of that key in the view shown (app/commands.h) and tells a lesson
  // the key; returns whether some command has that key.
  bool handle_key(int key, KeyMods mods);
  // Runs a command of the table (document/command_table.h) as its menu item, its key or a scripted verb does
  // (editor_commands.cpp); returns whether it was done, or why not.
  Check run_command(CommandId id, CommandStart start = CommandStart::Script);
  // A left click at pixel (x, y) of the view (framebuffer pixels, top-left origin): selects what is under it (or
  // clears the selection).
  void click(int x, int y);
  void hover(int x, int y);
  // Where the element's label anchor (a vertex's position, an edge's midpoint...) is in the view's pixels; nullopt
  // when it is dead, behind the eye or outside the view.
  std::optional<ScreenPoint> element_pixel(ElementRef element) const;

  // The settings that last between runs (document/settings.h): apply_settings takes them at start; the window saves
  // settings() when it closes.
  void apply_settings(const Settings& settings);
  const Settings& settings() const { return settings_; }
  // True once after the text size or the theme changed: the window applies the look before its next frame.
  bool take_look_change() { return std::exchange(look_changed_, false); }
  // What the window's apply_look made of the fonts: a missing font is a warning in the status line.
  void fonts_applied(const FontsLoaded& fonts);
  const WindowLayout& layout() const { return layout_; }
  // Where the lesson's text and buttons were drawn last frame, and "exercises-tab" when the Exercises tab was in front.
  const UiProbe& probe() const { return probe_; }
  float font_pixels() const { return font_pixels_; }

  // Opens the console and runs `code` in it, as if typed there and Enter pressed.
  void run_console(const std::string& code);
  const ScriptConsole& console() const { return console_; }
  ExerciseSession& exercises() { return exercises_; }
  // The "Your code" tab (app/editor_student_code.cpp): the active exercise's student file as its editor shows it, and
  // its save, which the Exercises tab then loads as any save of the file (an Info, or a Warning with the error when the
  // saved file does not load). The page's host then keeps the file in the browser's storage (host_keep_file).
  StudentEdit& student_edit();
  Check save_student_code();
  // The error the editor marks: the file's load error, else the last mine run's error; and the line it names.
  std::string student_code_error();
  std::optional<size_t> student_code_error_line();
  StudentEditorState& student_editor() { return student_editor_; }
  // The files a page's student picked or dropped (host_take_received_files): a .lua named as a file of the student
  // folder replaces that file (kept, and loaded as a save is; the status line names it); the rest open as dropped
  // files do.
  void receive_files(const std::vector<std::string>& paths);
  // File > Download your file: the editor's file, saved first when it has unsaved changes, handed to the user
  // (host_hand_over: a page's browser downloads it).
  void download_student_code();
  // View > Your code: opens the tab and the right column, the tab in front next frame.
  void show_student_code();
  // The curve view's state (what a lesson reads with curve_t() and curve_points(); the `curve-t` action sets its t).
  CurveEditorState& curve_editor() { return curve_; }
  const CurveEditorState& curve_editor() const { return curve_; }
  const PatchViewState& patch_view() const { return patches_; }
  PatchViewState& patch_view() { return patches_; }
  // The "mine" switches of the curve and patch views (M), with their results.
  BezierMine& bezier_mine() { return bezier_mine_; }

  // Saves the current mesh (in any format save_mesh writes); reports the outcome in the status line. A page's browser
  // then downloads the file (host_hand_over, window_host.h), as it does a screenshot.
  bool save(const std::filesystem::path& path);
  // Asks for a PNG of the whole window (3D view and panels) after the current frame is drawn.
  void request_screenshot(const std::filesystem::path& path) { screenshot_path_ = path; }
  // Called by the window between ImGui's rendering and the buffer swap.
  void write_pending_screenshot(int width, int height);

  bool quit_requested() const { return quit_requested_; }
  // Whether the window may close now (its close button, Ctrl+Q, File > Quit). Not while Your code holds unsaved text
  // of a file on the user's disk: then the Unsaved code dialog asks, and the window closes once the student chose
  // (answer_unsaved_code). A page never asks: its unsaved text is kept as a draft (window_host.h).
  bool may_close();
  enum class UnsavedCodeAnswer { SaveAndQuit, QuitWithoutSaving, KeepEditing };
  void answer_unsaved_code(UnsavedCodeAnswer answer);
  bool asking_about_unsaved_code() const { return show_unsaved_code_; }
  // The names of the student files whose editor text is not saved, in path order, as the dialog names them
  // ("flip.lua, split.lua"); "" when none.
  std::string unsaved_student_files() const;
  // A new size for the window (the `window-size` action): the window loop applies it before the next frame.
  void request_window_size(int width, int height) { window_size_request_ = {width, height}; }
  std::optional<std::pair<int, int>> take_window_size_request() { return std::exchange(window_size_request_, {}); }
  OrbitCamera& camera() { return camera_; }
  const RenderStats& mesh_render_stats() const { return mesh_renderer_->stats(); }
  RenderStyle& mesh_render_style() { return mesh_renderer_->style(); }  // tests lower its buffer cap
  const std::string& status_note() const { return status_bar_.note; }
  const ViewOptions& view_options() const { return view_options_; }  // as the user and the quality governor set them
  void fit_view() { fit_camera(); }
  Viewport viewport() const { return {view_pixels_.width, view_pixels_.height}; }
  // View > Up axis: shows the mesh or patches on screen with that up axis (app/up_axis_choice.h), refitted.
  void choose_up_axis(UpAxisChoice choice);
  UpAxisChoice up_axis_choice() const { return up_axis_choice_; }
  std::string_view status_up_axis() const { return status_bar_.up_axis; }  // "Y up (from the file)"
  void reset_view();                                                       // Space: back to the fitted view
  ViewMode mode() const { return mode_; }
  MeshDocument& document() { return doc_; }
  Selection& selection() { return selection_; }
  const std::string& title() const { return title_; }
  static constexpr char kStartTitle[] = "MeshEdit";  // the title before a file or a lesson names the window
  // "MeshEdit - <name>": the title naming a file or a lesson.
  static std::string window_title(const std::string& name);
  // The files opened or saved lately, the latest first (File > Open recent).
  const std::deque<std::string>& recent_files() const { return recent_; }
  // The labels the last frame drew over the mesh view (id and lesson labels, window coordinates) and how many it
  // dropped; empty outside the mesh view.
  const LabelPlacement& last_labels() const { return last_labels_; }

 private:
  void run_frame(int width, int height, float frame_ms);  // frame() without its guard
  void read_mouse_and_keys();
  void draw_mesh_view();
  // The view's rectangle in framebuffer pixels, from the layout's (window coordinates).
  void place_view(int framebuffer_width, int framebuffer_height);
  void begin_view_drawing();  // GL viewport and scissor on the view
  static void end_view_drawing();
  void draw_columns();
  void draw_left_column();
  void draw_right_column();
  void draw_console_strip();
  void draw_splitters();
  void draw_curve_canvas_window();
  // The mouse position in view pixels, or nullopt when it is outside the view.
  std::optional<glm::ivec2> mouse_in_view() const;
  void change_font_size(int steps);  // 0: back to the default
  // The theme: the renderers' colours now, ImGui's and the panels' when the window applies the look.
  void set_theme(Theme theme);
  void apply_size_defaults();
  void draw_patch_view();
  // Places and draws the id and lesson labels (id_labels.cpp) inside the view's rectangle, given in ImGui window
  // coordinates; `framebuffer` is the view's size in framebuffer pixels, which the camera projects to.
  void draw_labels(float view_x, float view_y, float view_width, float view_height, Viewport framebuffer);
  // The menu bar: the command table's menus and items in its order, each item running its command (editor_menus.cpp).
  void draw_menu_bar();
  void draw_menu_item(const Command& command);
  void draw_submenu(CommandId id);  // Open recent, Up axis, Theme
  void draw_open_panel();
  void draw_help_panel();
  void draw_unsaved_code_dialog();  // editor_menus.cpp, with the other dialogs
  void draw_repairs_tab();          // the Repairs tab's rows (editor_repairs.cpp)
  void draw_repair_spots();         // every current spot highlighted over the mesh
  // After open() failed: remembers `path` for open_repaired() when `repairable`, and says so in the message.
  void offer_repair(const std::filesystem::path& path, bool repairable) noexcept;
  void message(Severity severity, const std::string& text);
  void fit_camera();  // to what the view shows: the mesh, or the patches' surface
  void fit_camera(const BoundingBox& bounds);
  // Switch the window to a new document, view mode and view with steps that cannot fail (editor_files.cpp): the end
  // of showing a mesh, a curve or patches, once everything that can fail was made.
  void take_mesh(HalfedgeMesh&& mesh, std::string&& path, bool fit = true);  // fit: the camera to the mesh
  void take_curve(CurveEditorState&& curve);
  void take_patches(PatchViewState&& patches);  // tessellated already
  // Gives the camera and the status bar the up axis of file_up_axis_ and up_axis_choice_; returns whether the camera's
  // axis changed (the view then needs a fit). Cannot fail: a step of take_mesh and take_patches.
  bool apply_up_axis() noexcept;
  // A runner with no lesson, for the window's lesson host, printing to the console.
  std::unique_ptr<LessonRunner> make_lesson_runner();
  Check carry_out(CommandId id, CommandStart start);  // what each command does: run_command without its bookkeeping
  void draw_lesson_marks();                           // the lesson's highlights and arrows (its labels: draw_labels)
  void draw_lesson_arrows();                          // the lesson's arrows, over the mesh view or the patch view
  void draw_edit_animation();                         // the edit playing, over the mesh (editor_edit_animation.cpp)
  void update_lesson(float frame_ms);
  void tell_lesson_key(int key, KeyMods mods);
  void take_lesson_request();          // a lesson picked from the list, or "Lessons" (back to the list), this frame
  void bring_exercises_tab_forward();  // opens the Exercises tab and the right column, the tab in front next frame
  void draw_student_code_tab();        // the "Your code" tab's contents (editor_student_code.cpp)
  // Per frame: each edited file's unsaved text is kept as a draft (host_keep_draft) once it has rested half a second,
  // and its draft forgotten once the text is clean again; a file the editor first shows takes back its kept draft.
  void keep_student_drafts();
  void take_back_student_draft(StudentEdit& edit);
  // In a page (no editor of the student's own), opening the Exercises tab opens "Your code" beside it.
  void open_student_code_with_exercises();

  ShaderLibrary shaders_;
  std::unique_ptr<MeshRenderer> mesh_renderer_;
  std::unique_ptr<MeshRenderer> patch_renderer_;
  std::unique_ptr<OverlayRenderer> overlay_renderer_;
  OrbitCamera camera_;
  ViewOptions view_options_;
  bool show_labels_ = true;
  LabelPlacement last_labels_;
  // The shown mesh's size class (apply_size_defaults): small enough for halfedge arrows by default (kArrowsMaxFaces),
  // for the wireframe by default (kWireframeMaxFaces: past it the lines of a fitted mesh cover its faces), dense, or
  // past RenderStyle::large_mesh_triangles. When it changes, the wireframe and the arrows take its defaults; the
  // quality then follows the frame time (app/view_quality.h).
  static constexpr size_t kArrowsMaxFaces = 300;
  static constexpr size_t kWireframeMaxFaces = 20000;
  enum class SizeClass { Unknown, Small, Medium, Dense, Large };
  SizeClass size_class_ = SizeClass::Unknown;
  ViewQuality view_quality_;                 // multisampling, wireframe and back sides by the measured frame time
  std::optional<ViewRequest> pending_view_;  // a lesson's view{...}, for the next mesh frame
  void take_pending_view();
  // Why the renderer refused the document's mesh (too large to draw) at this generation and version; "" when drawn.
  std::string undrawable_;
  uint64_t undrawable_generation_ = 0, undrawable_version_ = 0;
  ViewMode mode_ = ViewMode::Mesh;

  MeshDocument doc_;
  Selection selection_;
  InspectorState inspector_;
  TablesState tables_;
  StatusBarState status_bar_;
  std::unique_ptr<WindowLessonHost> lesson_host_;
  std::unique_ptr<LessonRunner> lesson_;
  LessonPanelState lesson_panel_;
  ElementRef lesson_selection_;  // the selection the lesson last heard about
  ExerciseSession exercises_;
  ExercisePanelState exercise_panel_;
  StudentEditorState student_editor_;
  bool exercises_were_open_ = false;  // the Exercises tab was open last frame (open_student_code_with_exercises)
  // The student files the Your code tab has shown, by path: unsaved text stays with its file while the student
  // switches exercises, and each file's draft is kept on its own (keep_student_drafts).
  struct EditedStudentFile {
    StudentEdit edit;
    uint64_t changes_seen = 0;  // edit.changes() last frame
    uint64_t changes_kept = 0;  // ... when its draft was last kept or forgotten
    double changed_at = 0.0;    // ImGui's time when they last changed
  };
  std::map<std::filesystem::path, EditedStudentFile> student_files_;
  BezierMine bezier_mine_;
  ScriptConsole console_;
  ConsolePanelState console_panel_;
  CurveEditorState curve_;
  PatchViewState patches_;
  MeshEditState mesh_edits_;  // Loop's weights and the Catmull-Clark and linear steppers (document/mesh_edits.h)
  // The up axis of the file shown (nullopt: a mesh no file gave, Z-up) and View > Up axis's choice.
  std::optional<FileUpAxis> file_up_axis_;
  UpAxisChoice up_axis_choice_ = UpAxisChoice::FromFile;

  bool show_open_panel_ = false;
  bool show_help_ = false;
  bool show_unsaved_code_ = false;  // the Unsaved code dialog is up (may_close)
  bool close_confirmed_ = false;    // the student chose to quit with (or after saving) the unsaved code
  std::string repairable_path_;     // the mesh file open() last refused as not a manifold
  RepairMarks repairs_;             // the Repairs tab: the last repaired copy's changes and their spots
  bool repairs_tab_open_ = false;
  size_t repair_row_clicked_ = SIZE_MAX;  // the row last clicked (shown selected while the spots are current)
  std::string open_path_input_;
  std::string save_path_input_;
  std::deque<std::string> recent_;
  std::string title_ = kStartTitle;
  bool title_names_lesson_ = false;  // title_ is the running lesson's (open_lesson), not a file's: reloads rename it

  Settings settings_;
  bool look_changed_ = true;  // the window applies the look before the first frame
  float font_pixels_ = Settings::kDefaultFontPx;
  WindowLayout layout_;
  UiProbe probe_;
  enum class RightTab { None, Tables, Inspector, Exercises, Code, Repairs };
  RightTab select_tab_ = RightTab::None;  // a tab to bring to the front at the next frame (I, X)
  // The view in framebuffer pixels: x and y from the framebuffer's top-left corner.
  struct PixelRect {
    int x = 0, y = 0, width = 1, height = 1;
  };
  PixelRect view_pixels_;
  int framebuffer_height_ = 1;
  glm::vec2 pixels_per_point_{1.0f, 1.0f};  // framebuffer pixels per ImGui window coordinate (place_view)
  bool dragging_ = false;
  // A hover waiting for the mouse to rest, because the id buffer is stale and slow to redraw (read_mouse_and_keys).
  static constexpr double kSlowIdPassMs = 30.0;
  static constexpr double kHoverRestSeconds = 0.15;
  bool hover_pending_ = false;
  double mouse_moved_at_ = 0.0;
  std::optional<std::filesystem::path> screenshot_path_;
  std::optional<std::pair<int, int>> window_size_request_;
  bool quit_requested_ = false;
  EditAnimationPolicy edit_animation_policy_ = EditAnimationPolicy::Never;
  EditAnimator edit_animator_;
};

}  // namespace meshedit
