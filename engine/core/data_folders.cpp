// The folders of the program's files (see data_folders.h). The one place past page_memory where core asks the
// operating system something: the running program's path.
#include "core/data_folders.h"

#include <string>
#include <system_error>

#if defined(__APPLE__)
#include <mach-o/dyld.h>

#include <cstdint>
#elif defined(_WIN32)
#include <windows.h>
#endif

namespace meshedit {

std::filesystem::path program_folder() {
  std::error_code ec;
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
#elif defined(__APPLE__)
  std::uint32_t size = 0;
  _NSGetExecutablePath(nullptr, &size);  // asks for the size
  std::string buffer(size + 1, '\0');
  if (_NSGetExecutablePath(buffer.data(), &size) != 0) return {};
  const std::filesystem::path program = std::filesystem::canonical(buffer.c_str(), ec);  // may hold symlinks, ".."
#elif defined(_WIN32)
  std::wstring buffer(32768, L'\0');
  const DWORD length = GetModuleFileNameW(nullptr, buffer.data(), DWORD(buffer.size()));
  if (length == 0 || length >= buffer.size()) return {};
  buffer.resize(length);
  const std::filesystem::path program(buffer);
#else
  const std::filesystem::path program;
#endif
  if (ec || program.empty()) return {};
  return program.parent_path();
}

std::vector<std::filesystem::path> data_folder_candidates(std::string_view name) {
  std::vector<std::filesystem::path> candidates;
  if (const std::filesystem::path folder = program_folder(); !folder.empty()) {
    candidates.push_back(folder / std::filesystem::path(name));
    candidates.push_back(folder.parent_path() / "share" / "meshedit" / std::filesystem::path(name));
  }
  candidates.push_back(std::filesystem::path(MESHEDIT_DATA_DIR) / std::filesystem::path(name));
  return candidates;
}

std::filesystem::path data_folder(std::string_view name) {
  const std::vector<std::filesystem::path> candidates = data_folder_candidates(name);
  for (const std::filesystem::path& candidate : candidates) {
    std::error_code ec;
    if (std::filesystem::is_directory(candidate, ec)) return candidate;
  }
  return candidates.back();
}

}  // namespace meshedit
