// PLY reading (see ply_io.h): the header from ply_header.h, then the body element by element, through one
// PlyBody that yields numbers from ASCII tokens or from binary bytes in either byte order. Polygons come from the
// face element as they are and from the tristrips element as triangles, streamed: nothing is allocated for a list
// before its items are read.
#include <cmath>
#include <limits>
#include <optional>

#include "io/file_access.h"
#include "io/file_error.h"
#include "io/io_limits.h"
#include "io/ply_header.h"
#include "io/ply_io.h"
#include "io/text_scanner.h"

namespace meshedit {
namespace {

// Where the reader is: the element and its index, for messages.
struct PlyPlace {
  const std::string* element = nullptr;
  uint64_t index = 0;
};

// The numbers of a PLY body in order, whatever its format. Integer values come back exactly (every PLY
// integer fits a double); binary floats may be NaN or infinite, and the caller decides whether that matters.
class PlyBody {
 public:
  PlyBody(std::string_view bytes, const std::string& name, const PlyHeader& header)
      : name_(name), format_(header.format), scanner_(bytes.substr(header.body_offset), name, header.body_line) {
    if (format_ != PlyFormat::Ascii) {
      bytes_ = bytes;
      offset_ = header.body_offset;
      order_ = format_ == PlyFormat::BinaryBigEndian ? ByteOrder::Big : ByteOrder::Little;
    }
  }

  bool binary() const { return format_ != PlyFormat::Ascii; }
  // What is left: bytes for a binary body, tokens for an ASCII one.
  uint64_t remaining() const { return binary() ? bytes_.size() - offset_ : scanner_.count_remaining(); }

  void set_place(const std::string& element, uint64_t index) { place_ = {&element, index}; }

  double read(PlyType type, std::string_view what) {
    if (binary()) return read_binary(type, what);
    const auto token = scanner_.next();
    if (!token) fail("file ends where " + std::string(what) + " was expected");
    line_ = token->line;
    if (ply_type_is_integer(type)) {
      int64_t value = 0;
      const NumberStatus status = to_integer(token->text, value);
      if (status != NumberStatus::Ok || !fits(type, value)) {
        fail("expected " + std::string(what) + " (" + ply_type_name(type) + "), found " + quote(token->text));
      }
      return double(value);
    }
    double value = 0;
    if (to_real(token->text, value) != NumberStatus::Ok) {
      fail("expected " + std::string(what) + " (a finite number), found " + quote(token->text));
    }
    return value;
  }

  // Skips `count` values of `type` (a list's items that are not used).
  void skip(PlyType type, uint64_t count, std::string_view what) {
    if (binary()) {
      value_start_ = offset_;
      if (count > (bytes_.size() - offset_) / ply_type_size(type)) {
        fail("file ends inside " + std::string(what) + " (" + std::to_string(count) + " values)");
      }
      offset_ += count * ply_type_size(type);
      return;
    }
    for (uint64_t i = 0; i < count; ++i) read(type, what);
  }

  [[noreturn]] void fail(const std::string& message) const {
    const std::string where = place_.element ? *place_.element + " " + std::to_string(place_.index) : "body";
    if (binary()) throw FileError(name_, where + ", byte " + std::to_string(value_start_), message);
    throw FileError(name_, line_ == 0 ? scanner_.line() : line_, where + ": " + message);
  }

 private:
  static bool fits(PlyType type, int64_t value) {
    switch (type) {
      case PlyType::Int8: return value >= -128 && value <= 127;
      case PlyType::Uint8: return value >= 0 && value <= 255;
      case PlyType::Int16: return value >= -32768 && value <= 32767;
      case PlyType::Uint16: return value >= 0 && value <= 65535;
      case PlyType::Int32:
        return value >= std::numeric_limits<int32_t>::min() && value <= std::numeric_limits<int32_t>::max();
      case PlyType::Uint32: return value >= 0 && value <= int64_t(UINT32_MAX);
      default: return true;
    }
  }

  double read_binary(PlyType type, std::string_view what) {
    const size_t size = ply_type_size(type);
    value_start_ = offset_;
    if (bytes_.size() - offset_ < size) fail("file ends where " + std::string(what) + " was expected");
    const uint64_t raw = load_unsigned(bytes_, offset_, size, order_);
    double value = 0;
    switch (type) {
      case PlyType::Int8: value = double(static_cast<int8_t>(raw)); break;
      case PlyType::Int16: value = double(static_cast<int16_t>(raw)); break;
      case PlyType::Int32: value = double(static_cast<int32_t>(raw)); break;
      case PlyType::Float32: value = double(load_float(bytes_, offset_, order_)); break;
      case PlyType::Float64: value = load_double(bytes_, offset_, order_); break;
      default: value = double(raw); break;
    }
    offset_ += size;
    return value;
  }

