// Whole-file reading under a size cap, and whole-file writing (see file_bytes.h).
#include "core/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

namespace meshedit {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

std::string os_reason(int error_number) { return std::strerror(error_number); }

FileBytes failed(std::string reason) { return {{}, std::move(reason)}; }

}  // namespace

FileBytes read_file_bytes(const std::filesystem::path& path, size_t max_bytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec) return failed("cannot open: " + ec.message());
  if (std::filesystem::is_directory(status)) return failed("cannot open: " + os_reason(EISDIR));
  if (!std::filesystem::is_regular_file(status)) return failed("cannot open: not a regular file");

  errno = 0;
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) return failed("cannot open: " + os_reason(errno));

  // Read in chunks rather than trusting the size the file system reports: the file may change
  // underneath us, and chunked reads stop at the limit whatever the size claims.
  FileBytes out;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_bytes) {
    return failed("file is " + std::to_string(size) + " bytes; MeshEdit reads files up to " +
                  std::to_string(max_bytes) + " bytes");
  }
  if (!ec) out.bytes.reserve(static_cast<size_t>(size));
  char buffer[1 << 16];
  while (true) {
    const size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
    out.bytes.append(buffer, got);
    if (out.bytes.size() > max_bytes) return failed("file is larger than " + std::to_string(max_bytes) + " bytes");
    if (got < sizeof buffer) break;
  }
  if (std::ferror(file.get())) return failed("cannot read: " + os_reason(errno));
  return out;
}

std::string write_file_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path temp = path;
  temp += ".meshedit-tmp";
  {
    errno = 0;
    FilePtr file(std::fopen(temp.c_str(), "wb"));
    if (!file) return "cannot write: " + os_reason(errno);
    const bool wrote = std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
    const int write_errno = errno;
    const bool closed = std::fclose(file.release()) == 0;
    if (!wrote || !closed) {
      const int reason = wrote ? errno : write_errno;
      std::remove(temp.c_str());
      return "cannot write: " + os_reason(reason);
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::remove(temp.c_str());
    return "cannot write: " + ec.message();
  }
  return {};
}

}  // namespace meshedit
