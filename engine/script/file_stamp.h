// What "the student saved the file" means wherever the app watches a student's file (the Exercises tab's
// StudentFile, a lesson's your_turn): its modification time and its size, or that it cannot be read. A save that
// keeps the time (a coarse clock) still changes the stamp when the size changes.
#pragma once

#include <cstdint>
#include <filesystem>

namespace meshedit {

struct FileStamp {
  bool readable = false;  // false: missing or unreadable (time and size are then zero)
  std::filesystem::file_time_type time{};
  uintmax_t size = 0;

  bool operator==(const FileStamp&) const = default;
};

// The file's stamp now; never throws.
inline FileStamp file_stamp(const std::filesystem::path& file) noexcept {
  std::error_code error;
  FileStamp stamp;
  stamp.time = std::filesystem::last_write_time(file, error);
  if (error) return {};
  stamp.size = std::filesystem::file_size(file, error);
  if (error) return {};
  stamp.readable = true;
  return stamp;
}

}  // namespace meshedit
