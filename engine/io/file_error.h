// FileError: what every reader and writer throws. The message always starts with the file name and,
// when known, the place in it, in the `file:line: message` form editors and terminals understand:
//   teapot.bez:12: expected a number, found "0.5x"
//   scene.gltf: accessor 3: count 4000000000 exceeds the buffer view
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace meshedit {

class FileError : public std::runtime_error {
 public:
  // `place` is a line number ("12") or a named location ("accessor 3"); empty when not known.
  FileError(const std::string& file, const std::string& place, const std::string& message)
      : std::runtime_error(file + (place.empty() ? "" : (is_line(place) ? ":" : ": ") + place) + ": " + message) {}
  FileError(const std::string& file, size_t line, const std::string& message)
      : FileError(file, std::to_string(line), message) {}

 private:
  static bool is_line(const std::string& place) { return place.find_first_not_of("0123456789") == std::string::npos; }
};

}  // namespace meshedit
