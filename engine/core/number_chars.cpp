// std::to_chars / std::from_chars for doubles, or their equivalent where the library lacks them (see number_chars.h).
#include "core/number_chars.h"

#include <charconv>
#include <system_error>

#if !defined(__cpp_lib_to_chars)
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#endif

namespace meshedit {

#if defined(__cpp_lib_to_chars)

char* shortest_chars(char* first, char* last, double x) {
  const auto [end, error] = std::to_chars(first, last, x);
  return error == std::errc() ? end : nullptr;
}

const char* parse_chars(const char* first, const char* last, double& value, bool& out_of_range) {
  const auto [end, error] = std::from_chars(first, last, value, std::chars_format::general);
  out_of_range = error == std::errc::result_out_of_range;
  return error == std::errc() || out_of_range ? end : first;
}

#else

namespace {

// The text "d.ddde+X" with its last mantissa digit one higher, when that needs no carry into the exponent: printf
// rounds an exact tie to even, and the digits one up may be the ones that read back.
bool bump_last_digit(char* text) {
  char* p = std::strchr(text, 'e');
  for (--p; p >= text; --p) {
    if (*p == '.' || *p == '-') continue;
    if (*p != '9') {
      ++*p;
      return true;
    }
    *p = '0';
  }
  return false;
}

// x's shortest decimal digits (no trailing zeros) and the exponent of the first: x = d.ddd * 10^exponent.
void shortest_digits(double x, std::string& digits, int& exponent) {
  char buffer[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*e", precision - 1, x);
    if (std::strtod(buffer, nullptr) == x) break;
    char other[40];
    std::memcpy(other, buffer, sizeof other);
    if (bump_last_digit(other) && std::strtod(other, nullptr) == x) {
      std::memcpy(buffer, other, sizeof other);
      break;
    }
  }
  digits.clear();
  const char* p = buffer;
  for (; *p != 'e'; ++p) {
    if (*p >= '0' && *p <= '9') digits += *p;
  }
  exponent = std::atoi(p + 1);
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
}

size_t match_word(const char* first, const char* last, const char* word) {
  const size_t n = std::strlen(word);
  if (size_t(last - first) < n) return 0;
  for (size_t i = 0; i < n; ++i) {
    if (std::tolower(static_cast<unsigned char>(first[i])) != word[i]) return 0;
  }
  return n;
}

// The length of the longest prefix of [first, last) that from_chars's general format reads, after the sign.
size_t number_length(const char* first, const char* last) {
  if (size_t n = match_word(first, last, "infinity")) return n;
  if (size_t n = match_word(first, last, "inf")) return n;
  if (size_t n = match_word(first, last, "nan")) {
    const char* p = first + n;
    if (p != last && *p == '(') {
      const char* q = p + 1;
      while (q != last && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
      if (q != last && *q == ')') return size_t(q + 1 - first);
    }
    return n;
  }
  const char* p = first;
  size_t digits = 0;
  for (; p != last && *p >= '0' && *p <= '9'; ++p) ++digits;
  if (p != last && *p == '.') {
    for (++p; p != last && *p >= '0' && *p <= '9'; ++p) ++digits;
  }
  if (digits == 0) return 0;
  if (p != last && (*p == 'e' || *p == 'E')) {
    const char* q = p + 1;
    if (q != last && (*q == '+' || *q == '-')) ++q;
    const char* exponent_start = q;
    while (q != last && *q >= '0' && *q <= '9') ++q;
    if (q != exponent_start) p = q;
  }
  return size_t(p - first);
}

}  // namespace

char* shortest_chars(char* first, char* last, double x) {
  std::string text;
  if (std::isnan(x)) {
    text = std::signbit(x) ? "-nan" : "nan";
  } else if (std::isinf(x)) {
    text = x < 0 ? "-inf" : "inf";
  } else if (x == 0) {
    text = std::signbit(x) ? "-0" : "0";
  } else {
    std::string digits;
    int exponent = 0;
    shortest_digits(x, digits, exponent);
    std::string scientific = digits.substr(0, 1);
    if (digits.size() > 1) scientific += "." + digits.substr(1);
    const int magnitude = exponent < 0 ? -exponent : exponent;
    scientific += std::string(exponent < 0 ? "e-" : "e+") + (magnitude < 10 ? "0" : "") + std::to_string(magnitude);
    std::string fixed;
    if (exponent < 0) {
      fixed = "0." + std::string(size_t(-exponent - 1), '0') + digits;
    } else if (digits.size() <= size_t(exponent) + 1) {
      // An integer: fixed notation gives its exact digits, as printf's %f does, not the shortest ones padded.
      char exact[400];
      std::snprintf(exact, sizeof exact, "%.0f", std::fabs(x));
      fixed = exact;
    } else {
      fixed = digits.substr(0, size_t(exponent) + 1) + "." + digits.substr(size_t(exponent) + 1);
    }
    text = (x < 0 ? "-" : "") + (fixed.size() <= scientific.size() ? fixed : scientific);
  }
  if (text.size() > size_t(last - first)) return nullptr;
  std::memcpy(first, text.data(), text.size());
  return first + text.size();
}

const char* parse_chars(const char* first, const char* last, double& value, bool& out_of_range) {
  out_of_range = false;
  const bool negative = first != last && *first == '-';
  const size_t length = number_length(first + (negative ? 1 : 0), last);
  if (length == 0) return first;
  const std::string text(first, first + (negative ? 1 : 0) + length);
  errno = 0;
  const double parsed = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && (parsed == 0 || std::isinf(parsed))) {
    out_of_range = true;
  } else {
    value = parsed;
  }
  return first + text.size();
}

#endif

}  // namespace meshedit
