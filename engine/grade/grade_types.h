// The values the autograder passes around: a test as the suite declares it, what one run of it found (made
// in the child process, sent to the parent), and the graded result the writers turn into files.
//
// Invariants:
// - A TestRun only records facts (checks, the error, printed text); scores are computed once, by the parent
//   (score_test in grader.h), so nothing running beside student code decides a grade.
// - Visibility is one of Gradescope's four words; the suite loader refuses anything else.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace meshedit {

// How a test run ended when it did not run to its end.
enum class RunEnd {
  Completed,  // the test function returned
  Error,      // a Lua error (the student's or the suite's)
  LoadError,  // a student file did not compile or failed while it ran
  Timeout,    // the time limit or the instruction budget (in the child), or the parent's wall-clock kill
  Memory,     // the Lua memory cap
  Crash,      // the child died without a report (a signal, an exit, an unreadable report)
};

const char* run_end_name(RunEnd end);  // "completed", "error", "load error", "timeout", "memory", "crash"

// The input of a failed expect.exercise on a mesh, so the window can open it in the Exercises tab and the grader can
// draw it: the exercise, the input mesh and the student's mesh after the call with every record and id kept
// (core/mesh_records.h), and the element the student's function was given.
struct FailingCase {
  std::string
      exercise;       // the exercise's function: "flip_edge", "split_edge", "vertex_normal", "upsample", a scripted one
  std::string input;  // ExerciseInput::describe: "e5 of a mesh with 12 faces"
  std::string mesh;   // the input mesh, format_mesh_records
  std::string element;  // its element as format_id writes it ("e5", "v3"), "" for the whole mesh
  std::string mine;     // the student's mesh after the call, format_mesh_records ("" when there was none)
};

struct CheckResult {
  bool passed = false;
  std::string message;  // what was checked, and for a failure what was wrong
  // How much of `message` is its headline: what was checked and the first difference, the likely mistake (the
  // Markdown feedback folds the rest). 0: all of it.
  size_t headline = 0;
  std::optional<FailingCase> failing_case;  // a failed expect.exercise on a mesh: its input
};

// What one test run found.
struct TestRun {
  std::vector<CheckResult> checks;
  std::optional<double> fraction;  // set by expect.score(f): the share of the points, overriding the checks
  RunEnd end = RunEnd::Completed;
  std::string error;   // the message when end != Completed
  std::string output;  // what the student's code printed (capped)
  bool output_truncated = false;
};

// A test as the suite declares it (everything the parent needs to run and report it).
struct TestSpec {
  std::string number;  // "1.2"; defaults to the 1-based position
  std::string name;
  double points = 1.0;
  std::string visibility = "visible";  // visible | hidden | after_due_date | after_published
  double time_limit = 10.0;            // seconds of wall clock for the whole test
  size_t memory_mb = 256;              // the student state's Lua memory cap
  bool partial = false;                // score = points * passed checks / checks
  bool extra_credit = false;           // its points add on top of the base points (max_score 0 in results)
  std::vector<std::string> files;      // student files loaded for this test
  std::vector<std::string> reference;  // reference functions installed in the student's globals
  std::vector<std::string> allow_api;  // mesh API normally hidden from students that this test allows
  std::vector<std::string> tags;
  int run_ref = -1;  // registry reference of the run function in the suite's state
};

// A graded test, ready for the writers.
struct TestResult {
  std::string number;
  std::string name;
  std::string visibility;
  std::vector<std::string> tags;
  double score = 0.0;
  double max_score = 0.0;     // 0 for extra credit: its score adds on top of the base points
  double extra_points = 0.0;  // what an extra-credit test can add (0 for the others)
  bool passed = false;
  RunEnd end = RunEnd::Completed;
  std::string failure;          // the first problem in one line ("" when passed), for JUnit/TAP messages
  std::string output;           // the full text shown to the student
  std::string output_markdown;  // the same as Markdown (test_feedback.h), for results.json
  double seconds = 0.0;
  std::optional<FailingCase> failing_case;  // the first failed check's input, when it has one
};

// Tests a run left out because the student may not see them yet (GradeOptions::visible_only), by visibility.
struct NotShown {
  std::string visibility;  // hidden | after_due_date | after_published
  size_t tests = 0;
  double points = 0.0;  // base and extra-credit points together
};

struct GradeReport {
  std::string suite_name;
  std::vector<TestResult> tests;
  std::vector<NotShown> not_shown;  // in the order hidden, after_due_date, after_published; only those with tests
  std::string output;               // top-level text: the suite, the files found and whether they compile
  double score = 0.0;               // base and extra credit together
  double max_score = 0.0;           // the base points: a submission without the extra credit can reach 100%
  double extra_points = 0.0;        // what the extra-credit tests can add on top
  double execution_time = 0.0;      // seconds

  size_t passed() const;
  size_t failed() const { return tests.size() - passed(); }
};

}  // namespace meshedit
