// SpawnedProgram: a program run beside the window, what it prints read without blocking: File > Check my work's grader
// (check_process.h) and File > Write-up's `meshedit writeup` (writeup_room.h). Desktop only
// (spawned_program_native.cpp): a page has no processes.
//
// Invariants:
// - poll() never blocks. The child's standard input is /dev/null; what it prints on stderr (and on stdout when asked)
//   is kept up to a cap, the rest dropped.
// - The child is in a process group of its own: stop() and the destructor kill the whole group and reap the child, so
//   nothing is ever left behind.
// - Nothing here throws: a child that cannot be started is start()'s returned sentence.
#pragma once

#include <string>
#include <vector>

namespace meshedit {

class SpawnedProgram {
 public:
  enum class Output { StderrOnly, StdoutAndStderr };

  SpawnedProgram() = default;
  ~SpawnedProgram() { stop(); }
  SpawnedProgram(const SpawnedProgram&) = delete;
  SpawnedProgram& operator=(const SpawnedProgram&) = delete;

  // Starts `args` (args[0] is the program's path); a child still running is stopped first. "" when it started, else
  // why not.
  std::string start(const std::vector<std::string>& args, Output output);
  // Reads what the child printed since the last call; true once it has ended (then status() says how).
  bool poll();
  // Kills the child and its group, and reaps it.
  void stop();

  bool running() const { return pid_ > 0; }
  const std::string& printed() const { return printed_; }
  // waitpid's status of the ended child, or -1 when it was reaped elsewhere (SIGCHLD ignored).
  int status() const { return status_; }
  // The exit code of a child that exited, -1 for one killed by a signal or reaped elsewhere.
  int exit_code() const;
  // "ended by signal 9 (Killed)" or "ended with status 3", from status().
  std::string end_words() const;

 private:
  void read_printed();
  void close_pipe();

  int pid_ = -1;
  int pipe_ = -1;
  std::string printed_;
  int status_ = 0;
};

}  // namespace meshedit
