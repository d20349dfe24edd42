// What student code may call: one list for the window's exercises (StudentCode, exercises.h) and for grading
// (StudentState, grade/student_state.h), so that a call that works in one works in the other and a refusal reads
// the same in both.
//
// Invariants:
// - Never available to student code: the file functions meshedit.load, meshedit.load_curve,
//   meshedit.load_patches and mesh:save (besides what LuaRuntime's sandbox leaves out: io, os.execute, require,
//   debug, bytecode, string.dump).
// - Hidden unless allowed: the operations that are exercises or their references, mesh:flip, mesh:split,
//   mesh:collapse, mesh:loop_subdivide, mesh:catmull_clark, meshedit.curve and meshedit.patch
//   (hideable_api_names()). The window allows what exercise_api(exercise) lists for the exercise it runs; a grading
//   test allows what its suite lists (allow_api). The shipped suites list the same as exercise_api
//   (tests/grade/student_api_test.cpp).
// - A hidden or removed entry is not nil but a function that raises hidden_api_message(name), with the caller's
//   "file.lua:LINE: " in front: the same words whichever state runs the code.
// - set_student_api may be called again on the same state (the window runs several exercises on one loaded file):
//   each call shows or hides every hideable entry by the list it is given. The real functions are kept in a
//   registry table, which student code cannot reach (no debug library).
// - Another exercise's function that the student's file does not define (evaluate_step read in patch.lua) is not
//   nil but a function that raises other_file_message, with the caller's "file.lua:LINE: " in front: each file
//   runs in a state of its own, and the error says so instead of "attempt to call a nil value". Only a read from
//   Lua code of another file than the function's own that finds no global of that name sees it (the globals'
//   __index); the owner's own file, rawget and C code (the window's and the grader's lookups of the student's
//   functions) still find nil.
// - Patches reach student code as plain tables {points = {16 vec3}} (push_student_patch), in the window as in
//   grading: no reference evaluation comes with them.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/bezier.h"
#include "exercise/exercises.h"

struct lua_State;

namespace meshedit {

// "mesh:flip", "mesh:split", "mesh:collapse", "mesh:loop_subdivide", "mesh:catmull_clark", "meshedit.curve",
// "meshedit.patch".
const std::vector<std::string>& hideable_api_names();
bool is_hideable_api(const std::string& name);

// What an exercise's code may use beyond the always-available API: upsample gets mesh:flip and mesh:split and the
// reference flip_edge and split_edge; a scripted exercise what its definition allows; the others get nothing more.
struct ExerciseApi {
  std::vector<std::string> allow_api;  // hideable names
  std::vector<std::string> reference;  // reference function names (reference_functions.h)
};
const ExerciseApi& exercise_api(Exercise exercise);

// "mesh:flip is hidden from your code (in the window and in grading): it is what flip_edge does, so write the
// pointer updates yourself". For any name, hideable or a file function ("meshedit.load").
std::string hidden_api_message(const std::string& name);

// "evaluate_step is curve.lua's function, and each exercise file runs on its own (in the window and in grading,
// where patch.lua is loaded alone), so patch.lua cannot call it: copy the function into patch.lua, as a local
// function": what a student's file is told when it calls another exercise's function it does not define.
std::string other_file_message(const std::string& function, const std::string& owner_file, const std::string& file);

// Removes the file functions and shows exactly the hideable entries in `allowed` (the others raise). The meshedit
// module (with its Bézier part) must be open. Raises a Lua error if the bindings cannot be restricted; call in
// protected mode.
void set_student_api(lua_State* L, std::span<const std::string> allowed);

// Pushes {points = {...}} for a patch, as student code receives one.
void push_student_patch(lua_State* L, const BezierPatch& patch);

}  // namespace meshedit
