// The answers file of `meshedit lesson FILE --headless --answers A.lua` (lesson_headless.h runs them): a Lua file
// returning a table keyed by step number (1-based) or step title, each a list of answers given in order while that
// step waits.
//
//   return {
//     [2] = { {click = "v0"} },
//     ["Flip it"] = { {selection = "e7"}, {flip = "e7"}, {key = "F"} },
//     ["Which next?"] = { {choose = "h1", feedback = "twin"}, {choose = "h4"} },
//     ["Weights"] = { {curve_t = 0.25}, {answer = 0.375} },
//   }
//
// Answers, one per table: a key, a click, a selection, a button, an edit the window makes, an answer to a question,
// the curve or patch view's probe (all of them at ScriptedAnswer, below).
//
// A choose, click, answer or curve_click may also carry `feedback = "words"`: the answer must then be judged wrong,
// with feedback containing those words, or the run fails. That is how a test checks that a lesson names a mistake.
//
// {your_turn = "right"} and {your_turn = "wrong", feedback = "words"} are not given but expected: the verdict of the
// step's next your_turn run of the student's file (lesson_your_turn.h) must be that one, with a wrong one's diagnosis
// containing the words.
//
// Invariants: the file runs in a sandboxed runtime of its own under the given limits and is read raw (no metamethod
// of the file's runs while reading); anything malformed is a ScriptError naming the file, the step and the answer's
// position ("a.lua: step 2, answer 1: unknown answer 'klick' (use ...)").
#pragma once

#include <deque>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <lua.hpp>

#include "script/lua_runtime.h"

namespace meshedit {

// Answers, one per table: {key = "F"}, {click = "v3" | "vertex"}, {selection = "e7" | "edge"}, {button = "Continue"},
// the edits a key or a menu command makes in the window ({flip = "e7"}, {split = "e7"}, {collapse = "e7"},
// {subdivide = true} (Loop, as L), {subdivide = "loop" | "catmull-clark" | "linear"} (the Subdivide menu),
// {subdivide_phase = "loop" | "catmull-clark" | "linear"} (the scheme's next phase; {loop_phase = true} is Loop's, as
// Shift+L), {triangulate = true} (Edit > Triangulate), {open_repaired = "../assets/x.ply"} (File > Open a
// repaired copy of that file, a path from the lesson's folder)); each of these menu commands also tells the lesson
// its command's name (lesson_events.h: "catmull-clark-phase"), as the window's menu does; the answers to questions
// ({choose = "h4"} for choose{}; a click answers pick{};
// {answer = 0.375 | "3/8" | {0.5, 1}} for answer{}, as typed into its box), {curve_t = 0.25} (the curve view's t,
// as its slider sets it), {patch_uv = {0.25, 0.5}} (the patch view's probe, as its u and v sliders set it) and
// {curve_click = {0.9, 1.1}} (a click in the curve view at that point, in the curve's coordinates: it answers
// pick{on = "curve"}; it counts as on the curve within 2% of the control points' extent).
struct ScriptedAnswer {
  enum class Kind {
    Key,
    Click,
    Selection,
    Button,
    Flip,
    Split,
    Collapse,
    Subdivide,
    SubdividePhase,
    Triangulate,
    OpenRepaired,
    Choose,
    Value,
    CurveT,
    PatchUv,
    CurveClick,
    YourTurn
  };
  Kind kind = Kind::Key;
  std::string field;  // as written: "key", "click", "answer", ...
  std::string value;  // "F", "v3", "vertex", "Continue", "e7", "h4", "0.375", "0.5, 1", "right", "0.25 0.5"
                      // (patch_uv, curve_click); the scheme of subdivide and subdivide_phase ("loop" for loop_phase)
  std::optional<std::string> feedback;  // the words a wrong answer's feedback must contain

  bool is_edit() const;  // an edit of the scene (flip ... subdivide_phase, curve_t, patch_uv): always used, never
                         // "not awaited"
};
using ScriptedAnswerList = std::deque<ScriptedAnswer>;

struct ScriptedAnswers {
  std::map<lua_Integer, ScriptedAnswerList> by_number;
  std::map<std::string, ScriptedAnswerList> by_title;
};

// Reads the answers file. Throws ScriptError when it cannot be read or is malformed.
ScriptedAnswers read_scripted_answers(const std::filesystem::path& path, const LuaLimits& limits);

}  // namespace meshedit
