// markdown_to_plain (see lesson_text.h): one pass per line, code spans copied verbatim.
#include "lesson/lesson_text.h"

namespace meshedit {
namespace {

std::string inline_plain(std::string_view line) {
  std::string out;
  size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == '`') {  // a code span: copied as is up to the closing backtick
      const size_t close = line.find('`', i + 1);
      if (close != std::string_view::npos) {
        out.append(line.substr(i + 1, close - i - 1));
        i = close + 1;
        continue;
      }
    }
    if (c == '*') {  // ** or * around words: emphasis marks go
      i += (i + 1 < line.size() && line[i + 1] == '*') ? 2 : 1;
      continue;
    }
    if (c == '[') {  // [text](url) -> text (url)
      const size_t close = line.find(']', i + 1);
      if (close != std::string_view::npos && close + 1 < line.size() && line[close + 1] == '(') {
        const size_t end = line.find(')', close + 2);
        if (end != std::string_view::npos) {
          out += inline_plain(line.substr(i + 1, close - i - 1));
          out += " (";
          out.append(line.substr(close + 2, end - close - 2));
          out += ")";
          i = end + 1;
          continue;
        }
      }
    }
    out += c;
    ++i;
  }
  return out;
}

}  // namespace

std::string markdown_to_plain(std::string_view markdown) {
  std::string out;
  size_t start = 0;
  while (start <= markdown.size()) {
    size_t end = markdown.find('\n', start);
    if (end == std::string_view::npos) end = markdown.size();
    std::string_view line = markdown.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    // "# Heading" (up to six #) loses its marks.
    size_t hashes = 0;
    while (hashes < line.size() && hashes < 6 && line[hashes] == '#') ++hashes;
    if (hashes > 0 && hashes < line.size() && line[hashes] == ' ') line.remove_prefix(hashes + 1);
    // "- item" and "* item" keep a "- " in front.
    size_t indent = 0;
    while (indent < line.size() && line[indent] == ' ') ++indent;
    if (line.size() > indent + 1 && (line[indent] == '-' || line[indent] == '*') && line[indent + 1] == ' ') {
      out.append(indent, ' ');
      out += "- ";
      out += inline_plain(line.substr(indent + 2));
    } else {
      out += inline_plain(line);
    }
    if (end == markdown.size()) break;
    out += '\n';
    start = end + 1;
  }
  return out;
}

}  // namespace meshedit
