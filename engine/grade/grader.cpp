// The scoring rules, the suite's warnings and the not-shown sentence (see grader.h); grade() itself is in
// grader_processes.cpp.
#include "grade/grader.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/value_format.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "grade/test_feedback.h"

namespace meshedit {
namespace {

constexpr size_t kFailuresShown = 8;

std::string plural_points(double points) { return format_number(points) + (points == 1.0 ? " point" : " points"); }

// The window's hint for a run that did not finish (exercises.h), when the test loads one exercise's file.
std::string unfinished_hint(const TestSpec& spec) {
  std::optional<Exercise> exercise;
  for (const std::string& file : spec.files) {
    const std::optional<Exercise> e = find_exercise(file);
    if (!e || (exercise && *exercise != *e)) return "";
    exercise = e;
  }
  return exercise ? unfinished_run_hint(*exercise) : "";
}

}  // namespace

double round_score(double score) { return std::round(score * 1e6) / 1e6; }

const char* run_end_name(RunEnd end) {
  switch (end) {
    case RunEnd::Completed: return "completed";
    case RunEnd::Error: return "error";
    case RunEnd::LoadError: return "load error";
    case RunEnd::Timeout: return "timeout";
    case RunEnd::Memory: return "memory";
    case RunEnd::Crash: return "crash";
  }
  return "?";
}

size_t GradeReport::passed() const {
  size_t n = 0;
  for (const auto& t : tests) n += t.passed ? 1 : 0;
  return n;
}

std::vector<std::string> suite_warnings(const Suite& suite) {
  std::vector<std::string> warnings;
  for (const TestSpec& spec : suite.tests()) {
    if (spec.visibility != "hidden" || spec.points <= 0.0) continue;
    warnings.push_back("test " + spec.number + " (" + spec.name + ") is hidden and worth " +
                       plural_points(spec.points) +
                       ": on Gradescope a hidden test hides the student's total score too; give it visibility "
                       "after_due_date or after_published (hidden is for tests worth 0 points)");
  }
  return warnings;
}

std::string not_shown_sentence(const std::vector<NotShown>& not_shown) {
  std::string sentence;
  for (const NotShown& left_out : not_shown) {
    const char* when = left_out.visibility == "after_due_date"    ? "shown after the due date"
                       : left_out.visibility == "after_published" ? "shown once grades are published"
                                                                  : "never shown to students";
    sentence += std::string(sentence.empty() ? "" : "; ") + plural(left_out.tests, "more test", "more tests") + ", " +
                plural_points(left_out.points) + ", " + when;
  }
  return sentence.empty() ? sentence : "Not run here: " + sentence + ".";
}

TestResult score_test(const TestSpec& spec, const TestRun& run, double seconds) {
  TestResult r;
  r.number = spec.number;
  r.name = spec.name;
  r.visibility = spec.visibility;
  r.tags = spec.tags;
  if (spec.extra_credit) {
    r.name += " (extra credit)";
    r.tags.push_back("extra credit");
  }
  r.max_score = spec.extra_credit ? 0.0 : spec.points;
  r.extra_points = spec.extra_credit ? spec.points : 0.0;
  r.end = run.end;
  r.seconds = seconds;
  size_t passed = 0;
  for (const auto& c : run.checks) passed += c.passed ? 1 : 0;
  const size_t failed = run.checks.size() - passed;
  const bool stopped = run.end != RunEnd::Completed;
  double fraction = 0.0;
  if (stopped) {
    fraction = spec.partial ? double(passed) / double(run.checks.size() + 1) : 0.0;
  } else if (run.fraction) {
    fraction = std::clamp(*run.fraction, 0.0, 1.0);
  } else if (spec.partial) {
    fraction = run.checks.empty() ? 1.0 : double(passed) / double(run.checks.size());
  } else {
    fraction = failed == 0 ? 1.0 : 0.0;
  }
  r.score = round_score(spec.points * fraction);
  r.passed = !stopped && failed == 0 && r.score >= spec.points;

  TestFeedback feedback;
  if (stopped) {
    feedback.stopped = std::string(run.end == RunEnd::Timeout     ? "Timed out: "
                                   : run.end == RunEnd::Memory    ? "Out of memory: "
                                   : run.end == RunEnd::Crash     ? "Crashed: "
                                   : run.end == RunEnd::LoadError ? "Load error: "
                                                                  : "Error: ") +
                       run.error;
    if (run.end == RunEnd::Timeout || run.end == RunEnd::Memory) feedback.hint = unfinished_hint(spec);
    if (r.failure.empty()) r.failure = run.error;
  }
  // The first failures say enough; a loop over 40 elements should not print 40 near-identical lines.
  for (const auto& c : run.checks) {
    if (c.passed) continue;
    if (feedback.failures.size() < kFailuresShown) feedback.failures.push_back(c);
    else ++feedback.more_failures;
    if (r.failure.empty()) r.failure = c.message;
    if (!r.failing_case) r.failing_case = c.failing_case;
  }
  if (r.passed) {
    feedback.tally = run.checks.empty() ? std::string("Passed.") : "Passed: " + plural(passed, "check", "checks") + ".";
  } else if (!run.checks.empty()) {
    feedback.tally = plural(passed, "check", "checks") + " of " + std::to_string(run.checks.size()) + " passed.";
  }
  if (spec.extra_credit) {
    feedback.extra_credit = "Extra credit: " + format_rounded(round_score(r.score)) + " of " +
                            format_rounded(spec.points) + (spec.points == 1.0 ? " point" : " points") +
                            ", added on top of the base score.";
  }
  if (!run.output.empty()) {
    feedback.printed = run.output;
    if (run.output_truncated && run.output.back() != '\n') feedback.printed += "\n";
  }
  if (r.failure.empty() && !r.passed) r.failure = "score below the maximum";
  r.output = feedback_text(feedback);
  r.output_markdown = feedback_markdown(feedback);
  return r;
}

}  // namespace meshedit
