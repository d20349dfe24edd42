// TextScanner: the whitespace-separated tokens of a text format with the line each one starts on, and
// the strict number parsing that .bzc, .bez, .obj and COLLADA arrays share.
//
// Invariants:
// - A token never contains whitespace (space, \t, \n, \v, \f, \r) and is never empty.
// - Lines count '\n' from the scanner's first line (1 for a file, the element's line for XML text).
// - A number is accepted only when the WHOLE token is a finite decimal number in range: "0.5x", "",
//   "nan", "inf", "0x1p3" and "1e999" are refused, with the token quoted in the message. A value too
//   small for a double ("1e-400") becomes 0: harmless, unlike an overflow.
// - Errors are FileErrors "file:line: message"; nothing here allocates more than the text it reads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace meshedit {

struct Token {
  std::string_view text;
  size_t line = 0;
};

enum class NumberStatus { Ok, NotANumber, NotFinite, OutOfRange };

// Non-throwing cores (exposed for readers that hold tokens of their own).
NumberStatus to_real(std::string_view text, double& out);
NumberStatus to_integer(std::string_view text, int64_t& out);

// `"0.5x"` for messages: non-printable bytes escaped as \xNN, tokens longer than 40 bytes shortened.
std::string quote(std::string_view token);

// Strict conversions that throw FileError(file, token.line, ...), naming `what` ("x of point 3").
double parse_real(const Token& token, const std::string& file, std::string_view what);
// A whole number in [min, max].
int64_t parse_integer(const Token& token, const std::string& file, std::string_view what, int64_t min, int64_t max);

class TextScanner {
 public:
  TextScanner(std::string_view text, std::string file, size_t first_line = 1);

  // With a comment character set, a token starting with it begins a comment to the end of the line
  // (OBJ's '#'); 0 turns comments off (the default).
  void set_comment_char(char c) { comment_ = c; }
  // With continuations on, a backslash right before a line break joins the two lines (OBJ).
  void set_line_continuations(bool on) { continuations_ = on; }

  // The next token anywhere ahead; nullopt at the end of the text.
  std::optional<Token> next();
  // The next token on the current line; nullopt at the end of the line (the line break stays).
  std::optional<Token> next_on_line();
  // Skips the rest of the current line and its line break.
  void skip_line();
  // True when only whitespace and comments are left.
  bool at_end();
  // Tokens from here to the end, counted without consuming them, so declared counts can be checked
  // against what the file really holds before anything is allocated.
  size_t count_remaining() const;
  // The current line (of the last token, or further on after skipping).
  size_t line() const { return line_; }
  const std::string& file() const { return file_; }

  // The next token as a number / whole number; at the end of the text: "file ends where <what> was
  // expected".
  double read_real(std::string_view what);
  int64_t read_integer(std::string_view what, int64_t min, int64_t max);
  // The next token, or the end-of-file error naming `what`.
  Token expect(std::string_view what);

  [[noreturn]] void fail(size_t line, const std::string& message) const;

 private:
  // Skips whitespace (and comments); stops before a line break when `stop_at_newline`.
  // Returns false if it stopped at a line break.
  bool skip_space(bool stop_at_newline);
  bool is_continuation(size_t pos) const;

  std::string_view text_;
  std::string file_;
  size_t pos_ = 0;
  size_t line_ = 1;
  char comment_ = 0;
  bool continuations_ = false;
};

}  // namespace meshedit
