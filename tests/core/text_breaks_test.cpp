// Where lines of English and Chinese text may break (core/text_breaks.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/text_breaks.h"

namespace meshedit {
namespace {

std::vector<std::string> pieces(const std::string& line) {
  std::vector<std::string> out;
  for (const TextPiece& piece : break_pieces(line))
    out.push_back((piece.space_before ? "_" : "") + std::string(piece.text));
  return out;
}

// Each character one unit wide: wrapping by counted code points.
float width_of(const std::string& text) {
  float width = 0.0f;
  for (size_t i = 0; i < text.size();) {
    size_t n = 1;
    utf8_at(text, i, &n);
    width += 1.0f;
    i += n;
  }
  return width;
}

TEST(TextBreaks, EnglishBreaksOnlyAtSpaces) {
  EXPECT_EQ(pieces("the  value -0.2778 of h.next"),
            (std::vector<std::string>{"the", "_value", "_-0.2778", "_of", "_h.next"}));
}

TEST(TextBreaks, ChineseBreaksBetweenCharactersButNeverInsideNumbersOrIds) {
  EXPECT_EQ(pieces("顶点 v12 的度数为 4。"),
            (std::vector<std::string>{"顶", "点", "_v12", "_的", "度", "数", "为", "_4。"}));
  EXPECT_EQ(pieces("半边h12指向f3"), (std::vector<std::string>{"半", "边", "h12", "指", "向", "f3"}));
}

TEST(TextBreaks, ClosingPunctuationStaysWithWhatComesBeforeAndOpeningWithWhatFollows) {
  EXPECT_EQ(pieces("面（f5），对。"), (std::vector<std::string>{"面", "（f5），", "对。"}));
  EXPECT_EQ(pieces("“半边”"), (std::vector<std::string>{"“半", "边”"}));
}

TEST(TextBreaks, WrappingKeepsEveryCharacterAndItsOwnLineBreaks) {
  const std::string text = "按 **W** 键切换线框显示，然后按 N 走到下一条半边。\nB1(0.5) = 0.375";
  const std::string wrapped = wrapped_text(text, 8.0f, width_of);
  EXPECT_EQ(wrapped, "按 **W**\n键切换线框显示，\n然后按 N 走到\n下一条半边。\nB1(0.5)\n= 0.375");
  std::string joined;
  for (const char c : wrapped) joined += c == '\n' ? "" : std::string(1, c);
  std::string original;
  for (const char c : text) original += c == '\n' ? "" : std::string(1, c);
  EXPECT_EQ(joined.size() + 2, original.size()) << "only the spaces at the breaks go: after **W** and before =";
}

TEST(TextBreaks, ALoneLineBreakBetweenChineseJoinsWithoutASpace) {
  EXPECT_TRUE(joins_without_space("细分", "网格"));
  EXPECT_FALSE(joins_without_space("细分", "mesh"));
  EXPECT_FALSE(joins_without_space("the", "mesh"));
}

TEST(TextBreaks, SpacesBetweenChineseCharactersGoAndSpacesBesideLatinTextStay) {
  EXPECT_EQ(without_spaces_between_wide("是 半边 结构，按 W 键走到 h12 。"), "是半边结构，按 W 键走到 h12 。");
  EXPECT_EQ(without_spaces_between_wide("the half edge"), "the half edge");
}

TEST(TextBreaks, InvalidUtf8IsCutOnlyAtSpaces) {
  EXPECT_EQ(pieces("a\xff\xfe b"), (std::vector<std::string>{"a\xff\xfe", "_b"}));
}

}  // namespace
}  // namespace meshedit
