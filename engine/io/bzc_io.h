// .bzc: one Bézier curve in the plane, as the CS184 course files store it:
//   N            the number of control points (at least 1)
//   x y  (N times)
// Tokens may be separated by any whitespace, lines do not matter. Anything after the N-th point is an
// error (it usually means N is wrong). The declared N is checked against the numbers the file really
// holds before anything is allocated.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/bezier.h"

namespace meshedit {

// `name` is the file name used in error messages.
BezierCurve parse_bzc(std::string_view text, const std::string& name);
BezierCurve read_bzc(const std::filesystem::path& path);

// Text that parse_bzc reads back to the same points, bit for bit. Throws FileError for a curve with no
// points or a non-finite coordinate.
std::string format_bzc(const BezierCurve& curve, const std::string& name);
void write_bzc(const std::filesystem::path& path, const BezierCurve& curve);

}  // namespace meshedit
