// StudentFile: see student_file.h for the contract.
#include "document/student_file.h"

#include <exception>
#include <new>
#include <utility>

#include "core/data_folders.h"
#include "script/exception_text.h"

namespace meshedit {

std::filesystem::path default_student_folder() { return data_folder("scripts/student"); }

std::filesystem::path default_exercise_folder() { return data_folder("scripts/exercises"); }

void StudentFile::set_path(std::filesystem::path path) {
  if (path == path_) return;
  path_ = std::move(path);
  code_.reset();
  attempted_ = false;
}

void StudentFile::give_back(std::unique_ptr<StudentCode> code, uint64_t serial) {
  if (!code_ && attempted_ && attempted_path_ == path_ && serial == loads_) code_ = std::move(code);
}

bool StudentFile::changed() const {
  if (!attempted_ || attempted_path_ != path_) return true;
  const FileStamp now = file_stamp(path_);
  return !now.readable || now != attempted_stamp_;
}

bool StudentFile::ensure_loaded() {
  if (!changed()) return code_ != nullptr;
  code_.reset();
  ++loads_;
  try {
    // Taken before loading: a save during the load makes the next call load again rather than miss it.
    attempted_stamp_ = file_stamp(path_);
    attempted_path_ = path_;
    attempted_ = true;
    code_ = load_student_file(path_);
  } catch (const std::bad_alloc&) {
    attempted_ = false;            // not the file's doing: the next call tries again
    error_ = kScriptMemoryRanOut;  // fits std::string's inline buffer: allocates nothing
    return false;
  } catch (const std::exception& e) {
    error_ = exception_text(e);
    return false;
  }
  error_.clear();
  return true;
}

}  // namespace meshedit
