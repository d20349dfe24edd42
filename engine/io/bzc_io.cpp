// .bzc reading and writing (see bzc_io.h).
#include "io/bzc_io.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/value_format.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/io_limits.h"
#include "io/text_scanner.h"

namespace meshedit {

BezierCurve parse_bzc(std::string_view text, const std::string& name) {
  TextScanner scanner(text, name);
  if (scanner.at_end()) scanner.fail(1, "file is empty; expected the number of control points");
  const auto count = static_cast<uint64_t>(
      scanner.read_integer("the number of control points", 1, std::numeric_limits<int64_t>::max()));
  const size_t held = scanner.count_remaining();
  if (count > held / 2) {
    scanner.fail(scanner.line(), "file declares " + std::to_string(count) + " control points but holds only " +
                                     std::to_string(held) + " numbers (2 per point)");
  }
  if (count > kMaxVertices) {
    scanner.fail(scanner.line(), "more than " + std::to_string(kMaxVertices) + " control points");
  }
  BezierCurve curve;
  curve.control_points.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const std::string point = "point " + std::to_string(i + 1);
    const double x = scanner.read_real("x of " + point);
    const double y = scanner.read_real("y of " + point);
    curve.control_points.emplace_back(x, y);
  }
  if (auto extra = scanner.next()) {
    scanner.fail(extra->line, "unexpected " + quote(extra->text) + " after the last control point (the file declares " +
                                  std::to_string(count) + ")");
  }
  return curve;
}

BezierCurve read_bzc(const std::filesystem::path& path) { return parse_bzc(read_file(path), path.string()); }

std::string format_bzc(const BezierCurve& curve, const std::string& name) {
  if (curve.control_points.empty()) throw FileError(name, "", "a curve needs at least one control point");
  std::string out = std::to_string(curve.control_points.size()) + "\n";
  for (size_t i = 0; i < curve.control_points.size(); ++i) {
    const auto& p = curve.control_points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw FileError(name, "point " + std::to_string(i + 1), "coordinates must be finite");
    }
    append_number(out, p.x);
    out += ' ';
    append_number(out, p.y);
    out += '\n';
  }
  return out;
}

void write_bzc(const std::filesystem::path& path, const BezierCurve& curve) {
  write_file(path, format_bzc(curve, path.string()));
}

}  // namespace meshedit
