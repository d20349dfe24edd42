// The lesson globals that ask the student something and answer each wrong answer: choose, pick and answer. Each
// waits (its step yields, as wait_for does) until the right answer, and returns it.
//
// Lua API:
//   choose { "Which halfedge is h0.next after the flip?", options = {"h1", "h2", "h4"}, answer = "h4",
//            feedback = { h1 = "h1 is h0's twin ...", h2 = "..." }, hint = "..." }
//       -> the option chosen (the right one). The panel shows one button per option.
//   pick { "Click the halfedge that will be h0.next", answer = h4 | "h4" | function(element) -> ok, why,
//          feedback = function(element) -> text | { h1 = "...", ... }, hint = "..." }
//       -> the element clicked (a handle on a copy of the mesh on screen, or its id when no mesh is shown).
//   pick { "Click the point of the curve at t = 0.25", on = "curve", answer = 0.25 | function(t, point) -> ok, why,
//          tolerance = 0.04, feedback = function(t, point) -> text, hint = "..." }
//       -> the t clicked: a click on the curve view answers with the t of the curve point nearest to it (and that
//          point, a vec3 with z = 0); a number answer is right within `tolerance` (in t, default 0.04).
//   answer { "What is B1(0.5)?", number = 0.375 | point = {x, y[, z]}, tolerance = 1e-3,
//            feedback = function(value) -> text, hint = "..." }
//       -> the number, or a vec3 for a point (z = 0 for a 2D one). The panel shows an input box and Check.
//
// Invariants:
// - The question's text is the table's first item; every other field is named. Unknown fields, an answer that is not
//   one of the options, feedback for an option that does not exist, a pick answer that is no element, both or
//   neither of number and point: each is a Lua error at the lesson's line ("lesson.lua:12: choose: ...").
// - A wrong answer never returns: the step waits on the same question, whose wait (LessonWait) has `tries` one more
//   and `feedback` set to the lesson's text for that answer (a feedback table's entry, the feedback function's
//   value, a pick answer function's second value), or a default that names the answer and never the right one.
// - `hint` shows only after the first wrong try (LessonWait::hint_shown); what counts as a try: open_lesson_questions.
// - Every judgement is recorded in LessonScript (last_judgement, judgements); a right one also becomes an Answered
//   block, so the panel keeps what was asked (open_lesson_questions).
// - The lesson's functions (pick's answer and feedback, answer's feedback) run inside the step's coroutine under its
//   budget; their errors fail the step at their own line.
#pragma once

#include "lesson/internal/lesson_api.h"

namespace meshedit {

// Defines choose, pick and answer in `runtime` (after open_lesson_api), bound to `script`. Throws ScriptError if the
// API's own prelude fails.
// Text typed into answer{} that is not a number (or a point of the right size) is told how to write one, and is not
// counted as a try; so is a click on the curve view that is not on the curve (farther from it than the event's
// radius: the window's pick radius in pixels).
// A right answer's Answered block holds the question, the answer and the lesson's words on it (a feedback table's
// entry for the right option or id, or the answer function's second value).
void open_lesson_questions(LuaRuntime& runtime, LessonScript& script);

}  // namespace meshedit
