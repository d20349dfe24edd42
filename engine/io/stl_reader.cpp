// STL reading (see stl_io.h): binary or ASCII by the rule there, corners welded by PositionWelder.
#include <cmath>

#include "io/binary_bytes.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/io_limits.h"
#include "io/position_welder.h"
#include "io/stl_io.h"
#include "io/text_scanner.h"

namespace meshedit {
namespace {

constexpr size_t kBinaryHeader = 84;  // 80 bytes of anything, then the uint32 triangle count
constexpr size_t kTriangleBytes = 50;

bool starts_with_solid(std::string_view bytes) {
  const size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && bytes.substr(first, 5) == "solid";
}

// Adds the triangle as the file has it, even when two of its corners merge into one vertex: such a zero-area
// triangle is the file's, and the builder names it (mesh repair drops it, and says so).
void add_triangle(PolygonMesh& mesh, PositionWelder& welder, const glm::dvec3 (&corners)[3]) {
  const uint32_t a = welder.vertex_at(corners[0]);
  const uint32_t b = welder.vertex_at(corners[1]);
  const uint32_t c = welder.vertex_at(corners[2]);
  mesh.add_face({a, b, c});
}

PolygonMesh parse_binary(std::string_view bytes, const std::string& name) {
  const uint64_t count = load_unsigned(bytes, 80, 4, ByteOrder::Little);
  if (count > (bytes.size() - kBinaryHeader) / kTriangleBytes) {
    throw FileError(name, "byte 80",
                    "the header declares " + std::to_string(count) + " triangles (" +
                        std::to_string(kBinaryHeader + count * kTriangleBytes) + " bytes), but the file has " +
                        std::to_string(bytes.size()) + " bytes");
  }
  if (count * 3 > kMaxCorners) {
    throw FileError(
        name, "byte 80",
        "declares " + std::to_string(count) + " triangles; MeshEdit reads up to " + std::to_string(kMaxCorners / 3));
  }
  PolygonMesh mesh;
  PositionWelder welder(mesh);
  mesh.face_offsets.reserve(count + 1);
  for (uint64_t t = 0; t < count; ++t) {
    const size_t start = kBinaryHeader + t * kTriangleBytes;
    glm::dvec3 corners[3];
    for (size_t c = 0; c < 3; ++c) {
      for (size_t a = 0; a < 3; ++a) {
        const size_t at = start + 12 + 12 * c + 4 * a;
        const double value = load_float(bytes, at, ByteOrder::Little);
        if (!std::isfinite(value)) {
          throw FileError(name, "triangle " + std::to_string(t) + ", byte " + std::to_string(at),
                          "corner " + std::to_string(c) + " is not a finite position");
        }
        corners[c][static_cast<int>(a)] = value;
      }
    }
    add_triangle(mesh, welder, corners);
  }
  return mesh;
}

class AsciiStlReader {
 public:
  AsciiStlReader(std::string_view text, const std::string& name) : scanner_(text, name) {}

  PolygonMesh read() {
    PositionWelder welder(mesh_);
    expect_word("solid");
    scanner_.skip_line();  // the solid's name, which may hold spaces
    while (auto word = scanner_.next()) {
      if (word->text == "endsolid") {
        scanner_.skip_line();
        if (scanner_.at_end()) return std::move(mesh_);
        expect_word("solid");
        scanner_.skip_line();
        continue;
      }
      if (word->text != "facet") fail_expected(*word, "\"facet\" or \"endsolid\"");
      read_facet(welder);
    }
    scanner_.fail(scanner_.line(), "file ends where \"endsolid\" was expected");
  }

 private:
  void read_facet(PositionWelder& welder) {
    scanner_.skip_line();  // "normal nx ny nz": ignored (exporters write anything there, even "nan")
    expect_word("outer");
    expect_word("loop");
    glm::dvec3 corners[3];
    for (glm::dvec3& corner : corners) {
      expect_word("vertex");
      for (int a = 0; a < 3; ++a) corner[a] = scanner_.read_real("a vertex coordinate");
    }
    expect_word("endloop");
    expect_word("endfacet");
    if (3 * (mesh_.num_faces() + 1) > kMaxCorners) {
      scanner_.fail(scanner_.line(), "more than " + std::to_string(kMaxCorners / 3) + " triangles");
    }
    add_triangle(mesh_, welder, corners);
  }

  void expect_word(std::string_view word) {
    const Token token = scanner_.expect("\"" + std::string(word) + "\"");
    if (token.text != word) fail_expected(token, "\"" + std::string(word) + "\"");
  }

  [[noreturn]] void fail_expected(const Token& token, const std::string& what) {
    scanner_.fail(token.line, "expected " + what + ", found " + quote(token.text));
  }

  TextScanner scanner_;
  PolygonMesh mesh_;
};

}  // namespace

PolygonMesh parse_stl(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) throw FileError(name, "", "file is empty");
  const bool solid = starts_with_solid(bytes);
  PolygonMesh mesh;
  if (bytes.size() >= kBinaryHeader &&
      (!solid || kBinaryHeader + load_unsigned(bytes, 80, 4, ByteOrder::Little) * kTriangleBytes == bytes.size())) {
    mesh = parse_binary(bytes, name);
  } else if (solid) {
    mesh = AsciiStlReader(bytes, name).read();
  } else {
    throw FileError(name, "",
                    "not an STL file: " + std::to_string(bytes.size()) +
                        " bytes, too short for a binary STL's 84-byte header, and no \"solid\" line");
  }
  if (mesh.num_faces() == 0) throw FileError(name, "", "file holds no triangles");
  return mesh;
}

PolygonMesh read_stl(const std::filesystem::path& path) { return parse_stl(read_file(path), path.string()); }

}  // namespace meshedit
