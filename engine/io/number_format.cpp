// Shortest round-trip number text (see number_format.h).
#include "io/number_format.h"

#include <charconv>

namespace meshedit {

void append_number(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace meshedit
