// Wavefront .obj reading and writing (see obj_io.h).
#include "io/obj_io.h"

#include <cstdint>
#include <vector>

#include "core/value_format.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/io_limits.h"
#include "io/polygon_checks.h"
#include "io/text_scanner.h"

namespace meshedit {
namespace {

// A UTF-8 byte order mark before the first statement (Windows editors and some exporters write one) is not part of
// it: left in, it would hide a first `v` or `f` as an unknown statement.
std::string_view without_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  return text.substr(0, kBom.size()) == kBom ? text.substr(kBom.size()) : text;
}

class ObjReader {
 public:
  ObjReader(std::string_view text, const std::string& name) : scanner_(without_bom(text), name) {
    scanner_.set_comment_char('#');
    scanner_.set_line_continuations(true);
  }

  PolygonMesh read() {
    if (scanner_.at_end()) scanner_.fail(1, "file is empty");
    while (auto keyword = scanner_.next()) {
      if (keyword->text == "v") {
        read_vertex(*keyword);
      } else if (keyword->text == "f" || keyword->text == "fo") {
        read_face(*keyword);
      }
      scanner_.skip_line();
    }
    if (max_forward_ > mesh_.positions.size()) {
      refer_out_of_range(max_forward_line_, std::to_string(max_forward_), "defined");
    }
    if (mesh_.num_faces() == 0) throw FileError(scanner_.file(), "", "file holds no faces");
    return std::move(mesh_);
  }

 private:
  void read_vertex(const Token& keyword) {
    if (mesh_.positions.size() >= kMaxVertices) {
      scanner_.fail(keyword.line, "more than " + std::to_string(kMaxVertices) + " vertices");
    }
    double numbers[3] = {0, 0, 0};
    size_t count = 0;
    static constexpr const char* kNames[7] = {"x", "y", "z", "w", "red", "green", "blue"};
    while (auto token = scanner_.next_on_line()) {
      if (count == 7) scanner_.fail(token->line, "vertex has more than 7 numbers (x y z [w] [r g b])");
      const std::string what = std::string("vertex ") + kNames[count];
      if (count < 3) {
        numbers[count] = parse_real(*token, scanner_.file(), what);
      } else {
        // w or a colour, dropped: any number will do, even nan (exporters write nan for a colour they lack).
        double dropped = 0;
        if (to_real(token->text, dropped) == NumberStatus::NotANumber) {
          scanner_.fail(token->line, "expected " + what + ", found " + quote(token->text));
        }
      }
      ++count;
    }
    if (count < 3) {
      scanner_.fail(keyword.line, "vertex has " + std::to_string(count) + " coordinates; 3 are needed");
    }
    mesh_.positions.emplace_back(numbers[0], numbers[1], numbers[2]);
  }

  void read_face(const Token& keyword) {
    corners_.clear();
    while (auto token = scanner_.next_on_line()) corners_.push_back(read_corner(*token));
    // A face of fewer than 3 corners is kept as the file has it: the builder refuses it by its number and mesh repair
    // drops it with a report.
    if (mesh_.indices.size() + corners_.size() > kMaxCorners) {
      scanner_.fail(keyword.line, "more than " + std::to_string(kMaxCorners) + " face corners in all");
    }
    mesh_.add_face(corners_);
  }

  // One corner "i", "i/t", "i//n" or "i/t/n", where t and n may be empty ("i/", "i//", "i/t/"); returns the 0-based
  // vertex index.
  uint32_t read_corner(const Token& token) {
    std::string_view parts[3];
    size_t num_parts = 0;
    std::string_view rest = token.text;
    while (true) {
      const size_t slash = rest.find('/');
      if (num_parts == 3) scanner_.fail(token.line, "face corner " + quote(token.text) + " has more than 3 parts");
      parts[num_parts++] = rest.substr(0, slash);
      if (slash == std::string_view::npos) break;
      rest.remove_prefix(slash + 1);
    }
    // The vertex part is needed; an empty texture or normal part means the corner has none.
    check_index_part(token, parts[0], "vertex index");
    if (num_parts >= 2 && !parts[1].empty()) check_index_part(token, parts[1], "texture index");
    if (num_parts == 3 && !parts[2].empty()) check_index_part(token, parts[2], "normal index");

    int64_t index = 0;
    to_integer(parts[0], index);  // checked above
    const size_t defined = mesh_.positions.size();
    if (index > 0) {
      if (static_cast<uint64_t>(index) > kMaxVertices) refer_out_of_range(token.line, std::string(parts[0]), "defined");
      if (static_cast<uint64_t>(index) > defined && static_cast<uint64_t>(index) > max_forward_) {
        max_forward_ = static_cast<uint64_t>(index);
        max_forward_line_ = token.line;
      }
      return static_cast<uint32_t>(index - 1);
    }
    // Negative: -1 is the last vertex defined so far.
    if (static_cast<uint64_t>(-(index + 1)) >= defined) {
      refer_out_of_range(token.line, std::string(parts[0]) + " (counting back)", "defined so far");
    }
    return static_cast<uint32_t>(static_cast<int64_t>(defined) + index);
  }

  void check_index_part(const Token& token, std::string_view part, const char* what) {
    int64_t value = 0;
    const NumberStatus status = to_integer(part, value);
    if (status == NumberStatus::NotANumber) {
      scanner_.fail(token.line,
                    "face corner " + quote(token.text) + ": " + what + " " + quote(part) + " is not a whole number");
    }
    if (status == NumberStatus::OutOfRange) {
      scanner_.fail(token.line, "face corner " + quote(token.text) + ": " + what + " is out of range");
    }
    if (value == 0) scanner_.fail(token.line, "face corner " + quote(token.text) + ": OBJ indices start at 1, not 0");
  }

  [[noreturn]] void refer_out_of_range(size_t line, const std::string& index, const char* when) {
    scanner_.fail(line, "face refers to vertex " + index + ", but only " + std::to_string(mesh_.positions.size()) +
                            " are " + when);
  }

  TextScanner scanner_;
  PolygonMesh mesh_;
  std::vector<uint32_t> corners_;
  // The largest 1-based index that referred past the vertices defined at its line, and that line.
  uint64_t max_forward_ = 0;
  size_t max_forward_line_ = 0;
};

}  // namespace

PolygonMesh parse_obj(std::string_view text, const std::string& name) { return ObjReader(text, name).read(); }

PolygonMesh read_obj(const std::filesystem::path& path) { return parse_obj(read_file(path), path.string()); }

std::string format_obj(const PolygonMesh& mesh, const std::string& name) {
  require_writable(mesh, name);
  std::string out = "# MeshEdit OBJ: " + std::to_string(mesh.num_vertices()) + " vertices, " +
                    std::to_string(mesh.num_faces()) + " faces\n";
  for (const glm::dvec3& p : mesh.positions) {
    out += "v ";
    append_number(out, p.x);
    out += ' ';
    append_number(out, p.y);
    out += ' ';
    append_number(out, p.z);
    out += '\n';
  }
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    out += 'f';
    for (uint32_t v : mesh.face(f)) {
      out += ' ';
      out += std::to_string(v + 1);
    }
    out += '\n';
  }
  return out;
}

void write_obj(const std::filesystem::path& path, const PolygonMesh& mesh) {
  write_file(path, format_obj(mesh, path.string()));
}

}  // namespace meshedit
