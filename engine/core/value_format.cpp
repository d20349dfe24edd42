// Shortest round-trip printing of doubles (see value_format.h).
#include "core/value_format.h"

#include <charconv>

namespace meshedit {

std::string format_number(double x) {
  char buffer[32];  // the longest shortest form is 24 characters ("-2.2250738585072014e-308")
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
  if (error != std::errc()) return "?";
  return std::string(buffer, end);
}

std::string format_position(const glm::dvec3& p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + ")";
}

}  // namespace meshedit
