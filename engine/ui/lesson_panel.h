// The lesson panel: a lesson's title, its steps, what the current step shows (its text, live text, plots and the
// questions answered: lesson/lesson_blocks.h, in the order the step made them), what it waits for (a question's options
// or answer box, feedback and hint: ui/lesson_question_view.h), its error with file:line, and Back / Next / Reload;
// with no lesson loaded, the list of lessons to start.
//
// Invariants:
// - The panel only reads the runner and calls its public actions (next, back, go_to, reload or state.reload, deliver
//   of a button, an option or the text typed); it never touches Lua: live text and plot markers are evaluated by the
//   runner's update(), and a frame of the panel runs no lesson code. A runner in an error state still draws and still
//   takes Back/Next/Reload.
// - Hot reload: reload_if_changed() compares the lesson file's modification time at most every
//   kReloadCheckSeconds, so a file saved in an editor reloads within a second without a stat per frame. A reload
//   that runs out of memory (LessonRunner::out_of_memory, not an error that merely says so) is tried again at the next
//   check; one that fails otherwise waits for the next save.
// - Reload and hot reload reload through state.reload when it is set (the app's, which renames the window after the
//   lesson, whole or nothing), else with the runner's own reload().
// - While the step waits on a your_turn whose last run was wrong (your_turn_to_show), the panel shows the diagnosis
// and,
//   when state.show_your_turn is set, the "Show mine vs reference" button, which calls it: the app shows that run where
//   it compares runs (the Exercises tab, the curve and patch views' "mine"). The step's child scrolls to the button
//   once per run and once per width of the panel, so a new diagnosis and its button are in sight, after a resize too.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lesson/lesson_runner.h"
#include "ui/element_link.h"
#include "ui/lesson_question_view.h"

namespace meshedit {

// What a reload did: the lesson switched, or the file's own error (wait for the next save), or memory ran out (try
// again at the next check).
enum class ReloadOutcome { Reloaded, Failed, OutOfMemory };

struct LessonPanelState {
  static constexpr double kReloadCheckSeconds = 0.5;

  bool open = true;
  std::filesystem::path lessons_dir;  // where the lesson list comes from
  bool lessons_editable = true;  // lessons_dir is on the user's disk, to edit and save (not a page's packaged files)
  std::vector<std::filesystem::path> lesson_files;  // *.lua in lessons_dir, sorted; filled by refresh_lessons
  std::optional<std::filesystem::path> requested;   // a lesson the user picked from the list this frame
  std::filesystem::file_time_type loaded_time{};
  double since_check = 0.0;
  // How Reload and hot reload reload the lesson; empty: reload_runner.
  std::function<ReloadOutcome(LessonRunner&)> reload;
  UiProbe* probe = nullptr;  // where the step's text ("lesson-text"), Back, Next and the your_turn's button were drawn
  LessonAnswerBox answer_box;  // the text typed for the answer{} being asked
  // What the your_turn's "Show mine vs reference" does (the app's); empty: the panel offers no button.
  std::function<void()> show_your_turn;
  // The your_turn run the step's child last scrolled to: its step, how many runs the step had made, the panel's width.
  size_t scrolled_step = 0, scrolled_runs = 0;
  float scrolled_width = 0.0f;
  size_t scrolled_judgements = 0;  // the judgements the question's feedback was last scrolled into sight for
};

// The label of the your_turn's button (the scripted action lesson-show-mine presses it).
inline constexpr const char kShowMineButton[] = "Show mine vs reference";

// The your_turn run the "Show mine vs reference" button shows: the step's last run, while the step waits on it and it
// was wrong (a different answer, or the file's error); nullptr otherwise.
const YourTurnVerdict* your_turn_to_show(const LessonRunner& runner);

// The runner's own reload(), told as a ReloadOutcome (LessonRunner::out_of_memory for OutOfMemory).
ReloadOutcome reload_runner(LessonRunner& runner);

// Lists lessons_dir's *.lua files (welcome.lua first, then by name). A missing folder gives an empty list.
void refresh_lessons(LessonPanelState& state);

// Loads `path` into the runner and remembers its modification time for hot reload.
bool load_lesson(LessonRunner& runner, LessonPanelState& state, const std::filesystem::path& path);
// Remembers `path`'s modification time for hot reload and opens the panel: what load_lesson does besides loading,
// for a caller that loads in two steps (LessonRunner::prepare and take). Never throws.
void watch_lesson(LessonPanelState& state, const std::filesystem::path& path) noexcept;

// Reloads the lesson (state.reload or reload_runner) when its file changed on disk (checked at most every
// kReloadCheckSeconds of `dt`). Returns whether it reloaded or tried to.
bool reload_if_changed(LessonRunner& runner, LessonPanelState& state, double dt);

// Draws the panel. A lesson picked from the list is left in state.requested for the caller to load (the app
// also has to switch views).
void draw_lesson_panel(LessonRunner& runner, LessonPanelState& state);
// The same contents drawn into the current window (the app's left column).
void draw_lesson_panel_contents(LessonRunner& runner, LessonPanelState& state);

}  // namespace meshedit
