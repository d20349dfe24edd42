// EditorApp: the rooms wired together and one frame of them (see editor_app.h). Opening files is editor_files.cpp's,
// the commands editor_commands.cpp's, the menus and dialogs editor_menus.cpp's, your_turn's mine
// editor_your_turn.cpp's.
#include "app/editor_app.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "app/window_host.h"
#include "core/translation.h"
#include "document/document_actions.h"
#include "document/exception_report.h"
#include "document/student_call_work.h"
#include "exercise/exercise_registry.h"
#include "render/gl_api.h"
#include "render/image_file.h"
#include "render/render_target.h"
#include "ui/frame_guard.h"

namespace meshedit {

EditorApp::EditorApp()
    : view_(document_),
      exercises_(document_),
      check_(document_, exercises_),
      writeup_(document_, exercises_, view_),
      lessons_(document_, view_, exercises_,
               [this](const std::string& line) { panels_.console().append_output(line); }),
      input_(document_, view_),
      panels_(document_, view_, exercises_, check_, lessons_) {
  lessons_.panel().show_your_turn = [this] { show_your_turn_mine(); };
  // The curve and patch views' "mine" runs beside the frames too (a thread, or the page's Web Worker).
  view_.bezier_mine().set_in_background(StudentCallWork::off_the_callers_thread());
  // The exercises defined in Lua: a definition that does not load is named (file:line) and left out.
  const std::vector<std::string> errors = load_exercise_folder(default_exercise_folder());
  for (const std::string& error : errors) std::fprintf(stderr, "meshedit: exercise: %s\n", error.c_str());
  if (!errors.empty()) {
    document_.message(Severity::Warning,
                      tr_format("an exercise in scripts/exercises did not load: {error}", {{"error", errors.front()}}));
  }
}

EditorApp::~EditorApp() = default;

void EditorApp::write_pending_screenshot(int width, int height) {
  if (!screenshot_path_) return;
  const std::filesystem::path path = std::move(*screenshot_path_);  // moved: no copy to run out of memory
  screenshot_path_.reset();
  try {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    write_png(path, width, height, read_pixels({width, height}));
    const std::string handed = host_hand_over(path);  // a page's browser downloads it
    document_.message(Severity::Info, handed.empty()
                                          ? tr_format("screenshot saved to {file}", {{"file", path.string()}})
                                          : tr_format("screenshot {handed}", {{"handed", handed}}));
  } catch (const std::exception& e) {
    report_exception(document_.doc(), e);  // called outside the frame guard (between rendering and the swap)
  }
}

void EditorApp::finish_pending_writeup() {
  try {
    writeup_.finish_made();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the pictures' framebuffer unbound: the next frame draws on screen
  } catch (const std::exception& e) {
    report_exception(document_.doc(), e);
  }
}

void EditorApp::frame(int width, int height, float frame_ms) {
  // The safety net: whatever a key, a click, a menu or a panel throws is shown, not fatal (ui/frame_guard.h).
  run_guarded_frame(document_.doc(), [&] { run_frame(width, height, frame_ms); });
}

void EditorApp::run_frame(int width, int height, float frame_ms) {
  view_.advance_edit_animation(frame_ms);  // before this frame's actions: an edit they make starts at time 0
  check_.poll();
  writeup_.poll();
  const LuaLimits student_limits = window_student_limits(panels_.settings().student_code_seconds);
  exercises_.session().set_limits(student_limits);
  lessons_.runner().set_student_limits(student_limits);
  view_.bezier_mine().set_limits(student_limits);
  view_.bezier_mine().poll();                                         // a "mine" call whose code has ended
  exercises_.session().poll(document_.doc(), document_.selection());  // a Run mine whose code has ended
  read_input();                                                       // in the view placed by the last frame
  lessons_.update(frame_ms);
  view_.measure_frame(frame_ms);

  const glm::vec4 bg = view_.background();
  glViewport(0, 0, std::max(1, width), std::max(1, height));
  glClearColor(bg.r, bg.g, bg.b, bg.a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  panels_.probe().clear();
  draw_menu_bar();
  const float menu = ImGui::GetFrameHeight();
  StatusBarState& status_bar = view_.status_bar();
  status_bar.mesh_shown = view_.mode() == ViewMode::Mesh;
  status_bar.view_is_3d = view_.mode() != ViewMode::Curve;
  const float status = draw_status_bar(document_.doc(), document_.selection(), status_bar, frame_ms);
  panels_.lay_out(menu, status);
  view_.place(panels_.layout().view, width, height);

  ViewMarks marks;
  marks.lesson = &lessons_.marks();
  marks.repairs = repair_spots_current() ? &document_.repair_marks() : nullptr;
  marks.animate_edits = panels_.settings().animate_edits;
  view_.draw(marks);
  if (view_.mode() == ViewMode::Curve) {
    view_.draw_curve_canvas_window();  // before the levels table: it computes the levels
    lessons_.tell_curve_click();
  }
  view_.draw_labels(lessons_.marks());
  panels_.draw_columns();
  if (const std::optional<size_t> row = check_.take_case_request()) open_failing_case(*row);
  exercises_.keep_student_drafts();
  draw_open_panel();
  draw_help_panel();
  bug_report_.draw_dialog();
  draw_unsaved_code_dialog();
}

void EditorApp::read_input() {
  for (const auto& [key, mods] : InputRoom::keys_pressed()) handle_key(key, mods);
  if (const std::optional<glm::ivec2> clicked = input_.read_mouse()) click(clicked->x, clicked->y);
}

void EditorApp::click(int x, int y) {
  if (view_.mode() != ViewMode::Mesh) return;
  const ElementRef picked = view_.pick(x, y);
  if (!picked.valid()) {
    document_.selection().selected = {};
    return;
  }
  select_element(document_.doc(), document_.selection(), picked);
  reveal_in_tables(panels_.tables(), picked);
  lessons_.tell_click(picked);
}

bool EditorApp::animating() const {
  return input_.hover_pending() || view_.edit_animator().playing() || lessons_.animating() || check_.running() ||
         writeup_.running() || exercises_.session().running() || view_.bezier_mine().running();
}

bool EditorApp::repair_spots_current() const { return document_.repair_spots_current(view_.mode() == ViewMode::Mesh); }

bool EditorApp::click_repair_row(size_t row) { return document_.click_repair_row(row, view_.mode() == ViewMode::Mesh); }

void EditorApp::run_console(const std::string& code) {
  ConsolePanelState& panel = panels_.console_panel();
  panel.open = true;
  panel.scroll_to_bottom = true;
  exercises_.session().finish_replay(document_.doc());
  panels_.console().submit(document_.doc(), document_.selection(), code);
  keep_if_alive(document_.selection(), document_.doc().mesh);
}

void EditorApp::bring_exercises_tab_forward() {
  exercises_.panel().open = true;
  panels_.bring_forward(RightTab::Exercises);
}

void EditorApp::show_student_code() {
  exercises_.editor().open = true;
  panels_.bring_forward(RightTab::Code);
}

bool EditorApp::may_close() {  // called outside the frame's guard: allocates nothing
  if (close_confirmed_ || !host_files_on_users_disk() || !exercises_.any_unsaved()) return true;
  quit_requested_ = false;
  show_unsaved_code_ = true;
  return false;
}

void EditorApp::answer_unsaved_code(UnsavedCodeAnswer answer) {
  show_unsaved_code_ = false;
  if (answer == UnsavedCodeAnswer::KeepEditing) return;
  if (answer == UnsavedCodeAnswer::SaveAndQuit) {
    if (Check saved = exercises_.save_unsaved(); !saved) {
      document_.message(Severity::Error,
                        tr_format("not saved, so the window stays open: {reason}", {{"reason", saved.reason}}));
      return;
    }
  }
  close_confirmed_ = true;
  quit_requested_ = true;
}

}  // namespace meshedit
