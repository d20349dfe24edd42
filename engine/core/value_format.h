// Printing numbers, positions, counts and sizes for people, tests and diffs: the one place each of them is written.
//
// Invariants:
// - A double's text is the shortest that reads back to exactly the same double (std::to_chars without a
//   precision), so two values print alike only when they are equal: a diff never shows "0.1 -> 0.1".
//   Special values print as "nan", "-nan", "inf", "-inf"; negative zero prints as "-0".
// - A byte size is rounded up, so a size or a sum never reads as less than a limit it exceeds.
#pragma once

#include <cstddef>
#include <string>

#include <glm/vec3.hpp>

namespace meshedit {

// "0.5", "1", "-0", "0.1", "1e+100".
std::string format_number(double x);
// The same text appended to `out` (what the file writers use, without a string per number).
void append_number(std::string& out, double x);
// "(0.5, 0, 1)".
std::string format_position(const glm::dvec3& p);
// "1 face", "12 faces": the count and the noun that agrees with it (`one` for exactly 1, else `many`).
std::string plural(size_t n, const char* one, const char* many);
// "12 KB" below a megabyte (2^20 bytes), else "300 MB".
std::string format_bytes(size_t bytes);

}  // namespace meshedit
