// Printing numbers, positions, counts and sizes for people, tests and diffs: the one place each of them is written.
//
// Invariants:
// - A double's text is the shortest that reads back to exactly the same double (std::to_chars without a
//   precision), so two values print alike only when they are equal: a diff never shows "0.1 -> 0.1".
//   Special values print as "nan", "-nan", "inf", "-inf"; negative zero prints as "-0". A number shown rounded (a
//   slider's value, a plot's tick, a message) says how: format_rounded keeps significant digits, format_fixed keeps
//   decimals; both print the special values alike.
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
// The number to `digits` significant digits (1 to 17), trailing zeros dropped: format_rounded(1.0 / 3) is
// "0.333333", format_rounded(2.5e-7, 3) is "2.5e-07" (printf's %g).
std::string format_rounded(double x, int digits = 6);
// The number with exactly `decimals` decimals (0 to 17): format_fixed(0.5, 4) is "0.5000" (printf's %f).
std::string format_fixed(double x, int decimals);
// "(0.5, 0, 1)".
std::string format_position(const glm::dvec3& p);
// "1 face", "12 faces": the count and the noun that agrees with it (`one` for exactly 1, else `many`).
std::string plural(size_t n, const char* one, const char* many);
// "12 KB" below a megabyte (2^20 bytes), else "300 MB".
std::string format_bytes(size_t bytes);

}  // namespace meshedit
