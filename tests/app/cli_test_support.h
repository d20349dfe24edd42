// Running the built `meshedit` binary from a test: its status, stdout and stderr (the command-line tests share it).
// Invariant: the output files live in a folder of their own per process and `tag` (outside the test's scratch_dir,
// which scratch_dir() empties on each call), so parallel test processes never read each other's output.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace meshedit::testing {

struct CommandRun {
  int status = -1;
  std::string out, err;
};

inline std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs the meshedit binary with `args` (each shell-quoted), capturing stdout, stderr and the status.
inline CommandRun run_meshedit(const std::vector<std::string>& args, const std::string& tag) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "meshedit-tests" / (tag + "-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string command = shell_quoted(MESHEDIT_BINARY);
  for (const auto& a : args) command += " " + shell_quoted(a);
  command += " >" + shell_quoted((dir / "out").string()) + " 2>" + shell_quoted((dir / "err").string());
  CommandRun run;
  const int raw = std::system(command.c_str());
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = read_text(dir / "out");
  run.err = read_text(dir / "err");
  return run;
}

}  // namespace meshedit::testing
