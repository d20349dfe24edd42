// One call of a student's function, as plain values: the exercise, its input, the student's files (their texts) and
// the limits, and what the call gave. The one way the window's runs off its thread call student code: the Exercises
// tab's Run mine and a lesson's your_turn, on a thread of the desktop or in a page's Web Worker
// (document/student_call_work.h), where the call crosses as bytes (student_call_text.h).
//
// Invariants:
// - run_student_call never throws: a file that does not load is load_error (its "flip.lua:3: ..."), memory running
//   out outside the student's code is out_of_memory, and anything else thrown (a bug) is `thrown`; the student's own
//   errors, limits and a stop are the outcome's error, as StudentCode::run makes them.
// - The student's code stops at its next line once `stop` is set (LuaRuntime's stop request), and within the call's
//   limits anyway.
#pragma once

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "exercise/exercises.h"
#include "script/lua_runtime.h"

namespace meshedit {

// One student file: its name ("flip.lua", the chunk name its errors start with) and its text as read_lua_file reads
// it.
struct StudentSource {
  std::string name;
  std::string text;
};

// The file as a StudentSource; throws ScriptError "cannot open PATH" as StudentCode::load does.
StudentSource read_student_source(const std::filesystem::path& file);

struct StudentCall {
  Exercise exercise = Exercise::FlipEdge;
  ExerciseInput input;
  RunOptions options;
  LuaLimits limits;
  std::vector<StudentSource> files;  // loaded in this order into one fresh StudentCode
};

struct StudentCallResult {
  ExerciseOutcome outcome;
  std::string load_error;      // a file did not load ("flip.lua:3: ..."): nothing was called
  bool out_of_memory = false;  // memory ran out outside the student's code (loading, copying): nothing to show
  std::string thrown;          // an exception the call should not have thrown (a bug), said as the run's error
};

// The call's files loaded into a fresh StudentCode under its limits, then its exercise called on its input.
StudentCallResult run_student_call(const StudentCall& call, const std::atomic<bool>* stop = nullptr) noexcept;
// The call on code already loaded (its files are not loaded again), under the call's limits.
StudentCallResult run_student_call_on(StudentCode& code, const StudentCall& call,
                                      const std::atomic<bool>* stop = nullptr) noexcept;

}  // namespace meshedit
