// The Lua globals a lesson file sees (lesson, step, say, wait_for, show, highlight, label, clear, camera,
// animate, current_mesh, selection; the questions choose, pick and answer: lesson_questions.h; live, plot, arrow,
// curve_t and curve_points: lesson_displays.h) and the state they fill in. LessonRunner owns one LessonScript per
// loaded file; this file knows nothing about steps being run, only what each call is allowed to do.
//
// Lua API: listed at open_lesson_api, below.
//
// Invariants:
// - `lesson{}` and `step()` are accepted only while the file's top level runs (phase Loading); scene calls
//   (say, show, highlight, label, clear, camera, arrow, live, plot) and waits and questions only while a step runs
//   (phase Step); the calls that only read the view (current_mesh, selection, curve_t, curve_points, patch_uv) also
//   while a live block or a plot's marker is evaluated (phase Live). Anything else is a Lua error naming the call.
// - Every error raised here starts with the lesson's `file:line:` (the innermost frame that is not the API's
//   own Lua prelude), so the panel can point at the line the author wrote.
// - wait_for and animate yield only from the step's own coroutine (`step_thread`); before yielding they set
//   `wait` and `api_yield`, so the runner can tell an API yield from a stray coroutine.yield.
// - Host calls are made with C++ exceptions turned into Lua errors: nothing thrown crosses a Lua frame.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "lesson/lesson_blocks.h"
#include "lesson/lesson_events.h"
#include "lesson/lesson_host.h"
#include "lesson/lesson_texts.h"
#include "script/lua_runtime.h"

struct lua_State;

namespace meshedit {

class YourTurnRun;  // internal/your_turn_run.h

struct LessonStepDef {
  std::string title;
  int function_ref = -2;  // LUA_NOREF until registered: the step body in the registry
  std::string where;      // "welcome.lua:12", where step() was called
};

struct LessonScript {
  enum class Phase { Loading, Idle, Step, Live };

  LessonHost* host = nullptr;
  Phase phase = Phase::Loading;
  std::string title, summary;
  std::vector<LessonStepDef> steps;
  // The lesson's texts in other languages, by their English (every text the API reads: read_text).
  LessonTexts texts;
  std::filesystem::path directory;  // the lesson file's folder (lesson_file() resolves against it); may be empty
  // The student's folder your_turn runs files from (lesson_your_turn.h); empty: your_turn says none was given.
  std::filesystem::path student_folder;
  LuaLimits student_limits;  // for the student's code, as the window's exercises run it

  // The running step (phase Step): its coroutine, what it said, what it waits for.
  lua_State* step_thread = nullptr;
  std::vector<std::string> said;
  LessonWait wait;
  bool api_yield = false;

  // What the step shows besides its text (lesson_blocks.h), all in `blocks` in the order it was made.
  std::vector<LessonBlock> blocks;
  std::vector<LessonLive> lives;
  std::vector<LessonPlot> plots;
  std::vector<LessonJudgement> answered;  // the questions answered right, in order
  // The latest judgement of an answer and how many were made in this step (right or wrong).
  LessonJudgement last_judgement;
  size_t judgements = 0;
  // Every your_turn run of this step (lesson_your_turn.h), in order: kept apart from the questions' judgements.
  std::vector<YourTurnVerdict> your_turns;
  // The window's runner: a your_turn's run goes on beside the step, which waits for it (lesson_your_turn.h); the run
  // under way, if any (its destructor stops the student's code and waits for it).
  bool student_code_in_background = false;
  std::shared_ptr<YourTurnRun> running_turn;
};

// Defines the lesson globals in `runtime` (once, before the lesson file runs), all bound to `script`,
// which must outlive the runtime's use. Throws ScriptError if the API's own prelude fails.
//
// Lua API (a lesson file also has the whole `meshedit` module):
//   lesson { title = "...", summary = "..." }     top level; both optional (title defaults to the file's stem)
//   step("Title", function() ... end)             top level; steps run in the order they are defined
//   say(markdown)                                 a text block for the panel: # heading, **bold**, *italic*,
//                                                 `code`, [link](url), "- " lists, blank lines between paragraphs
//   wait_for { key = "F" }                        -> the key as pressed ("f"); names as in scripted actions:
//                                                    "F", "shift+L", "ctrl+Z" (case ignored)
//   wait_for { click = "vertex" | "e7" | element | "any" }       -> the clicked element
//   wait_for { selection = "e7" | "edge" | element | "any" }     -> the selected element (also met when it is
//                                                    already selected, at the next frame)
//   wait_for { condition = function() ... end }   -> its first truthy value; checked now, then once per frame
//   wait_for { button = "Continue" }              -> the label; the panel shows the button
//     every wait_for also takes hint = "..." (one line under the text; a default is made for key, click,
//     selection and button). Elements come back as handles on a copy of the mesh on screen (`e.mesh`), or as
//     the id string when no mesh is shown.
//   animate(seconds, function(t) ... end)         calls the function with t from 0 to 1 as the frames pass
//   show(mesh | curve | patch | {points...} | {{16 points}, ...})   a mesh, a 2D curve (z = 0), or patches
//   highlight(element | "e7" | {elements...}, colour)   colour: "red" ... "#rrggbb" or {r, g, b} in [0, 1];
//                                                 names give the palette's colour-blind-safe swatches
//                                                 (core/palette.h); default: the last-edit colour
//   label(element | "e7", text)    clear()  (removes highlights and labels)
//   camera "fit" | "reset" | { fit =, reset =, yaw =, pitch = (degrees), distance =, target = point }
//   current_mesh() -> a copy of the mesh on screen (with the student's edits), or nil
//   selection()    -> the selected element (a handle on a copy of the mesh on screen), or nil
//   lesson_file(relative) -> the path of a file next to the lesson ("../assets/teapot.bez" from lessons/),
//                            for meshedit.load/load_patches/load_curve; callable at any phase
void open_lesson_api(LuaRuntime& runtime, LessonScript& script);

// Forgets what the running step showed (its text, blocks, judgements) and releases the registry references its live
// blocks and plot markers hold in `L` (the runtime's main state). The runner calls it when a step starts.
void clear_step_display(lua_State* L, LessonScript& script);

// Pushes what a wait on an element returns to the lesson: a handle of `element` on a copy of the host's
// current mesh, or the id as a string ("e7") when no mesh is shown or the id is not in it.
void push_element_value(lua_State* L, LessonHost& host, ElementRef element);

}  // namespace meshedit
