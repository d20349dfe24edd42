// What a lesson says in more than one language. A lesson writes a text the student reads either as a string (English)
// or as a table of languages, `say { en = [[...]], zh = [[...]] }`; the lesson's logic only ever sees the English (the
// API reads the table and hands on its `en`), and the runner keeps the other languages here, by their English, for the
// panel to show in the window's language (core/translation.h).
//
// Invariants:
// - Every English text kept here was handed to the lesson's logic or to the host as it is; in() gives it back
//   unchanged when it has no translation into the language asked for, so a text is never shown as blank.
// - A translation that drops a `code` span or a number of its English is not kept: it is named in problems() with
//   both texts, and the English is shown instead.
// - Each problem, unknown language and untranslated text is listed once per place in the lesson (file:line).
#pragma once

#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/translation.h"

namespace meshedit {

class LessonTexts {
 public:
  // Keeps `text` (read at `where`, "4_edge_flip.lua:12") and checks it: its languages' code spans and numbers, and
  // whether it has a Chinese twin when it has words to translate.
  void keep(const LocalText& text, const std::string& where);
  // An unknown key in a text table ("fr"): one warning per place.
  void unknown_language(const std::string& code, const std::string& where);

  // `english` in `language`: the lesson's translation, else the app's own catalog's (the runner's default feedback,
  // "h6 is not the answer."), else `english`.
  const std::string& in(const std::string& english, Language language) const;
  // Forgets every text (a reload).
  void clear();
  // How many texts have a translation, and all of them in `language` one after another (what a font must draw).
  size_t size() const { return by_english_.size(); }
  std::string all_in(Language language) const;

  // "lesson.lua:12: the zh text drops `h.next` and 3 of its English: ... / ...", "lesson.lua:4: 'fr' is not a
  // language MeshEdit knows (en, zh): the text is shown in English".
  const std::vector<std::string>& problems() const { return problems_; }
  // "lesson.lua:20: \"Press W to switch...\"": texts with words and no zh twin, where they were read.
  const std::vector<std::string>& untranslated() const { return untranslated_; }

 private:
  std::unordered_map<std::string, LocalText> by_english_;
  std::vector<std::string> problems_, untranslated_;
  std::set<std::string> listed_;  // "where|what" of each problem and untranslated text listed
};

// The code spans (`h.next`) and numbers (3, 0.5, -1) of a text, sorted: what a translation must keep.
std::vector<std::string> kept_tokens(const std::string& text);
// Whether a text has words a reader needs translated: three or more Latin letters in a row outside code spans (an id
// like "h12", a number or "C(0.41)" does not, nor one lower-case code word such as "next" or "h.next").
bool has_words(const std::string& text);

}  // namespace meshedit
