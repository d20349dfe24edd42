// GradeRun: one grading of a submission by a suite, one test at a time, for a caller that runs each test where it
// can: grade() runs each in a child process (grader_processes.cpp), a page's Check my work in a Web Worker
// (app/check_process_web.cpp). Both build their report here, so the same files and suite give the same report.
//
// Invariants:
// - next_test() gives the tests in the suite's order, each once; a visible-only run skips the tests that are not
//   "visible" and counts them in the report's not_shown.
// - add_result() scores a run by the rules of grader.h (score_test) and adds it to the totals; finish() makes the
//   report: the suite's and the submission's notes first (files submitted, files missing), then the extra credit's
//   and the not-shown sentences.
// - A test stopped from outside (its process or worker killed at the wall-clock limit) is described by
//   wall_clock_stop_sentence, in the same words wherever it ran.
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "grade/grader.h"

namespace meshedit {

class GradeRun {
 public:
  // `suite` must outlive the run.
  GradeRun(Suite& suite, const Submission& submission, GradeOptions options);

  // The index (in suite.tests()) of the next test to run; nullopt once every test that runs has a result.
  std::optional<size_t> next_test();
  // How many tests this run runs (a visible-only run's visible tests).
  size_t tests_to_run() const { return to_run_; }
  // Test `index`'s run, `seconds` long: scored and added (on_test is called with its result).
  void add_result(size_t index, const TestRun& run, double seconds);
  // A line for the report's notes, after the submission's ("Note: the system call filter is not available here").
  void add_note(const std::string& line);
  // The report of the tests added so far.
  GradeReport finish();

 private:
  // Whether this run runs the test (a visible-only run: the visible tests alone).
  bool runs(const TestSpec& spec) const { return !options_.visible_only || spec.visibility == "visible"; }

  Suite& suite_;
  GradeOptions options_;
  std::chrono::steady_clock::time_point started_;
  size_t next_ = 0;
  size_t to_run_ = 0;
  std::string top_;
  std::string notes_;
  std::vector<NotShown> not_shown_;
  GradeReport report_;
};

// What a test stopped at its wall-clock limit `time_limit` (seconds) gets as its error.
std::string wall_clock_stop_sentence(double time_limit);

}  // namespace meshedit
