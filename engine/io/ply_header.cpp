// PLY header parsing (see ply_header.h).
#include "io/ply_header.h"

#include <array>

#include "io/file_error.h"
#include "io/text_scanner.h"

namespace meshedit {
namespace {

struct TypeName {
  std::string_view name;
  PlyType type;
};

constexpr std::array<TypeName, 16> kTypeNames = {{
    {"char", PlyType::Int8},
    {"uchar", PlyType::Uint8},
    {"short", PlyType::Int16},
    {"ushort", PlyType::Uint16},
    {"int", PlyType::Int32},
    {"uint", PlyType::Uint32},
    {"float", PlyType::Float32},
    {"double", PlyType::Float64},
    {"int8", PlyType::Int8},
    {"uint8", PlyType::Uint8},
    {"int16", PlyType::Int16},
    {"uint16", PlyType::Uint16},
    {"int32", PlyType::Int32},
    {"uint32", PlyType::Uint32},
    {"float32", PlyType::Float32},
    {"float64", PlyType::Float64},
}};

// A header is text; this long is far more than any real one (the Stanford files' are under 300 bytes).
constexpr size_t kMaxHeaderBytes = size_t(1) << 20;

// The whitespace-separated words of one header line.
std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

}  // namespace

size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::Uint8: return 1;
    case PlyType::Int16:
    case PlyType::Uint16: return 2;
    case PlyType::Int32:
    case PlyType::Uint32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

bool ply_type_is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

const char* ply_type_name(PlyType type) {
  for (const TypeName& entry : kTypeNames) {
    if (entry.type == type) return entry.name.data();
  }
  return "?";
}

int PlyElement::find(std::string_view property) const {
  for (size_t i = 0; i < properties.size(); ++i) {
    if (properties[i].name == property) return static_cast<int>(i);
  }
  return -1;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) throw FileError(name, "", "file is empty");
  PlyHeader header;
  bool have_format = false;
  size_t pos = 0;
  size_t line_number = 0;
  while (true) {
    const size_t end = bytes.find('\n', pos);
    ++line_number;
    if (end > kMaxHeaderBytes) {  // npos too: no newline at all
      throw FileError(name, line_number, "the header has no end_header line");
    }
    const std::string_view line = bytes.substr(pos, end - pos);
    pos = end + 1;
    const std::vector<std::string_view> words = words_of(line);
    auto fail = [&](const std::string& message) -> void { throw FileError(name, line_number, message); };
    if (line_number == 1) {
      if (words.size() != 1 || words[0] != "ply") fail("not a PLY file: it must start with the line \"ply\"");
      continue;
    }
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    const std::string_view keyword = words[0];
    if (keyword == "end_header") {
      if (!have_format) fail("the header has no format line");
      header.body_offset = pos;
      header.body_line = line_number + 1;
      return header;
    }
    if (keyword == "format") {
      if (words.size() != 3) fail("expected \"format <ascii|binary_little_endian|binary_big_endian> 1.0\"");
      if (words[1] == "ascii") {
        header.format = PlyFormat::Ascii;
      } else if (words[1] == "binary_little_endian") {
        header.format = PlyFormat::BinaryLittleEndian;
      } else if (words[1] == "binary_big_endian") {
        header.format = PlyFormat::BinaryBigEndian;
      } else {
        fail("unknown format " + quote(words[1]));
      }
      if (words[2] != "1.0" && words[2] != "1") fail("unsupported PLY version " + quote(words[2]));
      have_format = true;
    } else if (keyword == "element") {
      if (words.size() != 3) fail("expected \"element <name> <count>\"");
      int64_t count = 0;
      const NumberStatus status = to_integer(words[2], count);
      if (status != NumberStatus::Ok || count < 0 || count > int64_t(UINT32_MAX)) {
        fail("element " + std::string(words[1]) + ": count must be a whole number below 2^32, found " +
             quote(words[2]));
      }
      header.elements.push_back({std::string(words[1]), static_cast<uint64_t>(count), line_number, {}});
    } else if (keyword == "property") {
      if (header.elements.empty()) fail("property before any element");
      auto type_of = [&](std::string_view word) {
        for (const TypeName& entry : kTypeNames) {
          if (entry.name == word) return entry.type;
        }
        fail("unknown property type " + quote(word));
        return PlyType::Uint8;
      };
      PlyProperty property;
      if (words.size() == 5 && words[1] == "list") {
        property.is_list = true;
        property.count_type = type_of(words[2]);
        if (!ply_type_is_integer(property.count_type)) fail("a list's count type must be an integer type");
        property.type = type_of(words[3]);
        property.name = words[4];
      } else if (words.size() == 3 && words[1] != "list") {
        property.type = type_of(words[1]);
        property.name = words[2];
      } else {
        fail("expected \"property <type> <name>\" or \"property list <count type> <item type> <name>\"");
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail("unknown header line " + quote(line));
    }
  }
}

}  // namespace meshedit
