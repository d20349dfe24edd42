// CheckProcess on the desktop: `meshedit grade --visible-only` in a child process (see check_process.h).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <sstream>
#include <system_error>
#include <vector>

#include "app/check_process.h"
#include "core/data_folders.h"
#include "grade/report_json.h"
#include "grade/submission.h"
#include "io/file_access.h"

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX declares it nowhere

namespace meshedit {
namespace {

constexpr size_t kProgressCap = 64 << 10;
constexpr const char* kProgressPrefix = "meshedit grade: test ";

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// A folder of its own under the system's temporary folder, or empty.
std::filesystem::path make_run_folder() {
  std::error_code ec;
  std::string pattern = (std::filesystem::temp_directory_path(ec) / "meshedit-check-XXXXXX").string();
  if (ec) return {};
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (mkdtemp(buffer.data()) == nullptr) return {};
  return std::filesystem::path(buffer.data());
}

// What the child said besides its progress: the grader's own error ("meshedit grade: SUITE:3: ...").
std::string words_besides_progress(const std::string& printed) {
  std::istringstream lines(printed);
  std::string line, words;
  while (std::getline(lines, line)) {
    if (line.rfind(kProgressPrefix, 0) == 0 || line.empty()) continue;
    words += (words.empty() ? "" : "\n") + line;
  }
  return words;
}

}  // namespace

struct CheckProcess::Host {
  int pid = -1;
  int progress_fd = -1;
  std::string progress;  // what the child printed on stderr (capped)
  std::filesystem::path folder;
};

CheckProcess::CheckProcess() : host_(std::make_unique<Host>()) {}

bool CheckProcess::available() { return true; }

std::filesystem::path check_program() {
  const std::filesystem::path folder = program_folder();
  if (folder.empty()) return "meshedit";
  return folder / "meshedit";
}

CheckProcess::~CheckProcess() { stop(); }

double CheckProcess::seconds() const { return (running() ? now() : ended_) - started_; }

bool CheckProcess::start(const std::filesystem::path& meshedit, const std::filesystem::path& suite,
                         const std::filesystem::path& submission) {
  stop();
  report_.reset();
  problem_.clear();
  stopped_ = false;
  host_->progress.clear();
  done_ = total_ = 0;
  running_test_.clear();
  started_ = ended_ = now();
  host_->folder = make_run_folder();
  if (host_->folder.empty()) {
    problem_ = "Check my work could not make a temporary folder for the grader's files";
    return false;
  }
  std::array<int, 2> pipe_fds{-1, -1};
  if (pipe2(pipe_fds.data(), O_CLOEXEC) != 0) {
    problem_ = std::string("Check my work could not start the grader: ") + std::strerror(errno);
    forget_files();
    return false;
  }
  const std::vector<std::string> args = {meshedit.string(),
                                         "grade",
                                         "--suite",
                                         suite.string(),
                                         "--submission",
                                         submission.string(),
                                         "--visible-only",
                                         "--results",
                                         (host_->folder / "results.json").string(),
                                         "--report",
                                         (host_->folder / "check.json").string(),
                                         "--progress"};
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));  // NOLINT: posix_spawn's type
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);  // its own group: Stop ends its test children too
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(pipe_fds[1]);
  if (failed != 0) {
    close(pipe_fds[0]);
    problem_ = "Check my work could not start the grader " + meshedit.string() + ": " + std::strerror(failed);
    forget_files();
    return false;
  }
  fcntl(pipe_fds[0], F_SETFL, fcntl(pipe_fds[0], F_GETFL) | O_NONBLOCK);
  host_->pid = pid;
  host_->progress_fd = pipe_fds[0];
  running_ = true;
  return true;
}

void CheckProcess::read_progress() {
  if (host_->progress_fd < 0) return;
  std::array<char, 4096> buffer{};
  for (;;) {
    const ssize_t n = read(host_->progress_fd, buffer.data(), buffer.size());
    if (n <= 0) break;
    if (host_->progress.size() < kProgressCap) host_->progress.append(buffer.data(), static_cast<size_t>(n));
  }
  // The last whole progress line: "meshedit grade: test 3 of 14 running: NAME" or "... done: NAME".
  const size_t end = host_->progress.rfind('\n');
  if (end == std::string::npos) return;
  const size_t begin = host_->progress.rfind(kProgressPrefix, end);
  if (begin == std::string::npos) return;
  const std::string line =
      host_->progress.substr(begin + std::strlen(kProgressPrefix), end - begin - std::strlen(kProgressPrefix));
  unsigned long number = 0, total = 0;  // NOLINT(google-runtime-int): sscanf's type
  int rest = 0;
  if (std::sscanf(line.c_str(), "%lu of %lu %n", &number, &total, &rest) < 2 || rest <= 0) return;
  const std::string words = line.substr(static_cast<size_t>(rest));
  total_ = total;
  for (const char* state : {"running: ", "done: "}) {
    if (words.rfind(state, 0) != 0) continue;
    const bool running = state[0] == 'r';
    done_ = running ? number - 1 : number;
    running_test_ = running ? words.substr(std::strlen(state)) : std::string();
  }
}

void CheckProcess::poll() {
  if (!running()) return;
  read_progress();
  int status = 0;
  const pid_t ended = waitpid(host_->pid, &status, WNOHANG);
  if (ended == 0) return;
  read_progress();
  finish(ended == host_->pid ? status : -1);
}

void CheckProcess::finish(int status) {
  host_->pid = -1;
  running_ = false;
  ended_ = now();
  if (host_->progress_fd >= 0) close(host_->progress_fd);
  host_->progress_fd = -1;
  // status -1: the child was reaped elsewhere (SIGCHLD ignored): its report, when it wrote one, says how it went.
  std::error_code ec;
  const bool graded = status != -1 ? WIFEXITED(status) && WEXITSTATUS(status) == 0
                                   : std::filesystem::exists(host_->folder / "check.json", ec);
  if (graded) {
    try {
      report_ = decode_grade_report(read_file(host_->folder / "check.json"));
    } catch (const std::exception& e) {  // a GradeError, or a FileError for a report that was never written
      problem_ = std::string("the grader's report could not be read: ") + e.what();
    }
  } else {
    const std::string words = words_besides_progress(host_->progress);
    if (!words.empty()) problem_ = words;
    else if (status != -1 && WIFSIGNALED(status))
      problem_ = "the grader was ended by signal " + std::to_string(WTERMSIG(status)) + " (" +
                 strsignal(WTERMSIG(status)) + ")";
    else problem_ = "the grader ended with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  }
  forget_files();
}

void CheckProcess::stop() {
  if (running()) {
    kill(-host_->pid, SIGKILL);
    kill(host_->pid, SIGKILL);
    int status = 0;
    while (waitpid(host_->pid, &status, 0) < 0 && errno == EINTR) {
    }
    host_->pid = -1;
    running_ = false;
    ended_ = now();
    stopped_ = true;
  }
  if (host_->progress_fd >= 0) close(host_->progress_fd);
  host_->progress_fd = -1;
  forget_files();
}

void CheckProcess::forget_files() {
  if (host_->folder.empty()) return;
  std::error_code ec;
  std::filesystem::remove_all(host_->folder, ec);
  host_->folder.clear();
}

}  // namespace meshedit
