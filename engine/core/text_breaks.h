// text_breaks: where a line of text may wrap, for text with spaces (English) and without (Chinese). A line breaks at
// a space, and between two CJK characters; never inside a run of other characters (a word, a number such as -0.2778,
// an id such as h12 or a code word such as h.next). Closing punctuation (，。、)...) stays with what comes before it
// and opening punctuation (（“...) with what follows, as Chinese typesetting (and UAX #14) keeps them.
//
// Invariants:
// - break_pieces(line) joined back, each piece after a space when its space_before says so, gives the line with its
//   runs of spaces made single and the spaces at its ends dropped: no character is lost or moved.
// - Text that is not valid UTF-8 is cut only at spaces (each invalid byte is a character of its own, not wide).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace meshedit {

// The code point starting at text[i] and its length in bytes (1 for an invalid byte, which is returned as itself).
char32_t utf8_at(std::string_view text, size_t i, size_t* length);
// CJK ideographs, kana, Hangul, CJK and full-width punctuation: characters a line may break between.
bool wide_char(char32_t c);

// One piece of a line: a line may break before it. space_before: a space stood before it (dropped at a break).
struct TextPiece {
  std::string_view text;
  bool space_before = false;
};
// The pieces of one line (no '\n' in it).
std::vector<TextPiece> break_pieces(std::string_view line);

// Whether a lone line break in markdown between `before` and `after` joins them with nothing (both sides wide, as
// in Chinese) rather than with a space.
bool joins_without_space(std::string_view before, std::string_view after);

// `text` without the spaces that stand between two wide characters: markdown written "是 **半边** 结构" for its marks
// reads "是 半边 结构" once they are gone, and Chinese puts no space between its own characters ("是半边结构"). Spaces
// beside Latin text, numbers and ids stay ("按 W 键").
std::string without_spaces_between_wide(std::string_view text);

// Every line of `text` wrapped so no line is wider than `width` as `measure` says, at the breaks above; a piece wider
// than a whole line keeps a line of its own. The text's own line breaks stay.
template <typename Measure>
std::string wrapped_text(const std::string& text, float width, Measure measure);

}  // namespace meshedit

#include "core/text_breaks_inl.h"
