// Reading a whole file into memory under a size cap, and replacing a file's contents whole: the one reader behind io's
// read_file and every other file MeshEdit reads (shaders, images, fonts, scripts, lessons, suites, results, action
// scripts), and the writer behind io's write_file. They live in core, the module every other one depends on, so
// render reads through them too.
//
// Invariants:
// - Only regular files are opened: a directory, a FIFO or a device (/dev/zero would never end) is refused first.
// - No more than `max_bytes` are ever held: the file is read in chunks whatever size the file system reports, since
//   the file may change while it is read.
// - A write goes to a temporary file beside the target, renamed over the target once complete, so a failed save never
//   leaves a half-written file where the old one was.
// - A failure is a reason in words (FileBytes::error, "cannot open: No such file or directory"), never an
//   exception; only std::bad_alloc escapes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace meshedit {

// The largest file MeshEdit reads: a teaching editor has no use for more (at the vertex and corner limits of
// io/io_limits.h the mesh alone is about 0.5 GB).
inline constexpr size_t kMaxReadFileBytes = size_t(1) << 30;  // 1 GiB
// The largest student Lua file the window's editor takes: one it opens, a page's kept draft, a .lua dropped on it.
inline constexpr size_t kMaxStudentFileBytes = size_t(1) << 24;  // 16 MiB

struct FileBytes {
  std::string bytes;
  std::string error;  // why the file was not read, without its name; empty when it was
  bool ok() const { return error.empty(); }
};

FileBytes read_file_bytes(const std::filesystem::path& path, size_t max_bytes = kMaxReadFileBytes);

// Replaces the file's contents with `bytes`; "" when it did, else why not, without the file's name ("cannot write:
// Permission denied").
std::string write_file_bytes(const std::filesystem::path& path, std::string_view bytes);

}  // namespace meshedit
