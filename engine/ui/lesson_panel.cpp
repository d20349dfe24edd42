// The lesson panel: see lesson_panel.h for the contract.
#include "ui/lesson_panel.h"

#include <algorithm>
#include <system_error>

#include <imgui.h>

#include "core/text_breaks.h"
#include "core/translation.h"
#include "core/value_format.h"
#include "document/exercise_session.h"
#include "lesson/lesson_text.h"
#include "ui/flow_layout.h"
#include "ui/lesson_plot_view.h"
#include "ui/lesson_question_view.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

fs::file_time_type modified(const fs::path& path) noexcept {
  std::error_code ec;
  const auto time = fs::last_write_time(path, ec);
  return ec ? fs::file_time_type{} : time;
}

ImVec4 error_colour() { return im_colour(ui_palette().error); }
ImVec4 hint_colour() { return im_colour(ui_palette().emphasis); }

void draw_lesson_list(LessonPanelState& state) {
  if (state.lessons_editable) {
    text_wrapped_at_spaces(
        tr_format("Pick a lesson. Each one is a Lua file in {folder}; edit it and save, and the "
                  "lesson reloads.",
                  {{"folder", state.lessons_dir.string()}}));
  } else {
    text_wrapped_at_spaces(tr("Pick a lesson."));
  }
  ImGui::Separator();
  if (state.lesson_files.empty()) ImGui::TextDisabled("%s", tr("(no lessons found)"));
  for (const fs::path& file : state.lesson_files) {
    if (ImGui::Selectable(file.stem().string().c_str())) state.requested = file;
  }
}

// Lesson text is written with line breaks inside paragraphs; the panel wraps by itself, so a single line
// break becomes a space (nothing between two Chinese characters, which also lose the spaces their markdown's marks
// needed). Blank lines (paragraphs) and lines starting a list item stay.
std::string reflow(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    const bool lone_break = text[i] == '\n' && i + 1 < text.size() && text[i + 1] != '\n' &&
                            (i == 0 || text[i - 1] != '\n') && text.compare(i + 1, 2, "- ") != 0;
    if (!lone_break) out += text[i];
    else if (!joins_without_space(std::string_view(text).substr(0, i), std::string_view(text).substr(i + 1)))
      out += ' ';
  }
  return without_spaces_between_wide(out);
}

ReloadOutcome run_reload(LessonRunner& runner, LessonPanelState& state) {
  return state.reload ? state.reload(runner) : reload_runner(runner);
}

// One block of the step (lesson/lesson_blocks.h): say() text, live text (or its error), a plot, a question answered.
void draw_block(const LessonRunner& runner, const LessonBlock& block) {
  switch (block.kind) {
    case LessonBlock::Kind::Text:
      text_wrapped_at_spaces(reflow(markdown_to_plain(lesson_text(runner, runner.said()[block.index]))));
      break;
    case LessonBlock::Kind::Live: {
      const LessonLive& live = runner.lives()[block.index];
      if (!live.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, error_colour());
        text_wrapped_at_spaces(live.error);
        ImGui::PopStyleColor();
      } else {
        text_wrapped_at_spaces(reflow(markdown_to_plain(live.local.in(text_language()))));
      }
      break;
    }
    case LessonBlock::Kind::Plot: draw_lesson_plot(runner, runner.plots()[block.index]); break;
    case LessonBlock::Kind::Answered: draw_lesson_answered(runner, runner.answered()[block.index]); break;
  }
  ImGui::Spacing();
}

