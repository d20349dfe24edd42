// Suite: an instructor's grading suite, a Lua file run in a trusted state of its own, and running one of its
// tests in the current process (the child process calls that; see grader.h for the isolation around it).
//
// Suite file API (globals of the suite's state, besides the usual whitelist and the full `meshedit` module):
//   suite{ name =, files = {"flip.lua"}, time_limit = 10, memory_mb = 256, visibility = "visible",
//          reference = {"flip_edge"}, allow_api = {"mesh:flip"}, partial = false, output_kb = 16, language = "en" }
//       defaults for every test (any order in the file; optional)
//   test{ name = "flip: interior edge", points = 2, number = "1.1", visibility = "after_due_date",
//         time_limit = 2, memory_mb = 64, partial = true, files = {...}, reference = {...},
//         allow_api = {...}, tags = {"flip"}, extra_credit = false, run = function(student, expect) ... end }
//       declares a test; `name` and `run` are required; unknown fields are errors (typos do not pass silently);
//       an extra_credit test's points add to the score on top of the base points (grader.h)
//   SUITE_DIR   the folder of the suite file, for fixtures: meshedit.load(SUITE_DIR .. "/cow.dae")
//   include("flip.lua")   runs another suite file of the same folder here (one assignment suite gathering the
//               parts' suites); its suite{} defaults merge with this file's, field by field, the last call winning
//   exercise{...}   an exercise defined in Lua (exercise/scripted_exercise.h; a file of scripts/exercises is a suite):
//               registers it, sets the suite's name, files and allow_api, and declares one test per fixture that
//               runs the student's function on a copy of the fixture's mesh and checks it with expect.exercise
// Inside `run`: what `student` and `expect` do is at run_test_here, below.
//
// Invariants:
// - Everything a test needs from disk is read when the suite loads (the test process cannot open files): load
//   fixtures at the top level of the suite, not inside `run`.
// - Each test gets a fresh StudentState and a fresh budget window in the suite's state; the suite's own
//   state is only ever changed in the child process that runs the test, so tests cannot see each other.
// - `student` and `expect` work only while their test runs (kept past it, they raise an error).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/translation.h"
#include "grade/grade_types.h"
#include "grade/submission.h"
#include "script/lua_runtime.h"

namespace meshedit {

class TestRecorder;

class Suite {
 public:
  // Runs the suite file. Throws GradeError with the Lua message (file:line) when it fails, declares no
  // test, or declares one wrongly.
  static std::unique_ptr<Suite> load(const std::filesystem::path& path);
  static std::unique_ptr<Suite> from_text(std::string_view text, const std::string& chunk_name,
                                          const std::filesystem::path& folder);
  ~Suite();
  Suite(const Suite&) = delete;
  Suite& operator=(const Suite&) = delete;

  const std::string& name() const { return name_; }
  const std::vector<TestSpec>& tests() const { return tests_; }
  size_t output_bytes() const { return output_bytes_; }
  // suite{ language = "zh" }: the language the feedback is written in (core/translation.h); English by default.
  Language language() const { return language_; }
  // The student files test `spec` loads: its own list (or its suite{}'s), else every .lua file submitted.
  static std::vector<std::string> files_for(const TestSpec& spec, const Submission& submission);
  // Every file some test names (for the report of missing files).
  std::vector<std::string> named_files() const;

  // Lowers test `index`'s time limit to at most `seconds`.
  void cap_time_limit(size_t index, double seconds);

  // Runs test `index` here, in this process. Never throws: problems become the run's end and error.
  // Inside `run`:
  //   student.NAME(...)       calls the submission's function NAME in its sandbox (arguments and results are
  //                           copied; meshes are shared, so the student's changes to a mesh are seen); an error
  //                           or a limit in student code raises here with the student's message
  //   student.has("NAME")     whether the submission defines it;  student.call("NAME", ...) = student.NAME(...)
  //   student.output()        what the student's code printed so far
  //   expect.*                the checks (expectations.h)
  TestRun run_test_here(size_t index, const Submission& submission);

  struct Context;  // the test running now (suite.cpp)

 private:
  Suite();
  void finish_loading(const std::string& chunk_name);

  std::unique_ptr<LuaRuntime> runtime_;
  std::string name_;
  std::vector<TestSpec> tests_;
  std::filesystem::path folder_;  // SUITE_DIR
  std::string chunk_folder_;      // how the suite's own chunk name spells its folder ("" or "suites")
  size_t output_bytes_ = size_t(16) << 10;
  Language language_ = Language::English;
  Context* current_ = nullptr;
  TestRecorder* recorder_slot_ = nullptr;  // what `expect` records into; null between tests
  struct Declarations;
  std::unique_ptr<Declarations> declarations_;  // while loading only
  friend struct SuiteApi;
};

}  // namespace meshedit
