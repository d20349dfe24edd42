// Running a lesson with no window (`meshedit lesson FILE --headless`): every step in order, each wait
// answered from a scripted answers file or, where possible, automatically; what the steps say printed as
// plain text. This is how CI checks that every lesson still runs to its end, and (with a student folder) that a
// lesson's your_turn names a buggy solution's mistake.
//
// Answers file: lesson_answers.h (a table keyed by step number or title, each a list of answers given in order while
// that step waits: keys, clicks, selections, buttons, the edits a key would make in the window, the answers to
// choose/pick/answer, the curve view's t). A headless key press only tells the lesson; it edits nothing, so the
// window's Shift+L is {loop_phase = true} followed by {key = "shift+L"}.
//
// Invariants:
// - An answer the step does not wait for is used up and reported ("not awaited"), as a student's stray key.
// - An answer with `feedback = "words"` must be judged wrong with feedback containing the words; otherwise the run
//   fails with "lesson.lua:LINE: step 2 'Q': answer choose = "h6" should be judged wrong ..., but ...".
// - With no answer left: a button wait is pressed, a selection wait already met by the selection goes on,
//   anything else fails with "lesson.lua:LINE: step 3 'Flip it': waiting for key F (no scripted answer)".
// - Each your_turn run (lesson_your_turn.h) prints "  > your turn flip.lua: right" or ": wrong: DIAGNOSIS" and is
//   checked against the step's next answer when that is {your_turn = "right" | "wrong", feedback = "words"}; a wrong
//   verdict the answers expected ends the step there (the student's file cannot change headless), counted as passed.
// - Animations advance in frames of a tenth of their length (at least 1/60 s); a step that needs more than
//   100000 frames or answers fails rather than hanging.
// - The edit answers (flip, split, collapse, subdivide, subdivide_phase, loop_phase, triangulate) run the window's
//   commands by the function the window runs them with (document/mesh_edits.h's run_mesh_edit) on a document of the
//   mesh on screen: flip = "e7" is e7 selected and the command run. The one-phase edits keep each scheme's phases
//   between answers as the window does: phase 1 computes and changes nothing, the later phases change the mesh on
//   screen, and when the mesh on screen is not the one the last edit left (the lesson showed another) or another edit
//   changed it, the next one starts again at phase 1. Loop with the course's weights, as L and the exercises use.
// - An answer that stands for a command a lesson can wait for (document/command_table.h: subdivide, subdivide_phase,
//   loop_phase, triangulate, open_repaired) tells the lesson that command's name after its edit, as the window does.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "lesson/lesson_runner.h"

namespace meshedit {

struct HeadlessOutcome {
  size_t steps = 0;     // steps in the lesson
  size_t passed = 0;    // steps that ran to their end
  std::string failure;  // "" when every step passed; else one line with file:line and the step
  // What the run found of the lesson's other languages (lesson_texts.h): problems (an unknown language, a translation
  // that drops a code span or a number) and the texts read with words and no Chinese twin, each "file:line: ...".
  std::vector<std::string> text_problems, untranslated;
};

// Runs the lesson, your_turn with the files of `student_folder` (none given: your_turn fails the step saying so).
// Writes the transcript to `out`: each say() block as plain text, live text as "[live] ..." (again when an answer
// changed it), a plot as "[plot TITLE: B0, B1 for x from 0 to 1, marker at 0.5]", a question once as
// "? TEXT (a | b | c)", each answer as "> choose a: wrong: FEEDBACK" or "> answer 0.375: right", and "hint: ..."
// when a hint appears. Throws ScriptError when the answers file cannot be read or is malformed; a lesson
// that fails to load or run is reported in the outcome.
HeadlessOutcome run_lesson_headless(const std::filesystem::path& lesson,
                                    const std::optional<std::filesystem::path>& answers, std::ostream& out,
                                    const LuaLimits& limits = LessonRunner::default_limits(),
                                    const std::filesystem::path& student_folder = {});

}  // namespace meshedit
