// Helpers for the grading tests: fixture files under tests/grading, submissions made in memory, a suite
// from text, and grading with the small limits these tests use.
#pragma once

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

// The children these tests start get a short grace after their time limit.
inline GradeOptions quick_options() {
  GradeOptions o;
  o.kill_grace_seconds = 0.5;
  return o;
}

}  // namespace meshedit::testing
