// run_in_child: fork, limits, pipes, the wall-clock kill (see child_process.h).
#include "grade/child_process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "grade/grade_run.h"
#include "grade/submission.h"
#include "grade/syscall_filter.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MESHEDIT_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define MESHEDIT_ASAN 1
#endif

namespace meshedit {
namespace {

constexpr int kReportFd = 3;
constexpr unsigned char kFilterFailed = 'F';

void set_limit(int resource, rlim_t soft, rlim_t hard) {
  rlimit r{soft, hard};
  setrlimit(resource, &r);
}

// The address space this process has now, from /proc (read before the filter forbids opening files).
size_t address_space_now() {
  std::ifstream statm("/proc/self/statm");
  size_t pages = 0;
  statm >> pages;
  return pages * static_cast<size_t>(sysconf(_SC_PAGESIZE));
}

bool write_all(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

[[noreturn]] void child_main(const ChildLimits& limits, pid_t parent, int out_fd, int err_fd, int report_fd,
                             const std::function<std::string()>& body) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(120);
  // Descriptors: 0 closed, 1 and 2 the output pipes, 3 the report pipe, nothing else.
  if (dup2(out_fd, 1) < 0 || dup2(err_fd, 2) < 0 || dup2(report_fd, kReportFd) < 0) _exit(121);
  close(0);
  close_range(kReportFd + 1, ~0u, 0);
  const size_t have = address_space_now();
  set_limit(RLIMIT_CORE, 0, 0);
  set_limit(RLIMIT_FSIZE, 0, 0);
  const auto cpu = static_cast<rlim_t>(std::ceil(limits.wall_seconds)) + 1;
  set_limit(RLIMIT_CPU, cpu, cpu + 1);
  if (geteuid() != 0) set_limit(RLIMIT_NPROC, 0, 0);
#ifndef MESHEDIT_ASAN
  if (limits.memory_bytes > 0) set_limit(RLIMIT_AS, have + limits.memory_bytes, have + limits.memory_bytes);
#else
  (void)have;
#endif
  // The first byte of the report pipe says whether the filter is on ('F' + the reason when it is not).
  std::string header(1, '\0');
  if (limits.filter_syscalls) {
    const std::string problem = install_syscall_filter();
    if (!problem.empty()) header = std::string(1, char(kFilterFailed)) + problem + '\n';
  }
  std::string report;
  try {
    report = body();
  } catch (const std::exception& e) {
    const std::string message = std::string("grading child: ") + e.what() + "\n";
    write_all(2, message.data(), message.size());
    _exit(122);
  } catch (...) {
    _exit(123);
  }
  if (!write_all(kReportFd, header.data(), header.size()) || !write_all(kReportFd, report.data(), report.size())) {
    _exit(124);
  }
  _exit(0);
}

struct Stream {
  int fd;
  std::string* text;
  size_t cap;
  bool open = true;
};

using Pipes = int[3][2];  // the child's stdout, stderr and report: [read end, write end] each

void close_pipes(Pipes& pipes, int count) {
  for (int i = 0; i < count; ++i) {
    close(pipes[i][0]);
    close(pipes[i][1]);
  }
}

void make_pipes(Pipes& pipes) {
  for (int i = 0; i < 3; ++i) {
    if (pipe2(pipes[i], O_CLOEXEC) != 0) {
      close_pipes(pipes, i);
      throw GradeError(std::string("cannot make a pipe for a test: ") + std::strerror(errno));
    }
  }
}

// Reads the streams (each up to its cap) until every one is closed; kills the child at the deadline, and stops
// waiting for a pipe that stays open after the kill.
void read_until_closed(pid_t pid, Stream (&streams)[3], std::chrono::steady_clock::time_point deadline,
                       ChildResult& result) {
  char buffer[65536];
  for (;;) {
    pollfd fds[3];
    nfds_t n = 0;
    Stream* which[3];
    for (auto& s : streams) {
      if (!s.open) continue;
      fds[n] = {s.fd, POLLIN, 0};
      which[n++] = &s;
    }
    if (n == 0) break;
    const auto now = std::chrono::steady_clock::now();
    if (!result.timed_out && now >= deadline) {
      kill(pid, SIGKILL);
      result.timed_out = true;
    }
    // After the kill the pipes close at once; until then wake at the deadline.
    const int wait_ms =
        result.timed_out
            ? 1000
            : static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1;
    const int ready = poll(fds, n, wait_ms);
    if (ready < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (nfds_t i = 0; i < n; ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t got = read(which[i]->fd, buffer, sizeof buffer);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        which[i]->open = false;
        continue;
      }
      std::string& text = *which[i]->text;
      if (text.size() < which[i]->cap) text.append(buffer, std::min(size_t(got), which[i]->cap - text.size()));
    }
    if (ready == 0 && result.timed_out) break;  // killed, yet a pipe stays open: stop waiting for it
  }
}

// The report pipe's text without its first byte (child_main's header), the filter's problem taken from it; kept as
// the result's report only when the child ended well and it fits.
void take_report(std::string& report, const ChildLimits& limits, ChildResult& result) {
  if (!report.empty() && static_cast<unsigned char>(report[0]) == kFilterFailed) {
    const size_t end = report.find('\n');
    result.filter_problem = report.substr(1, end == std::string::npos ? std::string::npos : end - 1);
    report.erase(0, end == std::string::npos ? report.size() : end + 1);
  } else if (!report.empty()) {
    report.erase(0, 1);
  }
  result.report_complete = result.exit_code == 0 && !result.timed_out && report.size() <= limits.report_bytes;
  if (result.report_complete) result.report = std::move(report);
}

}  // namespace

ChildResult run_in_child(const ChildLimits& limits, const std::function<std::string()>& body) {
  Pipes pipes;
  make_pipes(pipes);
  const pid_t parent = getpid();
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) {
    close_pipes(pipes, 3);
    throw GradeError(std::string("cannot start a process for a test: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // dup2 clears O_CLOEXEC on the copies; the originals close at _exit anyway.
    child_main(limits, parent, pipes[0][1], pipes[1][1], pipes[2][1], body);
  }
  for (auto& p : pipes) close(p[1]);

  ChildResult result;
  std::string report;
  Stream streams[3] = {{pipes[0][0], &result.out, limits.output_bytes},
                       {pipes[1][0], &result.err, limits.output_bytes},
                       {pipes[2][0], &report, limits.report_bytes + 4096}};
  const auto deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                    std::chrono::duration<double>(limits.wall_seconds));
  read_until_closed(pid, streams, deadline, result);
  for (auto& s : streams) close(s.fd);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  take_report(report, limits, result);
  return result;
}

std::string describe_child_end(const ChildResult& result, double time_limit) {
  std::ostringstream s;
  if (result.timed_out) {
    s << wall_clock_stop_sentence(time_limit);
  } else if (result.signal == SIGXCPU) {
    s << "stopped: CPU time limit exceeded";
  } else if (result.signal != 0) {
    s << "the test process was killed by signal " << result.signal << " (" << strsignal(result.signal) << ")";
    if (result.signal == SIGKILL || result.signal == SIGABRT || result.signal == SIGSEGV) {
      s << "; running out of memory can cause this";
    }
  } else if (result.exit_code != 0) {
    s << "the test process exited with status " << result.exit_code << " without a report";
  } else {
    s << "the test process sent an incomplete report";
  }
  return s.str();
}

}  // namespace meshedit
