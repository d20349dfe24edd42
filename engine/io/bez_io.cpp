// .bez reading and writing (see bez_io.h).
#include "io/bez_io.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/value_format.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/io_limits.h"
#include "io/text_scanner.h"

namespace meshedit {
namespace {

constexpr size_t kNumbersPerPatch = size_t{16} * 3;
constexpr const char* kAxis[3] = {"x", "y", "z"};

}  // namespace

std::vector<BezierPatch> parse_bez(std::string_view text, const std::string& name) {
  TextScanner scanner(text, name);
  if (scanner.at_end()) scanner.fail(1, "file is empty; expected the number of patches");
  const auto count =
      static_cast<uint64_t>(scanner.read_integer("the number of patches", 1, std::numeric_limits<int64_t>::max()));
  const size_t held = scanner.count_remaining();
  if (count > held / kNumbersPerPatch) {
    scanner.fail(scanner.line(), "file declares " + std::to_string(count) + " patches but holds only " +
                                     std::to_string(held) + " numbers (48 per patch)");
  }
  if (count > kMaxVertices / 16) {
    scanner.fail(scanner.line(), "more than " + std::to_string(kMaxVertices / 16) + " patches");
  }
  std::vector<BezierPatch> patches(count);
  for (size_t p = 0; p < count; ++p) {
    for (size_t i = 0; i < 16; ++i) {
      for (int axis = 0; axis < 3; ++axis) {
        patches[p].points[i][axis] = scanner.read_real(std::string(kAxis[axis]) + " of point " + std::to_string(i + 1) +
                                                       " of patch " + std::to_string(p + 1));
      }
    }
  }
  if (auto extra = scanner.next()) {
    scanner.fail(extra->line, "unexpected " + quote(extra->text) + " after the last patch (the file declares " +
                                  std::to_string(count) + ")");
  }
  return patches;
}

std::vector<BezierPatch> read_bez(const std::filesystem::path& path) {
  return parse_bez(read_file(path), path.string());
}

std::string format_bez(const std::vector<BezierPatch>& patches, const std::string& name) {
  if (patches.empty()) throw FileError(name, "", "a patch file needs at least one patch");
  std::string out = std::to_string(patches.size()) + "\n";
  for (size_t p = 0; p < patches.size(); ++p) {
    for (size_t i = 0; i < 16; ++i) {
      const glm::dvec3& point = patches[p].points[i];
      for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(point[axis])) {
          throw FileError(name, "patch " + std::to_string(p + 1), "point " + std::to_string(i + 1) + " is not finite");
        }
        append_number(out, point[axis]);
        out += axis < 2 ? " " : (i % 4 == 3 ? "\n" : "   ");
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace meshedit
