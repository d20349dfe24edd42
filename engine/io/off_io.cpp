// OFF reading (see off_io.h).
#include "io/off_io.h"

#include <optional>

#include "io/file_access.h"
#include "io/file_error.h"
#include "io/io_limits.h"
#include "io/text_scanner.h"

namespace meshedit {
namespace {

bool all_digits(std::string_view text) {
  return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

class OffReader {
 public:
  OffReader(std::string_view text, const std::string& name) : scanner_(text, name) { scanner_.set_comment_char('#'); }

  PolygonMesh read() {
    if (scanner_.at_end()) scanner_.fail(1, "file is empty");
    read_counts();
    mesh_.positions.reserve(num_vertices_);
    mesh_.face_offsets.reserve(num_faces_ + 1);
    for (size_t v = 0; v < num_vertices_; ++v) read_vertex(v);
    for (size_t f = 0; f < num_faces_; ++f) read_face(f);
    return std::move(mesh_);
  }

 private:
  // The keyword (optional) and the counts, up to the end of their line.
  void read_counts() {
    Token first = scanner_.expect("the OFF keyword");
    std::optional<Token> vertex_count, face_count;
    const size_t off = first.text.find("OFF");
    if (off != std::string_view::npos) {
      const std::string_view prefix = first.text.substr(0, off);
      const std::string_view rest = first.text.substr(off + 3);
      if (prefix.find_first_of("4n") != std::string_view::npos) {
        scanner_.fail(first.line, quote(first.text) + ": 4D and n-dimensional OFF files are not supported");
      }
      if (prefix.find_first_not_of("STCN") != std::string_view::npos || (!rest.empty() && !all_digits(rest))) {
        scanner_.fail(first.line, "expected the keyword OFF (or COFF, NOFF, STOFF), found " + quote(first.text));
      }
      if (!rest.empty()) vertex_count = Token{rest, first.line};
      const size_t line = first.line;
      if (auto word = scanner_.next_on_line(); word && word->text == "BINARY") {
        scanner_.fail(line, "binary OFF files are not supported");
      } else if (word) {
        if (vertex_count) {
          face_count = word;
        } else {
          vertex_count = word;
        }
      }
    } else {
      vertex_count = first;  // the keyword is optional
    }
    if (!vertex_count) vertex_count = scanner_.expect("the vertex count");
    const Token faces = face_count ? *face_count : scanner_.expect("the face count");
    const size_t counts_line = faces.line;
    num_vertices_ = static_cast<size_t>(
        parse_integer(*vertex_count, scanner_.file(), "the vertex count", 0, int64_t(kMaxVertices)));
    num_faces_ =
        static_cast<size_t>(parse_integer(faces, scanner_.file(), "the face count", 1, int64_t(kMaxCorners / 3)));
    if (scanner_.line() == counts_line) scanner_.skip_line();  // the edge count, when there is one
    // Each vertex takes at least 3 numbers and each face at least 1 (its corner count).
    const size_t remaining = scanner_.count_remaining();
    if (3 * num_vertices_ + num_faces_ > remaining) {
      scanner_.fail(counts_line, "declares " + std::to_string(num_vertices_) + " vertices and " +
                                     std::to_string(num_faces_) + " faces, but the file holds only " +
                                     std::to_string(remaining) + " numbers after the counts");
    }
  }

  void read_vertex(size_t v) {
    const std::string what = "vertex " + std::to_string(v);
    const Token x = scanner_.expect(what);
    double xyz[3] = {parse_real(x, scanner_.file(), what + " x"), 0, 0};
    for (int a = 1; a < 3; ++a) {
      const auto token = scanner_.next_on_line();
      if (!token) scanner_.fail(x.line, what + ": the line has " + std::to_string(a) + " numbers; x y z are needed");
      xyz[a] = parse_real(*token, scanner_.file(), what + (a == 1 ? " y" : " z"));
    }
    scanner_.skip_line();  // colours, normals, texture coordinates
    mesh_.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  // A face is kept whatever its number of corners: the builder refuses one of fewer than 3 by its number and mesh
  // repair drops it with a report.
  void read_face(size_t f) {
    const std::string what = "face " + std::to_string(f);
    const Token count_token = scanner_.expect(what);
    const auto count = static_cast<size_t>(
        parse_integer(count_token, scanner_.file(), what + "'s corner count", 0, int64_t(kMaxCorners)));
    if (mesh_.indices.size() + count > kMaxCorners) {
      scanner_.fail(count_token.line, "more than " + std::to_string(kMaxCorners) + " face corners in all");
    }
    for (size_t c = 0; c < count; ++c) {
      const auto token = scanner_.next_on_line();
      if (!token) {
        scanner_.fail(count_token.line, what + " declares " + std::to_string(count) + " corners, but its line has " +
                                            std::to_string(c) + " indices");
      }
      int64_t index = 0;
      const NumberStatus status = to_integer(token->text, index);
      if (status != NumberStatus::Ok) {
        scanner_.fail(token->line, what + ": expected a vertex index, found " + quote(token->text));
      }
      if (index < 0 || uint64_t(index) >= num_vertices_) {
        scanner_.fail(token->line, what + ": index " + quote(token->text) + " is not below the vertex count " +
                                       std::to_string(num_vertices_));
      }
      mesh_.indices.push_back(static_cast<uint32_t>(index));
    }
    scanner_.skip_line();  // a face colour
    mesh_.face_offsets.push_back(static_cast<uint32_t>(mesh_.indices.size()));
  }

  TextScanner scanner_;
  PolygonMesh mesh_;
  size_t num_vertices_ = 0;
  size_t num_faces_ = 0;
};

}  // namespace

PolygonMesh parse_off(std::string_view text, const std::string& name) { return OffReader(text, name).read(); }

PolygonMesh read_off(const std::filesystem::path& path) { return parse_off(read_file(path), path.string()); }

}  // namespace meshedit
