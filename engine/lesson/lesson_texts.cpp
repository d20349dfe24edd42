// A lesson's texts in several languages and their checks (see lesson_texts.h).
#include "lesson/lesson_texts.h"

#include <algorithm>
#include <cctype>

namespace meshedit {
namespace {

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool latin(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

// The text with its code spans cut out, and the spans ("`h.next`") in `spans`.
std::string without_code(const std::string& text, std::vector<std::string>* spans) {
  std::string rest;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '`') {
      const size_t end = text.find('`', i + 1);
      if (end != std::string::npos) {
        if (spans) spans->push_back(text.substr(i, end + 1 - i));
        rest += ' ';
        i = end;
        continue;
      }
    }
    rest += text[i];
  }
  return rest;
}

// The tokens of `want` that `have` lacks (each counted as often as it appears).
std::vector<std::string> missing(const std::vector<std::string>& want, const std::vector<std::string>& have) {
  std::vector<std::string> out;
  std::set_difference(want.begin(), want.end(), have.begin(), have.end(), std::back_inserter(out));
  return out;
}

std::string shortened(const std::string& text) {
  std::string flat = text.substr(0, 70);
  std::replace(flat.begin(), flat.end(), '\n', ' ');
  return "\"" + flat + (text.size() > 70 ? "...\"" : "\"");
}

}  // namespace

std::vector<std::string> kept_tokens(const std::string& text) {
  std::vector<std::string> tokens;
  const std::string rest = without_code(text, &tokens);
  for (size_t i = 0; i < rest.size(); ++i) {
    if (!digit(rest[i])) continue;
    size_t end = i;
    while (end < rest.size() &&
           (digit(rest[end]) || (rest[end] == '.' && end + 1 < rest.size() && digit(rest[end + 1]))))
      ++end;
    tokens.push_back(rest.substr(i, end - i));
    i = end;
  }
  std::sort(tokens.begin(), tokens.end());
  return tokens;
}

bool has_words(const std::string& text) {
  const bool code_word = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::islower(static_cast<unsigned char>(c)) || digit(c) || c == '_' || c == '.' || c == ':';
  });
  if (code_word) return false;  // "next", "h.next", "flip_edge": a field or function name, the same in every language
  const std::string rest = without_code(text, nullptr);
  int run = 0;
  for (const char c : rest) {
    run = latin(c) ? run + 1 : 0;
    if (run >= 3) return true;
  }
  return false;
}

void LessonTexts::keep(const LocalText& text, const std::string& where) {
  const std::string& english = text.english();
  LocalText kept;
  kept.texts[0] = english;
  for (const Language language : kLanguages) {
    if (language == Language::English || !text.has(language)) continue;
    const std::string& translated = text.texts[size_t(language)];
    const std::vector<std::string> dropped = missing(kept_tokens(english), kept_tokens(translated));
    if (dropped.empty()) {
      kept.texts[size_t(language)] = translated;
      continue;
    }
    std::string list;
    for (const std::string& token : dropped) list += (list.empty() ? "" : ", ") + token;
    if (listed_.insert(where + "|drops|" + english).second) {
      problems_.push_back(where + ": the " + language_code(language) + " text drops " + list + " of its English, so " +
                          "the English is shown: " + shortened(english) + " / " + shortened(translated));
    }
  }
  if (!kept.has(Language::Chinese) && has_words(english) && listed_.insert(where + "|zh|" + english).second)
    untranslated_.push_back(where + ": " + shortened(english));
  if (kept.has(Language::Chinese)) by_english_[english] = std::move(kept);
}

void LessonTexts::unknown_language(const std::string& code, const std::string& where) {
  if (!listed_.insert(where + "|language|" + code).second) return;
  std::string known;
  for (const Language language : kLanguages)
    known += (known.empty() ? "" : ", ") + std::string(language_code(language));
  problems_.push_back(where + ": '" + code + "' is not a language MeshEdit knows (" + known +
                      "): the text is shown in English");
}

const std::string& LessonTexts::in(const std::string& english, Language language) const {
  if (language == Language::English) return english;
  if (const auto it = by_english_.find(english); it != by_english_.end() && it->second.has(language))
    return it->second.texts[size_t(language)];
  if (const std::string* app = catalog_of(language).find(english)) return *app;
  return english;
}

std::string LessonTexts::all_in(Language language) const {
  std::string all;
  for (const auto& [english, text] : by_english_) all += text.in(language);
  return all;
}

void LessonTexts::clear() {
  by_english_.clear();
  problems_.clear();
  untranslated_.clear();
  listed_.clear();
}

}  // namespace meshedit
