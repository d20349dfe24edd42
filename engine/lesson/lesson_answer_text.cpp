// parse_answer_text (see lesson_answer_text.h): split on separators, then read each word as a decimal or a fraction.
#include "lesson/internal/lesson_answer_text.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace meshedit {
namespace {

bool is_separator(char c) { return c == ',' || c == ';' || std::isspace(static_cast<unsigned char>(c)); }

// A decimal as strtod reads it, the whole word, finite; no hex, inf or nan (strtod would take them).
std::optional<double> decimal(const std::string& word) {
  if (word.empty()) return std::nullopt;
  for (char c : word) {
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+' && c != 'e' && c != 'E') {
      return std::nullopt;
    }
  }
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<double> number(const std::string& word) {
  const size_t slash = word.find('/');
  if (slash == std::string::npos) return decimal(word);
  const std::optional<double> a = decimal(word.substr(0, slash)), b = decimal(word.substr(slash + 1));
  if (!a || !b || *b == 0.0 || !std::isfinite(*a / *b)) return std::nullopt;
  return *a / *b;
}

}  // namespace

std::optional<std::vector<double>> parse_answer_text(std::string_view text, size_t components) {
  size_t first = 0, last = text.size();
  while (first < last && std::isspace(static_cast<unsigned char>(text[first]))) ++first;
  while (last > first && std::isspace(static_cast<unsigned char>(text[last - 1]))) --last;
  text = text.substr(first, last - first);
  if (text.size() >= 2) {
    const char open = text.front(), close = text.back();
    if ((open == '(' && close == ')') || (open == '[' && close == ']') || (open == '{' && close == '}')) {
      text = text.substr(1, text.size() - 2);
    }
  }
  std::vector<double> values;
  size_t i = 0;
  while (i < text.size()) {
    if (is_separator(text[i])) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < text.size() && !is_separator(text[end])) ++end;
    const std::optional<double> value = number(std::string(text.substr(i, end - i)));
    if (!value) return std::nullopt;
    values.push_back(*value);
    i = end;
  }
  if (values.size() != components) return std::nullopt;
  return values;
}

std::string answer_text_help(size_t components) {
  if (components == 1) return "Type a number, like 0.25 or 3/8.";
  if (components == 2) return "Type a point as x, y, like 0.5, 1.";
  return "Type a point as x, y, z, like 0.5, 1, 0.";
}

}  // namespace meshedit