// What the student sees of their file's wrong run: the task, the diagnosis, the hint and the button that shows the run
// side by side with the reference.
void draw_your_turn_wait(const LessonRunner& runner, LessonPanelState& state, const LessonWait& wait) {
  text_wrapped_at_spaces(lesson_text(runner, wait.question));
  ImGui::PushStyleColor(ImGuiCol_Text, im_colour(ui_palette().warning));
  text_wrapped_at_spaces(lesson_text(runner, wait.feedback));
  ImGui::PopStyleColor();
  if (!wait.hint.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, hint_colour());
    text_wrapped_at_spaces(tr_format("Hint: {hint}", {{"hint", lesson_text(runner, wait.hint)}}));
    ImGui::PopStyleColor();
  }
  const YourTurnVerdict* verdict = your_turn_to_show(runner);
  if (!verdict || !state.show_your_turn) return;
  ImGui::Spacing();
  const bool clicked = ImGui::Button(tr_label(kShowMineButton));
  if (state.probe) state.probe->record_last_item("lesson-show-mine");
  const float width = ImGui::GetContentRegionAvail().x;
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  if (is_mesh_exercise(verdict->exercise)) {
    text_wrapped_at_spaces(
        tr_format("Runs your {function} on this input in the Exercises tab (X): the pointers it "
                  "changed beside the reference's, and your writes one by one.",
                  {{"function", verdict->function}}));
  } else {
    const char* shows = verdict->exercise == Exercise::CurveStep
                            ? "Shows this input in the curve view with its \"mine\" on (M): your {function} beside the "
                              "reference's."
                            : "Shows this input in the patch view with its \"mine\" on (M): your {function} beside the "
                              "reference's.";
    text_wrapped_at_spaces(tr_format(shows, {{"function", verdict->function}}));
  }
  ImGui::PopStyleColor();
  // A new run, or the text wrapped anew (a resize): the diagnosis and the button come into sight, once.
  const size_t step = runner.current_step(), runs = runner.your_turns().size();
  if (state.scrolled_step != step || state.scrolled_runs != runs || state.scrolled_width != width) {
    ImGui::SetScrollHereY(1.0f);
    state.scrolled_step = step;
    state.scrolled_runs = runs;
    state.scrolled_width = width;
  }
  if (clicked) state.show_your_turn();
}

// A your_turn's run under way: what runs on what, its time and a Stop (the window draws on while it runs).
void draw_your_turn_running(LessonRunner& runner, LessonPanelState& state, const LessonWait& wait) {
  text_wrapped_at_spaces(lesson_text(runner, wait.question));
  const bool stop = ImGui::Button(tr_label("Stop"));
  if (state.probe) state.probe->record_last_item("lesson-stop-mine");
  if (stop) runner.stop_student_code();
  ImGui::SameLine();
  const std::string seconds = format_fixed(runner.student_code_seconds(), 1);
  text_wrapped_at_spaces(tr_format("running your code ({seconds} s)", {{"seconds", seconds}}));
}

void draw_step_body(LessonRunner& runner, LessonPanelState& state) {
  const std::vector<LessonBlock>& blocks = runner.blocks();
  for (size_t i = 0; i < blocks.size(); ++i) {
    ImGui::PushID(int(i));
    draw_block(runner, blocks[i]);
    ImGui::PopID();
  }
  const LessonWait& wait = runner.waiting_for();
  if (wait.is_question()) {
    draw_lesson_question(runner, state.answer_box, state.probe);
    // A wrong answer: its feedback and the hint come into sight, once (a short panel would hide them below).
    if (state.scrolled_judgements != runner.judgements() && !runner.last_judgement().right) ImGui::SetScrollHereY(1.0f);
    state.scrolled_judgements = runner.judgements();
  } else if (wait.kind == LessonWait::Kind::Button) {
    const std::string label = lesson_text(runner, wait.name) + "###lesson-button";
    if (ImGui::Button(label.c_str())) runner.deliver(LessonEvent::button(wait.name));
  } else if (wait.kind == LessonWait::Kind::YourTurn) {  // the student's file gave another answer: why, until saved
    draw_your_turn_wait(runner, state, wait);
  } else if (wait.kind == LessonWait::Kind::YourTurnRunning) {
    draw_your_turn_running(runner, state, wait);
  } else if (wait.kind == LessonWait::Kind::Animation && wait.seconds > 0) {
    ImGui::ProgressBar(float(std::clamp(wait.elapsed / wait.seconds, 0.0, 1.0)));
  } else if (wait.waiting()) {
    ImGui::PushStyleColor(ImGuiCol_Text, hint_colour());
    text_wrapped_at_spaces("-> " + (wait.hint.empty() ? wait.describe() : lesson_text(runner, wait.hint)));
    ImGui::PopStyleColor();
  }
  if (runner.step_finished()) ImGui::TextDisabled("%s", tr("Step done: press Next."));
}

}  // namespace

const YourTurnVerdict* your_turn_to_show(const LessonRunner& runner) {
  if (runner.waiting_for().kind != LessonWait::Kind::YourTurn || runner.your_turns().empty()) return nullptr;
  const YourTurnVerdict& last = runner.your_turns().back();
  return last.right ? nullptr : &last;
}

ReloadOutcome reload_runner(LessonRunner& runner) {
  if (runner.reload()) return ReloadOutcome::Reloaded;
  return runner.out_of_memory() ? ReloadOutcome::OutOfMemory : ReloadOutcome::Failed;
}

