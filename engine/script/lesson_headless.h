// Running a lesson with no window (`meshedit lesson FILE --headless`): every step in order, each wait
// answered from a scripted answers file or, where possible, automatically; what the steps say printed as
// plain text. This is how CI checks that every lesson still runs to its end.
//
// Answers file: a Lua file returning a table keyed by step number (1-based) or step title, each a list of
// answers given in order while that step waits:
//   return {
//     [2] = { {click = "v0"} },  -- a click on v0 (it also selects v0); "vertex": the first live vertex
//     ["Flip it"] = { {selection = "e7"}, {flip = "e7"}, {key = "F"} },
//   }
// Answers: {key = "F"}, {click = "v3" | "vertex"}, {selection = "e7" | "edge"}, {button = "Continue"}, and the
// edits a key would make in the window, applied to the mesh on screen: {flip = "e7"}, {split = "e7"},
// {collapse = "e7"}, {subdivide = true} (L), {loop_phase = true} (Shift+L: the next of Loop subdivision's four
// phases, core/loop_subdivision.h). A headless key press only tells the lesson; it edits nothing, so the
// window's Shift+L is {loop_phase = true} followed by {key = "shift+L"}.
//
// Invariants:
// - An answer the step does not wait for is used up and reported ("not awaited"), as a student's stray key.
// - With no answer left: a button wait is pressed, a selection wait already met by the selection goes on,
//   anything else fails with "lesson.lua:LINE: step 3 'Flip it': waiting for key F (no scripted answer)".
// - Animations advance in frames of a tenth of their length (at least 1/60 s); a step that needs more than
//   100000 frames or answers fails rather than hanging.
// - loop_phase keeps the phases' state between answers as the window's document does (ui/document_actions.h):
//   phase 1 computes and changes nothing, phases 2-4 change the mesh on screen, and when the mesh on screen is
//   not the one the last phase left (the lesson showed another, another edit answer changed it), the next
//   loop_phase starts again at phase 1. The course's weights, as L and the exercises use.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "script/lesson_runner.h"

namespace meshedit {

struct HeadlessOutcome {
  size_t steps = 0;     // steps in the lesson
  size_t passed = 0;    // steps that ran to their end
  std::string failure;  // "" when every step passed; else one line with file:line and the step
};

// Runs the lesson. Writes the transcript to `out`. Throws ScriptError when the answers file cannot be read
// or is malformed; a lesson that fails to load or run is reported in the outcome.
HeadlessOutcome run_lesson_headless(const std::filesystem::path& lesson,
                                    const std::optional<std::filesystem::path>& answers, std::ostream& out,
                                    const LuaLimits& limits = LessonRunner::default_limits());

}  // namespace meshedit
