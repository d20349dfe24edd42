// The languages, the PO catalogs and the window's texts (see translation.h).
#include "core/translation.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdlib>
#include <system_error>

#include "core/data_folders.h"
#include "core/file_bytes.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool name_char(char c, bool first) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_' ||
         (!first && std::isdigit(static_cast<unsigned char>(c)));
}

// The length of "{name}" at text[i] (0 when it is not one).
size_t placeholder_at(std::string_view text, size_t i) {
  if (text[i] != '{' || i + 1 >= text.size() || !name_char(text[i + 1], true)) return 0;
  size_t j = i + 2;
  while (j < text.size() && name_char(text[j], false)) ++j;
  return j < text.size() && text[j] == '}' ? j + 1 - i : 0;
}

std::string joined_names(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "{" : ", {") + name + "}";
  return out;
}

// One PO entry being read.
struct PoEntry {
  std::string msgid, msgstr;
  std::string* reading = nullptr;  // the field the next continuation string goes to
  size_t line = 0;                 // the msgid's line
  bool fuzzy = false, unsupported = false;
};

// The C-escaped string between the quotes of `line` (which starts at its opening quote), or nullopt when it is not one.
std::optional<std::string> quoted(std::string_view line) {
  if (line.size() < 2 || line.front() != '"' || line.back() != '"') return std::nullopt;
  std::string out;
  for (size_t i = 1; i + 1 < line.size(); ++i) {
    char c = line[i];
    if (c == '"') return std::nullopt;
    if (c == '\\') {
      if (i + 2 >= line.size()) return std::nullopt;
      c = line[++i];
      if (c == 'n') c = '\n';
      else if (c == 't') c = '\t';
      else if (c != '"' && c != '\\') return std::nullopt;
    }
    out += c;
  }
  return out;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

struct ProcessTexts {
  std::atomic<Language> language{Language::English};  // read by the window's worker threads too
  std::array<std::optional<Catalog>, kLanguageCount> catalogs;
};

ProcessTexts& process_texts() {
  static ProcessTexts texts;
  return texts;
}

}  // namespace

const char* language_code(Language language) { return language == Language::Chinese ? "zh" : "en"; }

const char* language_name(Language language) { return language == Language::Chinese ? "简体中文" : "English"; }

std::optional<Language> language_by_code(std::string_view code) {
  const std::string text = lower(code);
  const std::string_view first = std::string_view(text).substr(0, text.find_first_of("_-.@"));
  if (first == "en") return Language::English;
  if (first == "zh") return Language::Chinese;
  return std::nullopt;
}

Language system_language() {
  for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
    const char* value = std::getenv(name);
    if (!value || !*value) continue;
    return language_by_code(value).value_or(Language::English);
  }
  return Language::English;
}

const std::string& LocalText::in(Language language) const {
  const std::string& text = texts[size_t(language)];
  return text.empty() ? texts[0] : text;
}

std::string fill_template(std::string_view text, const MessageParts& parts) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    if ((text[i] == '{' || text[i] == '}') && i + 1 < text.size() && text[i + 1] == text[i]) {
      out += text[i];
      i += 2;
      continue;
    }
    if (const size_t n = placeholder_at(text, i); n > 0) {
      const std::string_view name = text.substr(i + 1, n - 2);
      const auto part = std::find_if(parts.begin(), parts.end(), [&](const auto& p) { return p.first == name; });
      out += part == parts.end() ? std::string(text.substr(i, n)) : part->second;
      i += n;
      continue;
    }
    out += text[i++];
  }
  return out;
}

std::vector<std::string> placeholder_names(std::string_view text) {
  std::vector<std::string> names;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '{' && i + 1 < text.size() && text[i + 1] == '{') {
      ++i;
      continue;
    }
    if (const size_t n = placeholder_at(text, i); n > 0) names.emplace_back(text.substr(i + 1, n - 2));
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

void Catalog::add(const std::string& english, const std::string& translated, const std::string& where) {
  const std::vector<std::string> want = placeholder_names(english), got = placeholder_names(translated);
  if (want != got) {
    problems_.push_back(where + ": the translation \"" + translated + "\" has placeholders " + joined_names(got) +
                        " where its English \"" + english + "\" has " + joined_names(want));
    return;
  }
  entries_[english] = translated;
  labels_.clear();
}

