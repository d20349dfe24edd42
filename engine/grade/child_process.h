// run_in_child: runs a function in a forked child process under hard limits, and gives the parent what it
// sent back. This is the isolation around every test: whatever student code does (loops inside one C call,
// exhausts memory, crashes the interpreter), the parent process survives and reports it.
//
// Invariants:
// - The child: dies with the parent (PR_SET_PDEATHSIG), has stdin closed and stdout/stderr on pipes, keeps
//   no other inherited descriptor but the report pipe, and runs under RLIMIT_CPU, RLIMIT_AS (what it had at
//   the fork plus memory_bytes; skipped under AddressSanitizer), RLIMIT_FSIZE 0, RLIMIT_CORE 0, RLIMIT_NPROC
//   0 (where the user is not root), and the system call filter (syscall_filter.h). It leaves with _exit,
//   never exit(): no atexit handler or stdio buffer of the parent runs twice.
// - The body's return value is the report; the child writes it to its pipe and ends. The child never writes
//   a file.
// - The parent reads the three pipes together (poll), keeps at most the caps and drains the rest, so a child
//   printing without end cannot block or exhaust the parent; at the wall-clock deadline it sends SIGKILL.
//   It always reaps the child.
// - Call from a single-threaded process (fork copies only the calling thread).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace meshedit {

struct ChildLimits {
  double wall_seconds = 10.0;              // the parent kills the child after this
  size_t memory_bytes = size_t(1) << 30;   // address space the child may add after the fork; 0: no limit
  size_t output_bytes = size_t(64) << 10;  // of stdout and of stderr, each
  size_t report_bytes = size_t(16) << 20;
  bool filter_syscalls = true;
};

struct ChildResult {
  std::string report;            // what the body returned (empty if it did not finish)
  bool report_complete = false;  // the child finished writing it and exited normally
  std::string out;               // the child's stdout and stderr, capped
  std::string err;
  bool timed_out = false;  // killed by the parent at the deadline
  int exit_code = -1;      // when it exited
  int signal = 0;          // when a signal ended it
  double seconds = 0.0;
  std::string filter_problem;  // why the syscall filter could not be installed ("" when it was)
};

// Runs `body` in a child. Throws GradeError only if the child cannot be started (fork or pipe failed).
ChildResult run_in_child(const ChildLimits& limits, const std::function<std::string()>& body);

// One sentence for a child that did not finish: "killed after 2 s (time limit)", "killed by signal 11
// (Segmentation fault)", "exited with status 3 without a report".
std::string describe_child_end(const ChildResult& result, double time_limit);

}  // namespace meshedit
