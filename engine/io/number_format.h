// Writing doubles as text that reads back to the identical value (shortest round-trip form, "0.5",
// "1e-07"), independent of the C locale, for every text writer.
#pragma once

#include <string>

namespace meshedit {

// Appends the shortest decimal text that parses back to exactly `value` (which must be finite).
void append_number(std::string& out, double value);

}  // namespace meshedit
