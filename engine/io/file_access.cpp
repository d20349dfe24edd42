// Whole-file reading and writing (see file_access.h).
#include "io/file_access.h"

#include "core/file_bytes.h"
#include "io/file_error.h"

namespace meshedit {

std::string read_file(const std::filesystem::path& path) {
  FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw FileError(path.string(), "", file.error);
  return std::move(file.bytes);
}

void write_file(const std::filesystem::path& path, std::string_view bytes) {
  const std::string error = write_file_bytes(path, bytes);
  if (!error.empty()) throw FileError(path.string(), "", error);
}

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return ext;
}

}  // namespace meshedit