  const std::string& name_;
  PlyFormat format_;
  TextScanner scanner_;
  std::string_view bytes_;
  size_t offset_ = 0;
  size_t value_start_ = 0;  // where the last value read (or expected) starts: the byte messages name
  ByteOrder order_ = ByteOrder::Little;
  size_t line_ = 0;
  PlyPlace place_;
};

class PlyReader {
 public:
  PlyReader(std::string_view bytes, const std::string& name)
      : name_(name), header_(parse_ply_header(bytes, name)), body_(bytes, name, header_) {}

  PolygonMesh read() {
    find_elements();
    check_sizes();
    mesh_.positions.resize(vertices_->count);
    if (faces_) mesh_.face_offsets.reserve(faces_->count + 1);
    for (const PlyElement& element : header_.elements) {
      if (element.properties.empty()) continue;  // its items hold no bytes
      for (uint64_t i = 0; i < element.count; ++i) {
        body_.set_place(element.name, i);
        if (&element == vertices_) {
          read_vertex(element, i);
        } else if (&element == faces_) {
          read_polygons(element, face_indices_, false);
        } else if (&element == strips_) {
          read_polygons(element, strip_indices_, true);
        } else {
          skip_item(element);
        }
      }
    }
    if (mesh_.num_faces() == 0) throw FileError(name_, "", "file holds no faces");
    return std::move(mesh_);
  }

 private:
  void find_elements() {
    for (const PlyElement& element : header_.elements) {
      if (element.name == "vertex" && !vertices_) vertices_ = &element;
      if (element.name == "face" && !faces_) faces_ = &element;
      if (element.name == "tristrips" && !strips_) strips_ = &element;
    }
    if (!vertices_) throw FileError(name_, "", "the header declares no vertex element");
    if (!faces_ && !strips_) {
      throw FileError(name_, "", "file holds no faces (the header declares no face or tristrips element)");
    }
    const char* axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      xyz_[a] = vertices_->find(axes[a]);
      if (xyz_[a] < 0 || vertices_->properties[size_t(xyz_[a])].is_list) {
        throw FileError(name_, vertices_->line, std::string("the vertex element has no scalar property ") + axes[a]);
      }
    }
    if (faces_) face_indices_ = index_list(*faces_);
    if (strips_) strip_indices_ = index_list(*strips_);
  }

  // The element's list of vertex indices: vertex_indices, or vertex_index as some scanners write.
  int index_list(const PlyElement& element) const {
    int found = element.find("vertex_indices");
    if (found < 0) found = element.find("vertex_index");
    if (found < 0 || !element.properties[size_t(found)].is_list) {
      throw FileError(name_, element.line, "the " + element.name + " element has no list property vertex_indices");
    }
    if (!ply_type_is_integer(element.properties[size_t(found)].type)) {
      throw FileError(name_, element.line, element.name + " vertex indices must have an integer type");
    }
    return found;
  }

  // Declared counts against the limits and against what the body really holds, before any allocation.
  void check_sizes() {
    if (vertices_->count > kMaxVertices) {
      throw FileError(name_, vertices_->line,
                      "declares " + std::to_string(vertices_->count) + " vertices; MeshEdit reads up to " +
                          std::to_string(kMaxVertices));
    }
    if (faces_ && faces_->count > kMaxCorners / 3) {
      throw FileError(name_, faces_->line,
                      "declares " + std::to_string(faces_->count) + " faces; MeshEdit reads up to " +
                          std::to_string(kMaxCorners / 3));
    }
    const uint64_t available = body_.remaining();
    for (const PlyElement& element : header_.elements) {
      // The fewest bytes (binary) or tokens (ASCII) one item can take: empty lists count only their counts.
      uint64_t least = 0;
      for (const PlyProperty& p : element.properties) {
        least += body_.binary() ? ply_type_size(p.is_list ? p.count_type : p.type) : 1;
      }
      if (least > 0 && element.count > available / least) {
        throw FileError(name_, element.line,
                        "declares " + std::to_string(element.count) + " " + element.name + " elements, but the body " +
                            "holds only " + std::to_string(available) + (body_.binary() ? " bytes" : " numbers"));
      }
    }
  }

