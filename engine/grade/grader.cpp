// grade(): one child per test, the child's report, and the scoring rules (see grader.h).
#include "grade/grader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/value_format.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "grade/child_process.h"
#include "grade/test_feedback.h"

namespace meshedit {
namespace {

constexpr size_t kFailuresShown = 8;

double round_score(double x) { return std::round(x * 1e6) / 1e6; }

std::string plural_points(double points) { return format_number(points) + (points == 1.0 ? " point" : " points"); }

RunEnd end_from_name(const std::string& name) {
  for (RunEnd e :
       {RunEnd::Completed, RunEnd::Error, RunEnd::LoadError, RunEnd::Timeout, RunEnd::Memory, RunEnd::Crash}) {
    if (name == run_end_name(e)) return e;
  }
  throw GradeError("unknown end '" + name + "' in a test report");
}

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

std::string encode_test_run(const TestRun& run) {
  nlohmann::json j;
  j["checks"] = nlohmann::json::array();
  for (const auto& c : run.checks) {
    j["checks"].push_back({{"passed", c.passed}, {"message", c.message}, {"headline", c.headline}});
  }
  if (run.fraction) j["fraction"] = *run.fraction;
  j["end"] = run_end_name(run.end);
  j["error"] = run.error;
  j["output"] = run.output;
  j["output_truncated"] = run.output_truncated;
  // Student text may hold any bytes: replace invalid UTF-8 rather than fail.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

TestRun decode_test_run(const std::string& text) {
  TestRun run;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    for (const auto& c : j.at("checks"))
      run.checks.push_back(
          {c.at("passed").get<bool>(), c.at("message").get<std::string>(), c.at("headline").get<size_t>()});
    if (j.contains("fraction")) run.fraction = j.at("fraction").get<double>();
    run.end = end_from_name(j.at("end").get<std::string>());
    run.error = j.at("error").get<std::string>();
    run.output = j.at("output").get<std::string>();
    run.output_truncated = j.at("output_truncated").get<bool>();
  } catch (const nlohmann::json::exception& e) {
    throw GradeError(std::string("malformed test report: ") + e.what());
  }
  return run;
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

GradeReport grade(Suite& suite, const Submission& submission, const GradeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  GradeReport report;
  report.suite_name = suite.name();
  std::ostringstream top;
  top << "Suite " << suite.name() << ": " << plural(suite.tests().size(), "test", "tests") << ".\n";
  std::string files;
  for (const auto& f : submission.files()) files += (files.empty() ? "" : ", ") + f.relative;
  top << "Files submitted: " << (files.empty() ? "none" : files) << ".\n";
  for (const auto& name : suite.named_files()) {
    if (!submission.find(name)) top << "Missing: " << name << " (the tests that need it fail).\n";
  }
  for (const auto& note : submission.notes()) top << "Note: " << note << ".\n";

  std::string filter_note;
  std::vector<NotShown> not_shown = {{"hidden"}, {"after_due_date"}, {"after_published"}};
  for (size_t i = 0; i < suite.tests().size(); ++i) {
    if (options.time_limit_cap > 0) suite.cap_time_limit(i, options.time_limit_cap);
    const TestSpec& spec = suite.tests()[i];
    if (options.visible_only && spec.visibility != "visible") {
      for (NotShown& left_out : not_shown) {
        if (left_out.visibility != spec.visibility) continue;
        ++left_out.tests;
        left_out.points += spec.points;
      }
      continue;
    }
    ChildLimits limits;
    limits.wall_seconds = spec.time_limit + options.kill_grace_seconds;
    limits.memory_bytes = options.child_memory_bytes + (spec.memory_mb << 20);
    limits.filter_syscalls = options.filter_syscalls;
    const ChildResult child = run_in_child(limits, [&] { return encode_test_run(suite.run_test_here(i, submission)); });
    if (!child.filter_problem.empty() && filter_note.empty()) {
      filter_note = "Note: the system call filter is not available here (" + child.filter_problem +
                    "); the Lua sandbox and the process limits still apply.\n";
    }
    TestRun run;
    if (child.report_complete) {
      try {
        run = decode_test_run(child.report);
      } catch (const GradeError& e) {
        run.end = RunEnd::Crash;
        run.error = e.what();
      }
    } else {
      run.end = child.timed_out || child.signal == SIGXCPU ? RunEnd::Timeout : RunEnd::Crash;
      run.error = describe_child_end(child, spec.time_limit);
      // What the child printed outside Lua (C++ messages) helps explain a crash; student prints are lost.
      if (!child.err.empty()) run.error += "\n" + child.err.substr(0, 2000);
    }
    TestResult result = score_test(spec, run, child.seconds);
    report.score += result.score;
    (spec.extra_credit ? report.extra_points : report.max_score) += spec.points;
    if (options.on_test) options.on_test(result);
    report.tests.push_back(std::move(result));
  }
  report.score = round_score(report.score);
  if (report.extra_points > 0) {
    std::string numbers;
    for (const auto& spec : suite.tests()) {
      if (spec.extra_credit) numbers += (numbers.empty() ? "" : ", ") + spec.number;
    }
    const bool one = numbers.find(',') == std::string::npos;
    top << "Extra credit: " << (one ? "test " : "tests ") << numbers << (one ? " adds" : " add") << " up to "
        << report.extra_points << (report.extra_points == 1.0 ? " point" : " points") << " on top of the "
        << report.max_score << " base points.\n";
  }
  std::erase_if(not_shown, [](const NotShown& left_out) { return left_out.tests == 0; });
  report.not_shown = std::move(not_shown);
  if (const std::string sentence = not_shown_sentence(report.not_shown); !sentence.empty()) top << sentence << "\n";
  report.output = top.str() + filter_note;
  report.execution_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace meshedit