void refresh_lessons(LessonPanelState& state) {
  state.lesson_files.clear();
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(state.lessons_dir, ec)) {
    if (entry.path().extension() == ".lua") state.lesson_files.push_back(entry.path());
  }
  std::sort(state.lesson_files.begin(), state.lesson_files.end(), [](const fs::path& a, const fs::path& b) {
    const bool a_welcome = a.stem() == "welcome", b_welcome = b.stem() == "welcome";
    return a_welcome != b_welcome ? a_welcome : a.filename() < b.filename();
  });
}

bool load_lesson(LessonRunner& runner, LessonPanelState& state, const fs::path& path) {
  watch_lesson(state, path);
  return runner.load(path);
}

void watch_lesson(LessonPanelState& state, const fs::path& path) noexcept {
  state.loaded_time = modified(path);
  state.since_check = 0.0;
  state.open = true;
}

bool reload_if_changed(LessonRunner& runner, LessonPanelState& state, double dt) {
  if (runner.path().empty()) return false;
  state.since_check += dt;
  if (state.since_check < LessonPanelState::kReloadCheckSeconds) return false;
  state.since_check = 0.0;
  const auto time = modified(runner.path());
  if (time == state.loaded_time) return false;
  state.loaded_time = time;
  // Memory that ran out is not the file's doing: the next check tries again (a broken file waits for the next save).
  if (run_reload(runner, state) == ReloadOutcome::OutOfMemory) state.loaded_time = {};
  return true;
}

void draw_lesson_panel(LessonRunner& runner, LessonPanelState& state) {
  if (!state.open) return;
  const std::string title =
      (runner.loaded() ? lesson_text(runner, runner.title()) : std::string(tr("Lessons"))) + "###lesson";
  if (ImGui::Begin(title.c_str(), &state.open)) draw_lesson_panel_contents(runner, state);
  ImGui::End();
}

void draw_lesson_panel_contents(LessonRunner& runner, LessonPanelState& state) {
  if (!runner.error().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, error_colour());
    text_wrapped_at_spaces(runner.error());
    ImGui::PopStyleColor();
    ImGui::Separator();
  }
  if (!runner.loaded()) {
    draw_lesson_list(state);
    return;
  }
  const std::vector<std::string> steps = runner.step_titles();
  const size_t current = runner.current_step();
  const std::string step_line =
      tr_format("Step {number} of {count}: {title}",
                {{"number", std::to_string(current + 1)},
                 {"count", std::to_string(steps.size())},
                 {"title", current < steps.size() ? lesson_text(runner, steps[current]) : std::string()}});
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##steps", step_line.c_str())) {
    for (size_t i = 0; i < steps.size(); ++i) {
      const std::string item = std::to_string(i + 1) + ". " + lesson_text(runner, steps[i]);
      if (ImGui::Selectable(item.c_str(), i == current)) runner.go_to(i);
    }
    ImGui::EndCombo();
  }
  // The buttons take one row, or two when the column is too narrow for them (large text): the step's text keeps the
  // rest, so the buttons never fall off the panel.
  const char* const buttons[] = {"< Back", "Next >", "Reload", "Lessons"};
  const ImGuiStyle& style = ImGui::GetStyle();
  float row = -style.ItemSpacing.x;
  for (const char* label : buttons)
    row += ImGui::CalcTextSize(tr(label)).x + style.FramePadding.x * 2.0f + style.ItemSpacing.x;
  const int rows = row <= ImGui::GetContentRegionAvail().x ? 1 : 2;
  ImGui::BeginChild("step", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * float(rows)), false);
  draw_step_body(runner, state);
  ImGui::EndChild();
  if (state.probe) state.probe->record_last_item("lesson-text");
  ImGui::BeginDisabled(current == 0);
  if (ImGui::Button(tr_label("< Back"))) runner.back();
  if (state.probe) state.probe->record_last_item("lesson-back");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(current + 1 >= steps.size());
  if (ImGui::Button(tr_label("Next >"))) runner.next();
  if (state.probe) state.probe->record_last_item("lesson-next");
  ImGui::EndDisabled();
  if (rows == 1) ImGui::SameLine();
  if (ImGui::Button(tr_label("Reload"))) run_reload(runner, state);
  ImGui::SameLine();
  if (ImGui::Button(tr_label("Lessons"))) {
    refresh_lessons(state);
    state.requested = fs::path();  // empty: back to the list
  }
}

}  // namespace meshedit
