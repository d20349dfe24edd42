// Whole-file reading and writing for every format, with the errors people need: the file's name and
// the operating system's reason ("No such file or directory", "Is a directory", "Permission denied").
//
// Invariants: read_file only opens regular files (a FIFO or /dev/zero would hang or never end) no larger than
// kMaxReadFileBytes. write_file writes a temporary file beside the target and renames it over the target, so a failed
// save never leaves a half-written file where the old one was. Both are core/file_bytes.h's, with the reason in a
// FileError.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace meshedit {

// The file's bytes; throws FileError naming the file and the reason when it cannot be read.
std::string read_file(const std::filesystem::path& path);

// Replaces the file's contents with `bytes`; throws FileError naming the file and the reason.
void write_file(const std::filesystem::path& path, std::string_view bytes);

// The extension in lower case with its dot (".obj"), or "" when there is none.
std::string lowercase_extension(const std::filesystem::path& path);

}  // namespace meshedit
