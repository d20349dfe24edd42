// The questions in the lesson panel (see lesson_question_view.h).
#include "ui/lesson_question_view.h"

#include <cstring>

#include <imgui.h>

#include "core/text_breaks.h"
#include "core/translation.h"
#include "lesson/lesson_text.h"
#include "ui/flow_layout.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

void coloured_text(glm::vec3 colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, im_colour(colour));
  text_wrapped_at_spaces(text);
  ImGui::PopStyleColor();
}

void draw_choices(LessonRunner& runner, const LessonWait& wait, UiProbe* probe) {
  // deliver() changes the wait: copy the options before the first button can be pressed.
  const std::vector<std::string> options = wait.options;
  for (size_t i = 0; i < options.size(); ++i) {
    const std::string& shown = lesson_text(runner, options[i]);
    if (i > 0) same_line_if_room(shown.c_str());
    ImGui::PushID(int(i));
    const bool pressed = wrapping_button(shown.c_str());
    ImGui::PopID();
    if (probe) probe->record_last_item("lesson-choice");
    if (pressed) runner.deliver(LessonEvent::choice(options[i]));
  }
}

void draw_answer_box(LessonRunner& runner, LessonAnswerBox& box, UiProbe* probe) {
  const std::string question = runner.waiting_for().where + "#" + std::to_string(runner.answered().size());
  if (box.question != question) {
    box.question = question;
    box.text[0] = '\0';
  }
  const ImGuiStyle& style = ImGui::GetStyle();
  const float check = ImGui::CalcTextSize(tr("Check")).x + style.FramePadding.x * 2.0f + style.ItemSpacing.x;
  ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - check, ImGui::GetFontSize() * 4.0f));
  const bool entered =
      ImGui::InputText("##lesson-answer", box.text, sizeof box.text, ImGuiInputTextFlags_EnterReturnsTrue);
  if (probe) probe->record_last_item("lesson-answer");
  if (entered) ImGui::SetKeyboardFocusHere(-1);  // keep typing after a wrong answer
  ImGui::SameLine();
  const bool checked = ImGui::Button(tr_label("Check"));
  if ((entered || checked) && box.text[0] != '\0') runner.deliver(LessonEvent::value(box.text));
}

}  // namespace

void draw_lesson_question(LessonRunner& runner, LessonAnswerBox& box, UiProbe* probe) {
  const LessonWait& wait = runner.waiting_for();
  if (!wait.is_question()) return;
  const Palette& palette = ui_palette();
  text_wrapped_at_spaces(without_spaces_between_wide(markdown_to_plain(lesson_text(runner, wait.question))));
  // Read what the panel shows now: a button below may deliver an answer, which changes the wait.
  const std::string feedback = lesson_text(runner, wait.feedback);
  const std::string hint = wait.hint_shown() ? lesson_text(runner, wait.hint) : std::string();
  const LessonWait::Kind kind = wait.kind;
  if (kind == LessonWait::Kind::Choice) draw_choices(runner, wait, probe);
  else if (kind == LessonWait::Kind::Answer) draw_answer_box(runner, box, probe);
  else if (kind == LessonWait::Kind::CurvePick) ImGui::TextDisabled("%s", tr("(click the curve in the view)"));
  else ImGui::TextDisabled("%s", tr("(click it in the view)"));
  if (!feedback.empty()) coloured_text(palette.warning, feedback);
  if (!hint.empty()) coloured_text(palette.emphasis, tr_format("Hint: {hint}", {{"hint", hint}}));
}

const std::string& lesson_text(const LessonRunner& runner, const std::string& english) {
  return runner.texts().in(english, text_language());
}

void draw_lesson_answered(const LessonRunner& runner, const LessonJudgement& judgement) {
  text_wrapped_at_spaces(without_spaces_between_wide(markdown_to_plain(lesson_text(runner, judgement.question))));
  const std::string& given = lesson_text(runner, judgement.given);
  coloured_text(ui_palette().ok,
                judgement.feedback.empty()
                    ? tr_format("Right: {answer}", {{"answer", given}})
                    : tr_format("Right: {answer}. {feedback}",
                                {{"answer", given}, {"feedback", lesson_text(runner, judgement.feedback)}}));
}

}  // namespace meshedit
