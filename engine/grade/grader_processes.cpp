// grade(): one child process per test, each test's report read back and scored (see grader.h). Native only: the page
// has no processes to fork.
#include <chrono>
#include <cmath>
#include <csignal>
#include <sstream>

#include "core/value_format.h"
#include "grade/child_process.h"
#include "grade/grader.h"
#include "grade/report_json.h"

namespace meshedit {

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
    if (options.on_test_start) options.on_test_start(spec);
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
