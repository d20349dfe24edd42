// Shortest round-trip text of a double and strict parsing of one, as std::to_chars and std::from_chars give them, on
// every standard library: the std functions where the library has them for floating point (__cpp_lib_to_chars:
// libstdc++, the native build), and an equivalent made of snprintf and strtod where it does not (the LLVM libc++ of
// Debian's emscripten, the web build).
//
// Invariants (both implementations):
// - shortest_chars writes what std::to_chars(first, last, x) writes: the fewest significant digits that read back to
//   exactly x, in fixed or scientific notation, whichever is shorter (fixed on a tie); "nan", "-nan", "inf", "-inf",
//   "0", "-0". It returns the end of the text, or nullptr when [first, last) is too small.
// - parse_chars reads what std::from_chars(first, last, value, chars_format::general) reads: an optional '-', digits
//   with an optional point and exponent, or inf, infinity, nan, nan(...), ignoring case; no space, '+' or hex. It
//   returns the end of what it read (first when nothing was a number) and sets `out_of_range` when the value's
//   magnitude is beyond a double's (value is then not written).
#pragma once

namespace meshedit {

char* shortest_chars(char* first, char* last, double x);
const char* parse_chars(const char* first, const char* last, double& value, bool& out_of_range);

}  // namespace meshedit
