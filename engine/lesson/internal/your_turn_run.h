// YourTurnRun: one run of a your_turn (lesson_your_turn.h): the student's file loaded into a fresh sandboxed
// StudentCode and its function called on the input, on a thread of its own (document/background_work.h), while the
// reference's outcome is made on the caller's thread first; finish() judges the two with compare(), the Exercises
// tab's comparison, into the run's verdict.
//
// Invariants:
// - The work touches only what the run owns (the verdict's input is read, never written, by both threads), so the
//   window draws on while it runs. The student's code stops at its next line once stop() is called or the run is
//   destroyed (LuaRuntime's stop request: "stopped: you pressed Stop"), and within its limits anyway.
// - finish() waits for the work, then gives the verdict once: right, or wrong with its diagnosis (the first
//   differences, the likely mistake first, with the diagram's legend) or the file's error ("flip.lua:4: ..."). It
//   throws std::bad_alloc when memory ran out in the run, as the run on the caller's thread would have.
#pragma once

#include <atomic>
#include <chrono>
#include <string>

#include "document/background_work.h"
#include "exercise/exercises.h"
#include "lesson/internal/diagram_names.h"
#include "lesson/lesson_blocks.h"
#include "script/lua_runtime.h"

namespace meshedit {

class YourTurnRun {
 public:
  // Starts the run of `verdict.path` on `verdict.exercise_input` (the rest of the verdict says what runs, for the
  // panel). Throws what the reference throws (memory running out).
  YourTurnRun(YourTurnVerdict verdict, DiagramNames names, const LuaLimits& limits);
  ~YourTurnRun();
  YourTurnRun(const YourTurnRun&) = delete;
  YourTurnRun& operator=(const YourTurnRun&) = delete;

  bool done() const { return work_.done(); }
  void stop() { stop_.store(true); }
  double seconds() const;
  const YourTurnVerdict& running() const { return verdict_; }  // before finish(): what runs, on what
  // Waits for the run and judges it (once).
  YourTurnVerdict finish();

 private:
  void work() noexcept;  // on the run's thread

  YourTurnVerdict verdict_;
  DiagramNames names_;
  LuaLimits limits_;
  ExerciseOutcome reference_;
  std::chrono::steady_clock::time_point started_;
  std::atomic<bool> stop_{false};
  // Written by work(), read once it has ended.
  ExerciseOutcome mine_;
  std::string load_error_;
  bool out_of_memory_ = false;
  BackgroundWork work_;
};

}  // namespace meshedit