  void read_vertex(const PlyElement& element, uint64_t index) {
    double xyz[3] = {0, 0, 0};
    for (size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (property.is_list) {
        skip_list(property);
        continue;
      }
      const double value = body_.read(property.type, property.name);
      for (int a = 0; a < 3; ++a) {
        if (int(p) == xyz_[a]) {
          if (!std::isfinite(value)) body_.fail(property.name + " is not a finite number");
          xyz[a] = value;
        }
      }
    }
    mesh_.positions[index] = glm::dvec3(xyz[0], xyz[1], xyz[2]);
  }

  // One item of the face element (one polygon) or of the tristrips element (strips), its other properties skipped.
  void read_polygons(const PlyElement& element, int indices, bool strips) {
    for (size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (int(p) != indices) {
        property.is_list ? skip_list(property) : void(body_.read(property.type, property.name));
      } else if (strips) {
        read_strips(property);
      } else {
        read_face(property);
      }
    }
  }

  // A polygon, kept whatever its number of corners: the builder refuses one of fewer than 3 by its number and mesh
  // repair drops it with a report.
  void read_face(const PlyProperty& property) {
    const double count = body_.read(property.count_type, "the face's corner count");
    if (count < 0) body_.fail("face has a negative corner count " + format_count(count));
    if (mesh_.indices.size() + uint64_t(count) > kMaxCorners) {
      body_.fail("more than " + std::to_string(kMaxCorners) + " face corners in all");
    }
    for (uint64_t c = 0; c < uint64_t(count); ++c) {
      mesh_.indices.push_back(static_cast<uint32_t>(read_index(property, false)));
    }
    mesh_.face_offsets.push_back(static_cast<uint32_t>(mesh_.indices.size()));
  }

  // Triangle strips, one after another in one list, each ended by -1 (or the list's end): strip s0 s1 s2 s3 ... makes
  // the triangles (s0 s1 s2), (s2 s1 s3), (s2 s3 s4), ..., every other one flipped so that all keep the strip's first
  // winding. Degenerate triangles (two corners the same vertex), which strips use to join, are skipped.
  void read_strips(const PlyProperty& property) {
    const double count = body_.read(property.count_type, "the strips' index count");
    if (count < 0) body_.fail("the strips have a negative index count " + format_count(count));
    uint32_t before_last = 0, last = 0;
    uint64_t in_strip = 0;  // indices of the current strip read so far
    for (uint64_t c = 0; c < uint64_t(count); ++c) {
      const int64_t index = read_index(property, true);
      if (index < 0) {
        in_strip = 0;
        continue;
      }
      const auto v = static_cast<uint32_t>(index);
      if (in_strip >= 2 && before_last != last && last != v && before_last != v) {
        if (mesh_.indices.size() + 3 > kMaxCorners) {
          body_.fail("more than " + std::to_string(kMaxCorners) + " face corners in all");
        }
        const bool flipped = in_strip % 2 == 1;
        mesh_.add_face({flipped ? last : before_last, flipped ? before_last : last, v});
      }
      before_last = last;
      last = v;
      ++in_strip;
    }
  }

  // One vertex index, checked against the vertex count; -1 is returned for a strip's end when `strip_end` allows it.
  int64_t read_index(const PlyProperty& property, bool strip_end) {
    const double index = body_.read(property.type, "a vertex index");
    if (strip_end && index == -1) return -1;
    if (index < 0 || index >= double(vertices_->count)) {
      body_.fail("index " + format_count(index) + " is not below the vertex count " + std::to_string(vertices_->count));
    }
    return static_cast<int64_t>(index);
  }

  void skip_item(const PlyElement& element) {
    for (const PlyProperty& property : element.properties) {
      property.is_list ? skip_list(property) : void(body_.read(property.type, property.name));
    }
  }

  void skip_list(const PlyProperty& property) {
    const double count = body_.read(property.count_type, property.name + "'s count");
    if (count < 0) body_.fail(property.name + " has a negative count " + format_count(count));
    body_.skip(property.type, uint64_t(count), property.name);
  }

  static std::string format_count(double value) { return std::to_string(static_cast<int64_t>(value)); }

  const std::string& name_;
  PlyHeader header_;
  PlyBody body_;
  const PlyElement* vertices_ = nullptr;
  const PlyElement* faces_ = nullptr;
  const PlyElement* strips_ = nullptr;  // "tristrips", as some old Stanford scans have in place of "face"
  int xyz_[3] = {-1, -1, -1};
  int face_indices_ = -1;
  int strip_indices_ = -1;
  PolygonMesh mesh_;
};

}  // namespace

PolygonMesh parse_ply(std::string_view bytes, const std::string& name) { return PlyReader(bytes, name).read(); }

PolygonMesh read_ply(const std::filesystem::path& path) { return parse_ply(read_file(path), path.string()); }

}  // namespace meshedit
