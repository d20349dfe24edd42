// A Lua file's bytes as Lua is given them, and the note for text that is not UTF-8 (see lua_source.h).
#include "script/lua_source.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>

namespace meshedit {
namespace {

constexpr std::string_view kUtf8Mark = "\xEF\xBB\xBF";

// The length of the UTF-8 sequence at `at`, or 0 when the bytes there are not one.
size_t utf8_sequence(std::string_view text, size_t at) {
  const auto byte = [&](size_t i) { return static_cast<uint8_t>(text[i]); };
  const uint8_t lead = byte(at);
  if (lead < 0x80) return 1;
  size_t length = 0;
  uint32_t point = 0;
  if ((lead & 0xE0) == 0xC0) {
    length = 2;
    point = lead & 0x1F;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3;
    point = lead & 0x0F;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4;
    point = lead & 0x07;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  for (size_t i = 1; i < length; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) return 0;
    point = (point << 6) | (byte(at + i) & 0x3F);
  }
  constexpr uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (point < kSmallest[length] || point > 0x10FFFF || (point >= 0xD800 && point <= 0xDFFF)) return 0;
  return length;
}

bool looks_like_utf16(std::string_view text) {
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF")) return true;
  size_t zeros = 0;
  for (char c : text) zeros += c == '\0' ? 1 : 0;
  return zeros > 0 && zeros * 4 >= text.size();  // ASCII as UTF-16: every other byte is 0
}

}  // namespace

std::string lua_source_text(std::string bytes) {
  if (bytes.starts_with(kUtf8Mark)) bytes.erase(0, kUtf8Mark.size());
  if (bytes.starts_with('#')) bytes.insert(0, "--");
  return bytes;
}

std::string encoding_note(std::string_view text, const std::string& name) {
  if (looks_like_utf16(text)) return name + " is UTF-16 text, which Lua cannot read: save it as UTF-8";
  size_t line = 1;
  for (size_t at = 0; at < text.size();) {
    const size_t length = utf8_sequence(text, at);
    if (length == 0) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(static_cast<uint8_t>(text[at])));
      return name + " is not UTF-8 text (line " + std::to_string(line) + " has the byte " + byte +
             "): save it as UTF-8";
    }
    if (text[at] == '\n') ++line;
    at += length;
  }
  return "";
}

std::string with_encoding_note(const std::string& error, std::string_view text, const std::string& name) {
  const std::string note = encoding_note(text, name);
  return note.empty() ? error : error + " (" + note + ")";
}

}  // namespace meshedit
