// grade(): runs every test of a suite against a submission, each in its own child process, and scores the
// results. The parent (this function's caller) is the only process that decides scores or writes files.
//
// Invariants:
// - One child per test (child_process.h) with the test's time limit plus a grace period as the wall-clock
//   kill; a test whose child hangs, crashes or runs out of memory fails with a sentence saying so, and the
//   other tests still run.
// - The child sends its TestRun as JSON; a report that is missing, cut or malformed is a crash, never a pass.
// - Scores: a test with an error (student or suite), a timeout or a crash scores 0, unless it is partial,
//   when it keeps points * passed / (checks + 1). Otherwise: expect.score's fraction if set; partial: points
//   * passed / checks; else all points when every check passed (a test with no checks passes), 0 if not.
//   Scores are rounded to 1e-6; a test passes when its score is its points and nothing failed. A failed test's
//   failing_case is its first failed check's.
// - Extra credit: an extra_credit test is scored the same way, but its max_score is 0 (its points are
//   extra_points) and the report's max_score counts the base tests only; the report's score adds every test's
//   score. So a submission without the extra credit can reach 100% of max_score, and one with it goes above.
// - A test that timed out or ran out of memory, loading one exercise's file, says what the window says of such a
//   run (unfinished_run_hint in exercises.h: "upsample did not finish: split only the edges of the original mesh").
// - The report lists the files the suite names that the submission lacks, and the submission's notes; a visible-only
//   run says how many tests and points it left out and when the student will see them.
#pragma once

#include <functional>
#include <string>

#include "grade/grade_types.h"
#include "grade/submission.h"
#include "grade/suite.h"

namespace meshedit {

struct GradeOptions {
  double kill_grace_seconds = 1.0;  // added to a test's time limit before the parent kills its child
  double time_limit_cap = 0.0;      // when > 0, no test gets more seconds than this (quick checks)
  size_t child_memory_bytes = size_t(2) << 30;
  bool filter_syscalls = true;
  std::function<void(const TestSpec&)> on_test_start;  // called before each test run (progress)
  std::function<void(const TestResult&)> on_test;      // called after each test (progress)
  // Only the tests the student sees before the due date (visibility "visible"): a student's own check before
  // handing in. The others are counted in the report's not_shown, and its totals are the visible tests'.
  bool visible_only = false;
};

// Native only (grader_processes.cpp): a page cannot fork.
GradeReport grade(Suite& suite, const Submission& submission, const GradeOptions& options = {});

// What an instructor should hear about a suite before it grades: each test worth points that is "hidden", which on
// Gradescope hides the student's total score as well (its spec); after_due_date or after_published show the total.
std::vector<std::string> suite_warnings(const Suite& suite);

// "4 more tests, 9 points, shown after the due date": the tests a visible-only run left out, one sentence per
// visibility ("" when none was left out).
std::string not_shown_sentence(const std::vector<NotShown>& not_shown);

// The scoring rules above, for one test.
TestResult score_test(const TestSpec& spec, const TestRun& run, double seconds);
// A score rounded to 1e-6, as every score is.
double round_score(double score);

}  // namespace meshedit
