// CheckProcess: one run of the course's visible tests on the student's folder for File > Check my work, beside the
// window: on the desktop `meshedit grade --visible-only --report FILE --progress` in a child process
// (check_process_native.cpp); in a page, each test in a Web Worker (check_process_web.cpp, web/student_code_worker.js),
// the report made by the page as grade() makes it (grade/grade_run.h). Either way the window keeps drawing while
// student code runs, and Stop ends it at once.
//
// Invariants:
// - poll() never blocks: it reads what progress the child printed and notices its end; call it once per frame.
// - A run ends in exactly one of: a report (the grader graded: every test's verdict, even failed, timed out or crashed
//   ones), a problem (the grader could not grade: a suite that does not load, a missing folder; its own words), or
//   stopped (the student pressed Stop, or the object went away: the child is killed and reaped, never left behind).
// - The child's files live in a temporary folder of their own, removed when the run ends.
// - Nothing here throws: a child that cannot be started is a problem.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "grade/grade_types.h"

namespace meshedit {

class CheckProcess {
 public:
  CheckProcess();
  ~CheckProcess();
  CheckProcess(const CheckProcess&) = delete;
  CheckProcess& operator=(const CheckProcess&) = delete;

  // Whether this host can run a check.
  static bool available();

  // Starts a check of `submission` with `suite`, run by the program `meshedit` (the window's own program by default).
  // A run already going is stopped first. Returns false, with problem() set, when the child cannot be started.
  bool start(const std::filesystem::path& meshedit, const std::filesystem::path& suite,
             const std::filesystem::path& submission);
  void poll();
  void stop();

  bool running() const { return running_; }
  size_t tests_done() const { return done_; }
  size_t tests_total() const { return total_; }
  const std::string& running_test() const { return running_test_; }  // the name of the test running now, if known
  double seconds() const;                                            // since the start (to its end once it ended)

  const std::optional<GradeReport>& report() const { return report_; }
  const std::string& problem() const { return problem_; }
  bool stopped() const { return stopped_; }

 private:
  // What runs the tests: the desktop's child process and its files (check_process_native.cpp), or the page's
  // suite, grading and Web Worker (check_process_web.cpp).
  struct Host;
  void read_progress();     // the desktop's: what the child printed
  void finish(int status);  // the desktop's: the child ended with `status`
  void forget_files();      // the desktop's: its temporary folder removed
  void run_next_test();     // the page's: the next test sent to the worker, or the report made
  void take_worker_news();  // the page's: what the worker said since the last frame

  std::unique_ptr<Host> host_;
  bool running_ = false;
  size_t done_ = 0, total_ = 0;
  std::string running_test_;
  double started_ = 0.0, ended_ = 0.0;
  std::optional<GradeReport> report_;
  std::string problem_;
  bool stopped_ = false;
};

// The program the window runs its checks with: itself when it is `meshedit`, else the meshedit beside it.
std::filesystem::path check_program();

}  // namespace meshedit
