// Deterministic mutations for the in-process fuzz tests: truncation, flipped bytes, huge and hostile
// numbers, deleted tokens, duplicated / swapped / deleted lines (duplicated XML tags), random bytes.
// Every choice comes from the caller's seeded generator, so a failure names a reproducible case.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace meshedit::testing {

class Mutator {
 public:
  explicit Mutator(uint64_t seed) : rng_(seed) {}

  // One to three random edits of `input`.
  std::string mutate(std::string text) {
    const size_t edits = 1 + below(3);
    for (size_t i = 0; i < edits; ++i) text = edit(std::move(text));
    return text;
  }

  size_t below(size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(rng_); }

 private:
  std::string edit(std::string text) {
    static const char* const kHostile[] = {"99999999999999999999",
                                           "4294967295",
                                           "4294967296",
                                           "2147483648",
                                           "-1",
                                           "-2147483649",
                                           "1e999",
                                           "-1e308",
                                           "nan",
                                           "-inf",
                                           "0",
                                           "1e-400",
                                           "18446744073709551615",
                                           "65536",
                                           "3.5",
                                           "0x10",
                                           "",
                                           "1e38"};
    if (text.empty()) return std::string(kHostile[below(std::size(kHostile))]);
    const size_t operation = below(10);
    switch (operation) {
      case 0:  // truncate
        text.resize(below(text.size()));
        break;
      case 1:  // flip one bit
        text[below(text.size())] ^= static_cast<char>(1u << below(8));
        break;
      case 2: {  // insert a hostile number at a random place
        const std::string number = kHostile[below(std::size(kHostile))];
        text.insert(below(text.size() + 1), " " + number + " ");
        break;
      }
      case 3: {  // replace a run of digits (a count, an index, an offset) with a hostile number
        for (int attempt = 0; attempt < 8; ++attempt) {
          const size_t at = below(text.size());
          if (text[at] < '0' || text[at] > '9') continue;
          size_t begin = at, end = at;
          while (begin > 0 && text[begin - 1] >= '0' && text[begin - 1] <= '9') --begin;
          while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
          text.replace(begin, end - begin, kHostile[below(std::size(kHostile))]);
          break;
        }
        break;
      }
      case 4: {  // delete a whitespace-separated token
        const size_t at = below(text.size());
        size_t begin = at, end = at;
        while (begin > 0 && !is_space(text[begin - 1])) --begin;
        while (end < text.size() && !is_space(text[end])) ++end;
        text.erase(begin, end - begin);
        break;
      }
      case 5:    // duplicate a line (in XML: a tag, often a whole element)
      case 6:    // swap two lines
      case 7: {  // delete a line
        std::vector<std::string> lines = split_lines(text);
        const size_t a = below(lines.size()), b = below(lines.size());
        if (operation == 5) {
          lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(a), lines[a]);
        } else if (operation == 6) {
          std::swap(lines[a], lines[b]);
        } else {
          lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(a));
        }
        text.clear();
        for (const std::string& line : lines) text += line + "\n";
        break;
      }
      case 8: {  // insert random bytes
        std::string junk(1 + below(16), '\0');
        for (char& c : junk) c = static_cast<char>(below(256));
        text.insert(below(text.size() + 1), junk);
        break;
      }
      default: {  // duplicate a random slice elsewhere
        const size_t begin = below(text.size());
        const size_t length = 1 + below(std::min<size_t>(200, text.size() - begin));
        text.insert(below(text.size() + 1), text.substr(begin, length));
        break;
      }
    }
    return text;
  }

  static bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }

  static std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start <= text.size()) {
      const size_t end = text.find('\n', start);
      lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
      if (end == std::string::npos) break;
      start = end + 1;
    }
    return lines;
  }

  std::mt19937_64 rng_;
};

}  // namespace meshedit::testing