void Catalog::read_po_text(std::string_view text, const std::string& name) {
  PoEntry entry;
  bool comment_fuzzy = false;
  const auto finish = [&] {
    const std::string where = name + ":" + std::to_string(entry.line);
    if (entry.unsupported) problems_.push_back(where + ": msgctxt and plural forms are not read: left out");
    else if (!entry.msgid.empty() && !entry.msgstr.empty() && !entry.fuzzy) add(entry.msgid, entry.msgstr, where);
    entry = PoEntry{};
  };
  size_t line_number = 0;
  for (size_t start = 0; start <= text.size();) {
    const size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = trimmed(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    const std::string where = name + ":" + std::to_string(line_number);
    if (line.empty()) continue;
    if (line.front() == '#') {
      if (line.substr(0, 2) == "#," && line.find("fuzzy") != std::string_view::npos) comment_fuzzy = true;
      continue;
    }
    const size_t space = line.find(' ');
    const std::string_view keyword = line.front() == '"' ? std::string_view() : line.substr(0, space);
    const std::optional<std::string> value =
        quoted(keyword.empty() ? line : trimmed(line.substr(std::min(space, line.size()))));
    if (!value) {
      problems_.push_back(where + ": not a PO line (a keyword and a \"quoted\" text): " + std::string(line));
      continue;
    }
    if (keyword.empty()) {
      if (entry.reading) *entry.reading += *value;
      else problems_.push_back(where + ": a text continued with no msgid or msgstr before it");
      continue;
    }
    if (keyword == "msgid" || keyword == "msgctxt") {
      if (entry.line > 0) finish();
      entry.line = line_number;
      entry.fuzzy = comment_fuzzy;
      comment_fuzzy = false;
      entry.unsupported = keyword == "msgctxt";
      entry.msgid = keyword == "msgid" ? *value : "";
      entry.reading = keyword == "msgid" ? &entry.msgid : nullptr;
    } else if (keyword == "msgstr" && entry.line > 0) {
      entry.msgstr = *value;
      entry.reading = &entry.msgstr;
    } else if (keyword == "msgid_plural" || keyword.substr(0, 7) == "msgstr[") {
      entry.unsupported = true;
      entry.reading = nullptr;
    } else {
      problems_.push_back(where + ": '" + std::string(keyword) + "' is not a PO keyword");
    }
  }
  if (entry.line > 0) finish();
}

bool Catalog::read_po(const fs::path& file) {
  const FileBytes bytes = read_file_bytes(file);
  if (!bytes.ok()) {
    problems_.push_back(file.string() + ": cannot be read");
    return false;
  }
  read_po_text(bytes.bytes, file.parent_path().filename().string() + "/" + file.filename().string());
  return true;
}

const std::string* Catalog::find(std::string_view english) const {
  const auto it = entries_.find(std::string(english));
  return it == entries_.end() ? nullptr : &it->second;
}

std::string Catalog::all_translations() const {
  std::string all;
  for (const auto& [english, translated] : entries_) all += translated;
  return all;
}

const char* Catalog::label(const char* english) const {
  if (const auto it = labels_.find(english); it != labels_.end()) return it->second.c_str();
  const std::string_view whole(english);
  const size_t id = whole.find("##");
  const std::string* shown = find(whole.substr(0, id));
  if (!shown) return nullptr;
  // "###" makes ImGui hash only what follows: the whole English label, its own "##id" included.
  std::string text = *shown + "###" + std::string(whole);
  return labels_.emplace(english, std::move(text)).first->second.c_str();
}

Catalog read_catalog(Language language, const fs::path& folder) {
  Catalog catalog;
  if (language == Language::English) return catalog;
  const fs::path dir = folder / language_code(language);
  std::error_code ec;
  std::vector<fs::path> files;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".po") files.push_back(it->path());
  if (files.empty()) {
    catalog.add_problem("no translations of " + std::string(language_name(language)) + " in " + dir.string() +
                        ": the window is shown in English");
    return catalog;
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) catalog.read_po(file);
  return catalog;
}

fs::path translations_folder() { return data_folder("assets") / "translations"; }

Language text_language() { return process_texts().language; }

const Catalog& catalog_of(Language language) {
  std::optional<Catalog>& catalog = process_texts().catalogs[size_t(language)];
  if (!catalog) catalog = read_catalog(language, translations_folder());
  return *catalog;
}

std::vector<std::string> set_text_language(Language language) {
  const Catalog& catalog = catalog_of(language);  // read before a worker thread can see the language
  process_texts().language = language;
  return catalog.problems();
}

void set_catalog(Language language, Catalog catalog) {
  process_texts().catalogs[size_t(language)] = std::move(catalog);
}

const char* tr(const char* english) {
  const Language language = text_language();
  if (language == Language::English) return english;
  const std::string* shown = catalog_of(language).find(english);
  return shown ? shown->c_str() : english;
}

std::string tr(const std::string& english) { return tr(english.c_str()); }

const char* tr_label(const char* english) {
  const Language language = text_language();
  if (language == Language::English) return english;
  const char* shown = catalog_of(language).label(english);
  return shown ? shown : english;
}

std::string tr_format(const char* english_template, const MessageParts& parts) {
  return fill_template(tr(english_template), parts);
}

LocalText local_format(const char* english_template, const MessageParts& parts) {
  LocalText out;
  out.texts[0] = fill_template(english_template, parts);
  for (const Language language : kLanguages) {
    if (language == Language::English) continue;
    const Catalog& catalog = catalog_of(language);
    const std::string* shown = catalog.find(english_template);
    if (!shown) continue;
    MessageParts translated = parts;
    for (auto& part : translated) {
      if (const std::string* part_shown = catalog.find(part.second)) part.second = *part_shown;
    }
    out.texts[size_t(language)] = fill_template(*shown, translated);
  }
  return out;
}

}  // namespace meshedit
