// The lesson global your_turn: the student's own function, from their folder (scripts/student by default, the folder
// the window's Exercises tab uses), run on the lesson's input beside the reference and judged by the Exercises tab's
// compare() (exercises.h), so the lesson, the tab and the grader say the same words.
//
// Lua API:
//   your_turn { exercise = "flip", mesh = m, element = m:edge(0) | "e0", hint = "..." }
//       exercise: "curve" (points = {...}, t =), "patch" (patch = meshedit.patch(...), u =, v =), "normals" (mesh =,
//       element = a vertex), "flip" / "split" (mesh =, element = an edge), "upsample" (mesh =), or the name of an
//       exercise registered from scripts/exercises (scripted_exercise.h: mesh =, and element = what it takes; for
//       one on points, control = {{x, y}, ...}, for one on a patch, patch = 16 points or meshedit.patch(...), and
//       args = {...}, the values passed after them, as its fixtures write them).
//       names = {a = v2, h0 = "h3", ...} (optional): the diagram's names of elements of the mesh, which a wrong
//       verdict lists beside the storage ids it mentions (diagram_names.h).
//       -> true once the student's function gives the reference's answer. Until then the step waits: the panel shows
//          the diagnosis, and the file runs again each time it is saved.
//
// Invariants:
// - The input is copied when your_turn is called: later edits of the lesson's mesh change nothing of the runs, and
//   neither run changes the lesson's mesh (check_exercise works on copies).
// - Each run loads the file afresh into its own sandboxed StudentCode under LessonScript::student_limits (the limits
//   the window's exercises use), so a Lua error is its "flip.lua:LINE: message" and a runaway loop is stopped by the
//   limits, with the Exercises tab's hint for the exercise: both are the run's wrong verdict, never the step's error.
// - The student's code runs on a thread of its own (YourTurnRun, your_turn_run.h). With
//   LessonScript::student_code_in_background (the window) the step waits for it (LessonWait::Kind::YourTurnRunning,
//   the run in LessonScript::running_turn) and the runner, once the run is done, records its verdict
//   (record_your_turn) and resumes the step with it; without (the headless driver) your_turn waits for it in place.
// - Every run is a YourTurnVerdict in LessonScript::your_turns, with the exercise and the input it ran on (the copy
//   above), so the window can show the same run in the Exercises tab; a right one is also an Answered block (the
//   panel keeps it, as a question answered right). A wrong one leaves the step waiting (LessonWait::Kind::YourTurn,
//   with the diagnosis as its feedback) until the file's stamp (script/file_stamp.h) changes; the runner reads it at
//   most every kStudentFileCheckSeconds.
// - Bad arguments are Lua errors at the lesson's line ("lesson.lua:12: your_turn: ..."), like every lesson call.
#pragma once

#include <filesystem>
#include <string>

#include "lesson/internal/lesson_api.h"

namespace meshedit {

// How often a waiting your_turn looks at the student's file (twice a second, as the lesson's own hot reload).
inline constexpr double kStudentFileCheckSeconds = 0.5;

// Defines your_turn in `runtime` (after open_lesson_api's own globals), bound to `script`. Throws ScriptError if the
// API's own prelude fails.
void open_lesson_your_turn(LuaRuntime& runtime, LessonScript& script);

// Adds a finished run's verdict to the step (its your_turns, and an Answered block when right); returns whether it
// was right.
bool record_your_turn(LessonScript& script, YourTurnVerdict verdict);

}  // namespace meshedit
