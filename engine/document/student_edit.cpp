// StudentEdit: a student file's text as the window's editor changes it (see student_edit.h).
#include "document/student_edit.h"

#include <cctype>

#include "core/file_bytes.h"

namespace meshedit {

void StudentEdit::follow(const std::filesystem::path& path) {
  if (path != path_) {
    path_ = path;
    dirty_ = false;
    read();
    return;
  }
  if (!dirty_ && file_stamp(path_) != stamp_) read();
}

void StudentEdit::read() {
  changes_ += 1;
  stamp_ = file_stamp(path_);
  FileBytes file = read_file_bytes(path_, kMaxStudentFileBytes);
  text_ = std::move(file.bytes);
  read_error_ = file.ok() ? "" : path_.filename().string() + ": " + file.error;
  if (!file.ok()) text_.clear();
}

std::optional<size_t> StudentEdit::line_start(size_t line) const {
  if (line == 0) return std::nullopt;
  size_t start = 0;
  for (size_t at = 1; at < line; ++at) {
    const size_t end = text_.find('\n', start);
    if (end == std::string::npos) return std::nullopt;
    start = end + 1;
  }
  return start;
}

std::optional<std::string_view> StudentEdit::line(size_t line) const {
  const std::optional<size_t> start = line_start(line);
  if (!start) return std::nullopt;
  const size_t end = text_.find('\n', *start);
  return std::string_view(text_).substr(*start, end == std::string::npos ? std::string::npos : end - *start);
}

bool StudentEdit::set_line(size_t line, std::string_view text) {
  std::optional<size_t> start = line_start(line);
  if (!start && line > 1 && line_start(line - 1)) {  // one past the last line: a new line
    text_ += '\n';
    start = text_.size();
  }
  if (!start) return false;
  const size_t end = text_.find('\n', *start);
  text_.replace(*start, end == std::string::npos ? std::string::npos : end - *start, text);
  mark_edited();
  return true;
}

bool StudentEdit::take_draft(std::string draft) {
  if (draft == text_) return false;
  text_ = std::move(draft);
  mark_edited();
  return true;
}

Check StudentEdit::save() {
  if (path_.empty()) return Check::no("no student file to save");
  if (const std::string error = write_file_bytes(path_, text_); !error.empty()) {
    return Check::no(path_.filename().string() + ": " + error);
  }
  dirty_ = false;
  read_error_.clear();
  stamp_ = file_stamp(path_);
  return Check::yes();
}

std::optional<size_t> error_line_in(std::string_view error, std::string_view file_name) {
  if (file_name.empty()) return std::nullopt;
  for (size_t at = error.find(file_name); at != std::string_view::npos; at = error.find(file_name, at + 1)) {
    size_t colon = at + file_name.size();
    if (colon < error.size() && error[colon] == '"') colon += 1;  // [string "flip.lua"]:3:
    if (colon < error.size() && error[colon] == ']') colon += 1;
    if (colon >= error.size() || error[colon] != ':') continue;
    size_t line = 0, digit = colon + 1;
    while (digit < error.size() && std::isdigit(static_cast<unsigned char>(error[digit])) && line < 100000000) {
      line = line * 10 + size_t(error[digit] - '0');
      ++digit;
    }
    if (digit > colon + 1 && line > 0) return line;
  }
  return std::nullopt;
}

}  // namespace meshedit
