// What the lesson panel draws for the questions of a step (lesson/internal/lesson_questions.h): the question waited on,
// with a button per option (choose), the words "click it in the view" (pick) or an input box with Check (answer); the
// feedback on the last wrong answer in the palette's warning colour; the hint, in the emphasis colour, once the student
// has tried; and each question answered right, with its answer in the ok colour.
//
// Invariants: it only reads the runner and calls runner.deliver with a Choice or Value event, as the scripted actions
// lesson-choose and lesson-answer do; the text typed stays in the box after a wrong answer, and the box empties when
// another question is asked.
#pragma once

#include <string>

#include "lesson/lesson_runner.h"
#include "ui/element_link.h"

namespace meshedit {

// The answer box of answer{}: the text typed and the question it was typed for.
struct LessonAnswerBox {
  char text[128] = {};
  std::string question;  // where the question was asked and how many were answered before it
};

// A text of the lesson (its English, as the runner holds it) in the window's language (core/translation.h).
const std::string& lesson_text(const LessonRunner& runner, const std::string& english);

// Draws the question the runner waits on (nothing when it waits for no question). Records the option buttons as
// "lesson-choice" and the box as "lesson-answer" in `probe` when given.
void draw_lesson_question(LessonRunner& runner, LessonAnswerBox& box, UiProbe* probe);
// Draws a question answered right: the question, then "Right: <answer>" and the lesson's words on it.
void draw_lesson_answered(const LessonRunner& runner, const LessonJudgement& judgement);

}  // namespace meshedit
