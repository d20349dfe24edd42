// YourTurnRun: one run of a your_turn (lesson_your_turn.h): the student's file loaded into a fresh sandboxed
// StudentCode and its function called on the input, off the caller's thread (document/student_call_work.h: a thread on
// the desktop, a Web Worker in a page) or at once, while the reference's outcome is made on the caller's thread first;
// finish() judges the two with compare(), the Exercises tab's comparison, into the run's verdict.
//
// Invariants:
// - The run owns what it works on (the call holds its own copy of the input and the file's text), so the window draws
//   on while it runs. The student's code stops once stop() is called or the run is destroyed (StudentCallWork::stop:
//   "stopped: you pressed Stop"), and within its limits anyway.
// - finish() waits for the work, then gives the verdict once: right, or wrong with its diagnosis (the first
//   differences, the likely mistake first, with the diagram's legend) or the file's error ("flip.lua:4: ..."). It
//   throws std::bad_alloc when memory ran out in the run, as the run on the caller's thread would have.
#pragma once

#include <chrono>
#include <string>

#include "document/student_call_work.h"
#include "exercise/exercises.h"
#include "lesson/internal/diagram_names.h"
#include "lesson/lesson_blocks.h"
#include "script/lua_runtime.h"

namespace meshedit {

class YourTurnRun {
 public:
  // Starts the run of `verdict.path` on `verdict.exercise_input` (the rest of the verdict says what runs, for the
  // panel), off the caller's thread when `in_background`, else at once. Throws what the reference throws (memory
  // running out).
  YourTurnRun(YourTurnVerdict verdict, DiagramNames names, const LuaLimits& limits, bool in_background);
  ~YourTurnRun() = default;
  YourTurnRun(const YourTurnRun&) = delete;
  YourTurnRun& operator=(const YourTurnRun&) = delete;

  bool done() { return ran_here_ || work_.done(); }
  void stop() { work_.stop(); }
  double seconds() const;
  const YourTurnVerdict& running() const { return verdict_; }  // before finish(): what runs, on what
  // Waits for the run and judges it (once).
  YourTurnVerdict finish();

 private:
  YourTurnVerdict verdict_;
  DiagramNames names_;
  ExerciseOutcome reference_;
  std::chrono::steady_clock::time_point started_;
  StudentCallResult result_;  // the run's, once it is taken
  bool ran_here_ = false;     // result_ was made at once, on the caller's thread
  StudentCallWork work_;
};

}  // namespace meshedit
