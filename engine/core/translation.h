// translation: the languages a student can read MeshEdit in, and the window's texts in the chosen one. English is the
// source and the fallback: every text is written in English in the code (or the lesson), and a catalog gives its
// translation. A text the catalog lacks shows in English, never as a key or a blank.
//
// A catalog is read from gettext PO files (assets/translations/CODE/*.po): each msgid is an English text exactly as
// the code writes it, its msgstr the translation ("" = not translated yet). Templates name their parts in braces,
// "{count} faces reversed", and a translation may put the parts in any order but must use the same names.
//
// Invariants:
// - tr(english) returns `english` itself (the same pointer) when the text language is English or the catalog has
//   no translation, so English output is byte for byte what the code wrote; otherwise a pointer the catalog owns,
//   valid until that catalog is replaced (set_catalog).
// - A catalog holds only entries whose placeholders match their msgid's; an entry that does not match is left out and
//   named in the catalog's problems, so a translation can never drop a number or an id from a message.
// - The text language and the catalogs are one per process. They are set on the main thread, before any other thread
//   reads them (the window's worker threads, the grader's tests); catalog_of is read-only once a language is set.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace meshedit {

enum class Language { English, Chinese };
inline constexpr size_t kLanguageCount = 2;
inline constexpr std::array<Language, kLanguageCount> kLanguages{Language::English, Language::Chinese};

// "en", "zh": the code lessons use (`say{ en = ..., zh = ... }`), the page's `?lang=` and the catalog's folder.
const char* language_code(Language language);
// The language's own name, as the View > Language menu lists it: "English", "简体中文".
const char* language_name(Language language);
// A language by its code or a locale naming it: "zh", "zh_CN.UTF-8", "zh-Hans", "en_GB"; nullopt for others.
std::optional<Language> language_by_code(std::string_view code);
// The language of the system's locale (LC_ALL, LC_MESSAGES, LANG, in the order POSIX reads them), English when it
// names none of kLanguages.
Language system_language();

// A text in each language: the English always, the others where the author gave them.
struct LocalText {
  std::array<std::string, kLanguageCount> texts;
  const std::string& english() const { return texts[0]; }
  // The text in `language`, or the English when that one is missing.
  const std::string& in(Language language) const;
  bool has(Language language) const { return !texts[size_t(language)].empty(); }
};

// The parts a template names: {"count", "3"}.
using MessageParts = std::vector<std::pair<std::string_view, std::string>>;
// The template with each {name} replaced by its part; "{{" and "}}" are braces. A name without a part stays as
// written, so a missing part shows rather than vanishing.
std::string fill_template(std::string_view text, const MessageParts& parts);
// The names a template uses, sorted, each once: "{b} and {a} and {a}" -> {"a", "b"}.
std::vector<std::string> placeholder_names(std::string_view text);

// One language's translations of the window's English texts.
class Catalog {
 public:
  // Reads one PO file into the catalog. Each entry that cannot be used (a syntax error, placeholders that differ
  // from the msgid's) is left out and named in problems() as "zh/app.po:12: ...". Returns false when the file
  // cannot be read.
  bool read_po(const std::filesystem::path& file);
  // Reads PO text as if from a file named `name` (the tests).
  void read_po_text(std::string_view text, const std::string& name);
  // Adds one translation (checked as read_po checks it; `where` names it in a problem).
  void add(const std::string& english, const std::string& translated, const std::string& where);

  // The translation of `english`, or null.
  const std::string* find(std::string_view english) const;
  size_t size() const { return entries_.size(); }
  // Every translation, one after another (what a font must be able to draw).
  std::string all_translations() const;
  const std::vector<std::string>& problems() const { return problems_; }
  void add_problem(std::string problem) { problems_.push_back(std::move(problem)); }
  // "打开###Open": the label for `english` ("Open", or "Open##menu" with an id of its own), made once; null when the
  // text before "##" has no translation.
  const char* label(const char* english) const;

 private:
  std::unordered_map<std::string, std::string> entries_;
  mutable std::unordered_map<std::string, std::string> labels_;
  std::vector<std::string> problems_;
};

// Every PO file of `language` in `folder` (assets/translations/CODE/*.po, read in name order). English gives an
// empty catalog. A missing folder is a problem ("no translations of 简体中文 in ...").
Catalog read_catalog(Language language, const std::filesystem::path& folder);
// The folder holding one subfolder of PO files per language (data_folder("assets") / "translations").
std::filesystem::path translations_folder();

// The language of the texts this process writes for a student, English until set: the window's (View > Language) or
// the grader's (its suite's `language`). set_text_language chooses it and returns the problems of its catalog (empty
// when all is well), read from translations_folder() then, so other threads only ever read a catalog.
Language text_language();
std::vector<std::string> set_text_language(Language language);
// The catalog of `language` (read the first time; English's is empty).
const Catalog& catalog_of(Language language);
// Replaces the catalog of `language` without reading files (the tests).
void set_catalog(Language language, Catalog catalog);

// The text for `english` in the text language (see the invariants).
const char* tr(const char* english);
std::string tr(const std::string& english);
// A widget label whose ImGui id stays the English one in every language: "Lesson" -> "课程###Lesson", so a window,
// tab or tree node keeps its place and state when the language changes. English gives `english` itself.
const char* tr_label(const char* english);
// The template translated, then filled: tr_format("{count} faces reversed", {{"count", "3"}}).
std::string tr_format(const char* english_template, const MessageParts& parts);
// The template filled in every language whose catalog translates it (the English always); a part that is itself a
// text of that catalog ("a vertex") is put in translated, any other (an id, a number) as it is.
LocalText local_format(const char* english_template, const MessageParts& parts);

}  // namespace meshedit
