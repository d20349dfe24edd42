// Line breaks for English and Chinese text (see text_breaks.h).
#include "core/text_breaks.h"

namespace meshedit {
namespace {

// Punctuation that never starts a line: it stays with the character before it.
bool closing(char32_t c) {
  switch (c) {
    case U'，':
    case U'。':
    case U'、':
    case U'；':
    case U'：':
    case U'！':
    case U'？':
    case U'）':
    case U'」':
    case U'』':
    case U'》':
    case U'〉':
    case U'】':
    case U'”':
    case U'’':
    case U'…':
    case U'·':
    case U'～':
    case U',':
    case U'.':
    case U';':
    case U':':
    case U'!':
    case U'?':
    case U')':
    case U']':
    case U'%': return true;
    default: return false;
  }
}

// Punctuation that never ends a line: it stays with the character after it.
bool opening(char32_t c) {
  switch (c) {
    case U'（':
    case U'「':
    case U'『':
    case U'《':
    case U'〈':
    case U'【':
    case U'“':
    case U'‘':
    case U'(':
    case U'[': return true;
    default: return false;
  }
}

}  // namespace

char32_t utf8_at(std::string_view text, size_t i, size_t* length) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  size_t n = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
  char32_t c = n == 1 ? lead : n == 2 ? lead & 0x1Fu : n == 3 ? lead & 0x0Fu : lead & 0x07u;
  if (n == 0 || i + n > text.size()) n = 0;
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) {
      n = 0;
      break;
    }
    c = (c << 6) | (byte(i + k) & 0x3Fu);
  }
  *length = n == 0 ? 1 : n;
  return n == 0 ? char32_t(lead) : c;
}

bool wide_char(char32_t c) {
  return (c >= 0x2E80 && c <= 0x9FFF) || (c >= 0xAC00 && c <= 0xD7AF) || (c >= 0xF900 && c <= 0xFAFF) ||
         (c >= 0xFE30 && c <= 0xFE4F) || (c >= 0xFF00 && c <= 0xFFEF) || (c >= 0x20000 && c <= 0x3FFFF) || c == U'“' ||
         c == U'”' || c == U'‘' || c == U'’' || c == U'…';
}

std::vector<TextPiece> break_pieces(std::string_view line) {
  std::vector<TextPiece> pieces;
  bool space = false;                     // a space came since the last piece
  bool glue_next = false;                 // the last character was opening punctuation: the next one joins its piece
  bool last_wide = false;                 // the last character was wide: a narrow one after it may start a piece
  size_t start = std::string_view::npos;  // the piece being read
  const auto end_piece = [&](size_t at) {
    if (start == std::string_view::npos) return;
    pieces.back().text = line.substr(start, at - start);
    start = std::string_view::npos;
  };
  for (size_t i = 0; i < line.size();) {
    size_t n = 1;
    const char32_t c = utf8_at(line, i, &n);
    if (c == U' ' || c == U'\t') {
      end_piece(i);
      space = !pieces.empty();
      glue_next = false;
      i += n;
      continue;
    }
    const bool wide = wide_char(c);
    const bool joins = start != std::string_view::npos && (glue_next || closing(c) || (!wide && !last_wide));
    if (!joins) {
      end_piece(i);
      pieces.push_back({line.substr(i, n), space});
      start = i;
      space = false;
    }
    glue_next = opening(c);
    last_wide = wide;
    i += n;
  }
  end_piece(line.size());
  return pieces;
}

std::string without_spaces_between_wide(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == ' ' && !out.empty() && i + 1 < text.size() && joins_without_space(out, text.substr(i + 1))) continue;
    out += text[i];
  }
  return out;
}

bool joins_without_space(std::string_view before, std::string_view after) {
  if (before.empty() || after.empty()) return false;
  size_t start = before.size() - 1;
  while (start > 0 && (static_cast<unsigned char>(before[start]) & 0xC0) == 0x80) --start;
  size_t n = 1;
  const bool wide_before = wide_char(utf8_at(before, start, &n));
  return wide_before && wide_char(utf8_at(after, 0, &n));
}

}  // namespace meshedit
