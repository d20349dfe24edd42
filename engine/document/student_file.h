// StudentFile: one exercise file of scripts/student (curve.lua, flip.lua...) loaded into its own StudentCode and
// loaded again when it is saved. The exercises panel (exercise_session.h) and the curve and patch views' "mine"
// switch (bezier_mine.h) both read student code through it.
//
// Invariants:
// - ensure_loaded() loads the file into a fresh StudentCode when its path, modification time or size differ
//   from the last attempt (one or two stat calls otherwise), so saving the file in an editor is enough.
// - A file that does not load (syntax error, error at its top level, missing) leaves code() null and keeps the
//   error, starting with "name.lua:LINE:" or "cannot open"; it is not tried again until the file changes, so
//   calling ensure_loaded() every frame never re-runs a broken file every frame.
// - serial() grows by one at every load attempt: what was computed from the code may be kept while it is the same.
// - Nothing here throws. Memory running out while the file loads is error() "memory ran out", and the file is tried
//   again at the next call, as if it had changed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "exercise/exercises.h"
#include "script/file_stamp.h"

namespace meshedit {

// scripts/student: beside the binary, in the installed layout or in the source tree (core/data_folders.h).
std::filesystem::path default_student_folder();
// scripts/exercises, found the same way: the exercises defined in Lua (exercise/scripted_exercise.h) the window and the
// lesson command register when they start.
std::filesystem::path default_exercise_folder();

class StudentFile {
 public:
  StudentFile() = default;
  explicit StudentFile(std::filesystem::path path) : path_(std::move(path)) {}

  const std::filesystem::path& path() const { return path_; }
  // Forgets the loaded code when the path differs (the next ensure_loaded loads afresh).
  void set_path(std::filesystem::path path);

  // The file differs from the last attempt (or there was none, or it cannot be read).
  bool changed() const;
  // Loads the file if changed(); true when code() is loaded.
  bool ensure_loaded();
  StudentCode* code() { return code_.get(); }
  // The loaded code, taken for a run on another thread: code() is null (and ensure_loaded() false, unless the file
  // changed and loads afresh) until give_back, which keeps it only while no load attempt came between (`serial`:
  // serial() when it was lent) and the path is the same.
  std::unique_ptr<StudentCode> lend() { return std::move(code_); }
  void give_back(std::unique_ptr<StudentCode> code, uint64_t serial);
  const std::string& error() const { return error_; }
  size_t loads() const { return loads_; }  // load attempts (tests)
  uint64_t serial() const { return loads_; }

 private:
  std::filesystem::path path_;
  std::unique_ptr<StudentCode> code_;
  bool attempted_ = false;
  std::filesystem::path attempted_path_;
  FileStamp attempted_stamp_;
  std::string error_;
  size_t loads_ = 0;
};

}  // namespace meshedit
