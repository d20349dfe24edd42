// Tokens with line numbers and strict numbers (see text_scanner.h).
#include "io/text_scanner.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "core/number_chars.h"
#include "io/file_error.h"

namespace meshedit {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

// True when the token has a negative exponent ("1e-400"): an out-of-range value is then an underflow.
bool has_negative_exponent(std::string_view text) {
  const size_t e = text.find_first_of("eE");
  return e != std::string_view::npos && e + 1 < text.size() && text[e + 1] == '-';
}

std::string number_problem(NumberStatus status, std::string_view what, std::string_view token) {
  switch (status) {
    case NumberStatus::NotFinite: return std::string(what) + " must be a finite number, found " + quote(token);
    case NumberStatus::OutOfRange: return std::string(what) + " is out of range: " + quote(token);
    default: return "expected " + std::string(what) + ", found " + quote(token);
  }
}

}  // namespace

NumberStatus to_real(std::string_view text, double& out) {
  // from_chars refuses a leading '+', which some exporters write; accept exactly one before a digit.
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  if (text.empty()) return NumberStatus::NotANumber;
  double value = 0;
  bool out_of_range = false;
  const char* end = parse_chars(text.data(), text.data() + text.size(), value, out_of_range);
  if (end != text.data() + text.size()) return NumberStatus::NotANumber;
  if (out_of_range) {
    if (!has_negative_exponent(text)) return NumberStatus::OutOfRange;
    out = text[0] == '-' ? -0.0 : 0.0;
    return NumberStatus::Ok;
  }
  if (!std::isfinite(value)) return NumberStatus::NotFinite;
  out = value;
  return NumberStatus::Ok;
}

NumberStatus to_integer(std::string_view text, int64_t& out) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  if (text.empty()) return NumberStatus::NotANumber;
  int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, 10);
  if (end != text.data() + text.size()) return NumberStatus::NotANumber;
  if (ec == std::errc::result_out_of_range) return NumberStatus::OutOfRange;
  if (ec != std::errc()) return NumberStatus::NotANumber;
  out = value;
  return NumberStatus::Ok;
}

std::string quote(std::string_view token) {
  constexpr size_t kShown = 40;
  std::string out = "\"";
  const size_t shown = token.size() > kShown ? kShown : token.size();
  for (size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char* const kHex = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (shown < token.size()) out += "...";
  out += '"';
  return out;
}

double parse_real(const Token& token, const std::string& file, std::string_view what) {
  double value = 0;
  const NumberStatus status = to_real(token.text, value);
  if (status != NumberStatus::Ok) throw FileError(file, token.line, number_problem(status, what, token.text));
  return value;
}

int64_t parse_integer(const Token& token, const std::string& file, std::string_view what, int64_t min, int64_t max) {
  int64_t value = 0;
  const NumberStatus status = to_integer(token.text, value);
  if (status == NumberStatus::NotANumber) {
    throw FileError(file, token.line,
                    "expected " + std::string(what) + " (a whole number), found " + quote(token.text));
  }
  if (status != NumberStatus::Ok || value < min || value > max) {
    throw FileError(file, token.line,
                    std::string(what) + " must be between " + std::to_string(min) + " and " + std::to_string(max) +
                        ", found " + quote(token.text));
  }
  return value;
}

TextScanner::TextScanner(std::string_view text, std::string file, size_t first_line)
    : text_(text), file_(std::move(file)), line_(first_line) {}

bool TextScanner::is_continuation(size_t pos) const {
  // A backslash followed by "\n" or "\r\n".
  if (!continuations_ || text_[pos] != '\\') return false;
  if (pos + 1 < text_.size() && text_[pos + 1] == '\n') return true;
  return pos + 2 < text_.size() && text_[pos + 1] == '\r' && text_[pos + 2] == '\n';
}

bool TextScanner::skip_space(bool stop_at_newline) {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      if (stop_at_newline) return false;
      ++line_;
      ++pos_;
    } else if (is_space(c)) {
      ++pos_;
    } else if (is_continuation(pos_)) {
      while (text_[pos_] != '\n') ++pos_;
      ++pos_;
      ++line_;
    } else if (comment_ != 0 && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return true;
    }
  }
  return true;
}

std::optional<Token> TextScanner::next() {
  skip_space(false);
  if (pos_ >= text_.size()) return std::nullopt;
  const size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) && !is_continuation(pos_)) ++pos_;
  return Token{text_.substr(start, pos_ - start), line_};
}

std::optional<Token> TextScanner::next_on_line() {
  if (!skip_space(true) || pos_ >= text_.size()) return std::nullopt;
  return next();
}

void TextScanner::skip_line() {
  while (pos_ < text_.size()) {
    if (text_[pos_] == '\n') {
      ++pos_;
      ++line_;
      return;
    }
    if (is_continuation(pos_)) {
      while (text_[pos_] != '\n') ++pos_;
      ++line_;
    }
    ++pos_;
  }
}

bool TextScanner::at_end() {
  skip_space(false);
  return pos_ >= text_.size();
}

size_t TextScanner::count_remaining() const {
  TextScanner copy = *this;
  size_t count = 0;
  while (copy.next()) ++count;
  return count;
}

Token TextScanner::expect(std::string_view what) {
  auto token = next();
  if (!token) fail(line_, "file ends where " + std::string(what) + " was expected");
  return *token;
}

double TextScanner::read_real(std::string_view what) { return parse_real(expect(what), file_, what); }

int64_t TextScanner::read_integer(std::string_view what, int64_t min, int64_t max) {
  return parse_integer(expect(what), file_, what, min, max);
}

void TextScanner::fail(size_t line, const std::string& message) const { throw FileError(file_, line, message); }

}  // namespace meshedit
