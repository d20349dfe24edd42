// grade(): one child process per test, each test's report read back and scored (see grader.h). Native only: the page
// has no processes to fork (it runs its tests in a Web Worker: app/check_process_web.cpp).
#include <csignal>

#include "grade/child_process.h"
#include "grade/grade_run.h"
#include "grade/grader.h"
#include "grade/report_json.h"

namespace meshedit {

GradeReport grade(Suite& suite, const Submission& submission, const GradeOptions& options) {
  GradeRun grading(suite, submission, options);
  std::string filter_note;
  while (const std::optional<size_t> index = grading.next_test()) {
    const TestSpec& spec = suite.tests()[*index];
    if (options.on_test_start) options.on_test_start(spec);
    ChildLimits limits;
    limits.wall_seconds = spec.time_limit + options.kill_grace_seconds;
    limits.memory_bytes = options.child_memory_bytes + (spec.memory_mb << 20);
    limits.filter_syscalls = options.filter_syscalls;
    const ChildResult child =
        run_in_child(limits, [&] { return encode_test_run(suite.run_test_here(*index, submission)); });
    if (!child.filter_problem.empty() && filter_note.empty()) {
      filter_note = "Note: the system call filter is not available here (" + child.filter_problem +
                    "); the Lua sandbox and the process limits still apply.";
      grading.add_note(filter_note);
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
    grading.add_result(*index, run, child.seconds);
  }
  return grading.finish();
}

}  // namespace meshedit
