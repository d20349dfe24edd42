// Whole-file reading and writing (see file_access.h).
#include "io/file_access.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

#include "core/file_bytes.h"
#include "io/file_error.h"

namespace meshedit {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

std::string os_reason(int error_number) { return std::strerror(error_number); }

}  // namespace

std::string read_file(const std::filesystem::path& path) {
  FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw FileError(path.string(), "", file.error);
  return std::move(file.bytes);
}

void write_file(const std::filesystem::path& path, std::string_view bytes) {
  const std::string name = path.string();
  std::filesystem::path temp = path;
  temp += ".meshedit-tmp";
  {
    errno = 0;
    FilePtr file(std::fopen(temp.c_str(), "wb"));
    if (!file) throw FileError(name, "", "cannot write: " + os_reason(errno));
    const bool wrote = std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
    const int write_errno = errno;
    const bool closed = std::fclose(file.release()) == 0;
    if (!wrote || !closed) {
      const int reason = wrote ? errno : write_errno;
      std::remove(temp.c_str());
      throw FileError(name, "", "cannot write: " + os_reason(reason));
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::remove(temp.c_str());
    throw FileError(name, "", "cannot write: " + ec.message());
  }
}

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return ext;
}

}  // namespace meshedit
