// CheckProcess: one run of the course's visible tests on the student's folder for File > Check my work, beside the
// window: on the desktop `meshedit grade --visible-only --report FILE --progress` in a child process
// (check_process_native.cpp), so the window keeps drawing while student code runs and Stop ends it at once.
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
#include <optional>
#include <string>

#include "grade/grade_types.h"

namespace meshedit {

class CheckProcess {
 public:
  CheckProcess() = default;
  ~CheckProcess();
  CheckProcess(const CheckProcess&) = delete;
  CheckProcess& operator=(const CheckProcess&) = delete;

  // Whether this host can run a check (a page cannot start a process).
  static bool available();

  // Starts a check of `submission` with `suite`, run by the program `meshedit` (the window's own program by default).
  // A run already going is stopped first. Returns false, with problem() set, when the child cannot be started.
  bool start(const std::filesystem::path& meshedit, const std::filesystem::path& suite,
             const std::filesystem::path& submission);
  void poll();
  void stop();

  bool running() const { return pid_ > 0; }
  size_t tests_done() const { return done_; }
  size_t tests_total() const { return total_; }
  const std::string& running_test() const { return running_test_; }  // the name of the test running now, if known
  double seconds() const;                                            // since the start (to its end once it ended)

  const std::optional<GradeReport>& report() const { return report_; }
  const std::string& problem() const { return problem_; }
  bool stopped() const { return stopped_; }

 private:
  void read_progress();
  void finish(int status);
  void forget_files();

  int pid_ = -1;
  int progress_fd_ = -1;
  std::string progress_;  // what the child printed on stderr (capped)
  size_t done_ = 0, total_ = 0;
  std::string running_test_;
  double started_ = 0.0, ended_ = 0.0;
  std::filesystem::path folder_;
  std::optional<GradeReport> report_;
  std::string problem_;
  bool stopped_ = false;
};

// The program the window runs its checks with: itself when it is `meshedit`, else the meshedit beside it.
std::filesystem::path check_program();

}  // namespace meshedit
