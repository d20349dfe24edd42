// Whole-file reading and writing (see file_access.h).
#include "io/file_access.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

#include "io/file_error.h"
#include "io/io_limits.h"

namespace meshedit {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

std::string os_reason(int error_number) { return std::strerror(error_number); }

}  // namespace

std::string read_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec) throw FileError(name, "", "cannot open: " + ec.message());
  if (std::filesystem::is_directory(status)) throw FileError(name, "", "cannot open: " + os_reason(EISDIR));
  if (!std::filesystem::is_regular_file(status)) throw FileError(name, "", "cannot open: not a regular file");

  errno = 0;
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) throw FileError(name, "", "cannot open: " + os_reason(errno));

  // Read in chunks rather than trusting the size the file system reports: the file may change
  // underneath us, and chunked reads stop at the limit whatever the size claims.
  std::string bytes;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxFileBytes) {
    throw FileError(name, "",
                    "file is " + std::to_string(size) + " bytes; MeshEdit reads files up to " +
                        std::to_string(kMaxFileBytes) + " bytes");
  }
  if (!ec) bytes.reserve(static_cast<size_t>(size));
  char buffer[1 << 16];
  while (true) {
    const size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
    bytes.append(buffer, got);
    if (bytes.size() > kMaxFileBytes) {
      throw FileError(name, "", "file is larger than " + std::to_string(kMaxFileBytes) + " bytes");
    }
    if (got < sizeof buffer) break;
  }
  if (std::ferror(file.get())) throw FileError(name, "", "cannot read: " + os_reason(errno));
  return bytes;
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
