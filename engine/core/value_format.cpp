// Shortest round-trip and rounded printing of doubles, counts with their nouns, byte sizes (see value_format.h).
#include "core/value_format.h"

#include <algorithm>
#include <cstdio>

#include "core/number_chars.h"

namespace meshedit {

void append_number(std::string& out, double x) {
  char buffer[32];  // the longest shortest form is 24 characters ("-2.2250738585072014e-308")
  char* const end = shortest_chars(buffer, buffer + sizeof buffer, x);
  if (end == nullptr) {
    out += '?';
    return;
  }
  out.append(buffer, end);
}

std::string format_number(double x) {
  std::string text;
  append_number(text, x);
  return text;
}

std::string format_rounded(double x, int digits) {
  char buffer[32];  // 17 digits, a sign, a point and a 4-character exponent
  std::snprintf(buffer, sizeof buffer, "%.*g", std::clamp(digits, 1, 17), x);
  return buffer;
}

std::string format_fixed(double x, int decimals) {
  char buffer[352];  // DBL_MAX has 309 digits before the point
  std::snprintf(buffer, sizeof buffer, "%.*f", std::clamp(decimals, 0, 17), x);
  return buffer;
}

std::string format_position(const glm::dvec3& p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + ")";
}

std::string plural(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string format_bytes(size_t bytes) {
  constexpr size_t kKilobyte = size_t(1) << 10, kMegabyte = size_t(1) << 20;
  if (bytes < kMegabyte) return std::to_string((bytes + kKilobyte - 1) / kKilobyte) + " KB";
  return std::to_string((bytes + kMegabyte - 1) / kMegabyte) + " MB";
}

}  // namespace meshedit
