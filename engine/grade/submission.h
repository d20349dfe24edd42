// A student's submission: the Lua files in a folder, read into memory by the parent before any student code
// runs (the child that runs a test never opens a file).
//
// Invariants:
// - Only regular files ending in .lua are taken; symbolic links are never followed, so a submission cannot
//   make the grader read a suite or reference file as "student code".
// - A file is known by its base name ("flip.lua"). Files at the top of the folder win; a file found only in
//   a subfolder (students often zip their folder) is used too, and the notes say where it was found. Hidden
//   folders and __MACOSX are skipped; the search stops 4 folders deep.
// - Sizes are capped (kMaxSubmittedFileBytes each, kMaxFiles files); what is skipped is named in the notes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshedit {

// The grader itself could not work (a missing folder, a suite that does not load, a results file that
// cannot be written), as opposed to a submission that fails its tests.
class GradeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SubmissionFile {
  std::string name;      // base name, "flip.lua"
  std::string relative;  // path inside the submission folder, "hw/flip.lua"
  std::string text;
};

class Submission {
 public:
  static constexpr size_t kMaxSubmittedFileBytes = size_t(1) << 20;  // each .lua file; a larger one is skipped
  static constexpr size_t kMaxFiles = 200;

  // Reads every .lua file of `folder`. Throws GradeError when the folder does not exist or cannot be listed.
  static Submission read(const std::filesystem::path& folder);
  // A submission made in memory (tests).
  static Submission from_files(std::vector<SubmissionFile> files);

  const std::filesystem::path& folder() const { return folder_; }
  const std::vector<SubmissionFile>& files() const { return files_; }  // sorted by name
  const SubmissionFile* find(const std::string& name) const;
  // Things the student should know about the files ("flip.lua was found in hw/flip.lua").
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  std::filesystem::path folder_;
  std::vector<SubmissionFile> files_;
  std::vector<std::string> notes_;
};

}  // namespace meshedit
