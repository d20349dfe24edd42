// SpawnedProgram on the desktop: posix_spawn, a pipe read without blocking, waitpid (see spawned_program.h).
#include "app/spawned_program.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX declares it nowhere

namespace meshedit {
namespace {

constexpr size_t kPrintedCap = 64 << 10;

}  // namespace

std::string SpawnedProgram::start(const std::vector<std::string>& args, Output output) {
  stop();
  printed_.clear();
  status_ = 0;
  if (args.empty()) return "no program to start";
  std::array<int, 2> pipe_fds{-1, -1};
  if (pipe2(pipe_fds.data(), O_CLOEXEC) != 0) return std::strerror(errno);
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));  // NOLINT: posix_spawn's type
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  if (output == Output::StdoutAndStderr) {
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
  } else {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  }
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);  // its own group: stop() ends its children too
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(pipe_fds[1]);
  if (failed != 0) {
    close(pipe_fds[0]);
    return std::strerror(failed);
  }
  fcntl(pipe_fds[0], F_SETFL, fcntl(pipe_fds[0], F_GETFL) | O_NONBLOCK);
  pid_ = pid;
  pipe_ = pipe_fds[0];
  return "";
}

void SpawnedProgram::read_printed() {
  if (pipe_ < 0) return;
  std::array<char, 4096> buffer{};
  for (;;) {
    const ssize_t n = read(pipe_, buffer.data(), buffer.size());
    if (n <= 0) break;
    if (printed_.size() < kPrintedCap) printed_.append(buffer.data(), static_cast<size_t>(n));
  }
}

bool SpawnedProgram::poll() {
  if (!running()) return true;
  read_printed();
  int status = 0;
  const pid_t ended = waitpid(pid_, &status, WNOHANG);
  if (ended == 0) return false;
  read_printed();
  status_ = ended == pid_ ? status : -1;
  pid_ = -1;
  close_pipe();
  return true;
}

void SpawnedProgram::stop() {
  if (running()) {
    kill(-pid_, SIGKILL);
    kill(pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    status_ = status;
    pid_ = -1;
  }
  close_pipe();
}

void SpawnedProgram::close_pipe() {
  if (pipe_ >= 0) close(pipe_);
  pipe_ = -1;
}

int SpawnedProgram::exit_code() const { return status_ != -1 && WIFEXITED(status_) ? WEXITSTATUS(status_) : -1; }

std::string SpawnedProgram::end_words() const {
  if (status_ != -1 && WIFSIGNALED(status_)) {
    return "ended by signal " + std::to_string(WTERMSIG(status_)) + " (" + strsignal(WTERMSIG(status_)) + ")";
  }
  return "ended with status " + std::to_string(exit_code());
}

}  // namespace meshedit
