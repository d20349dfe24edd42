// .bez: bicubic Bézier patches, as the CS184 course files store them:
//   P                   the number of patches (at least 1)
//   16 points "x y z"   per patch, row-major: points[row * 4 + col]
// Tokens may be separated by any whitespace, lines do not matter. Anything after the last patch is an
// error. The declared P is checked against the numbers the file really holds before anything is
// allocated ("file declares 2147483648 patches but holds only 48 numbers").
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/bezier.h"

namespace meshedit {

// `name` is the file name used in error messages.
std::vector<BezierPatch> parse_bez(std::string_view text, const std::string& name);
std::vector<BezierPatch> read_bez(const std::filesystem::path& path);

// Text that parse_bez reads back to the same points, bit for bit; one patch row per line. Throws
// FileError for an empty list or a non-finite coordinate.
std::string format_bez(const std::vector<BezierPatch>& patches, const std::string& name);

}  // namespace meshedit
