// The header of a PLY file ("ply", "format ...", "comment", "obj_info", "element NAME COUNT",
// "property TYPE NAME", "property list COUNT_TYPE ITEM_TYPE NAME", "end_header"), parsed into the
// elements and properties the body holds. The PLY reader (ply_io.h) reads the body from this.
//
// Invariants of a parsed header:
// - every property type is one of the eight PLY number types (char uchar short ushort int uint float
//   double, also spelled int8 uint8 int16 uint16 int32 uint32 float32 float64); a list's count type is
//   an integer type;
// - element counts are below 2^32 (a larger count is refused at its line, before anything is allocated);
// - `body_offset` is the byte just past the line break that ends "end_header".
// Errors are FileErrors naming the header line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/binary_bytes.h"

namespace meshedit {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyType { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);
// The name the header uses for the type ("uchar", "float").
const char* ply_type_name(PlyType type);

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::Uint8;  // lists only
  PlyType type = PlyType::Float32;      // the value's type, or a list item's type
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  size_t line = 0;  // the header line that declares it
  std::vector<PlyProperty> properties;

  // The index of the property with this name, or -1.
  int find(std::string_view property) const;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  size_t body_offset = 0;
  size_t body_line = 0;  // the line the body starts on (for ASCII bodies)
};

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name);

}  // namespace meshedit
