// wrapped_text's template body (see text_breaks.h): included at its end only.
#pragma once

namespace meshedit {

template <typename Measure>
std::string wrapped_text(const std::string& text, float width, Measure measure) {
  std::string out;
  size_t line_start = 0;
  while (line_start <= text.size()) {
    size_t line_end = text.find('\n', line_start);
    if (line_end == std::string::npos) line_end = text.size();
    std::string line;
    for (const TextPiece& piece : break_pieces(std::string_view(text).substr(line_start, line_end - line_start))) {
      std::string longer = line;
      if (!line.empty() && piece.space_before) longer += ' ';
      longer += piece.text;
      if (!line.empty() && measure(longer) > width) {
        out += line + "\n";
        line = std::string(piece.text);
      } else {
        line = std::move(longer);
      }
    }
    out += line;
    if (line_end < text.size()) out += "\n";
    line_start = line_end + 1;
  }
  return out;
}

}  // namespace meshedit
