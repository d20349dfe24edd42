// Helpers for the grading tests: fixture files under tests/grading, submissions made in memory, a suite
// from text, grading with the small limits these tests use, and running the built meshedit.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "grade/grader.h"
#include "grade/submission.h"
#include "grade/suite.h"
#include "support/test_support.h"

namespace meshedit::testing {

inline std::filesystem::path grading_dir() { return source_dir() / "tests" / "grading"; }

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A submission of the given (name, text) files.
inline Submission submission_of(std::vector<std::pair<std::string, std::string>> files) {
  std::vector<SubmissionFile> list;
  for (auto& [name, text] : files) list.push_back({name, name, text});
  return Submission::from_files(std::move(list));
}

inline std::unique_ptr<Suite> suite_of(const std::string& text) {
  return Suite::from_text(text, "suite.lua", std::filesystem::temp_directory_path());
}

// What the built meshedit printed and its exit status.
struct Outcome {
  int status = -1;
  std::string out, err;
};

// Runs `meshedit ARGUMENTS` in `dir`, stdout and stderr kept in files there.
inline Outcome run_meshedit(const std::filesystem::path& dir, const std::string& arguments) {
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(MESHEDIT_BINARY) + "' " + arguments +
                              " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
}

// The children these tests start get a short grace after their time limit.
inline GradeOptions quick_options() {
  GradeOptions o;
  o.kill_grace_seconds = 0.5;
  return o;
}

}  // namespace meshedit::testing
