// parse_answer_text: what a student types into a lesson's answer box, read whole as numbers or not at all.
#include <gtest/gtest.h>

#include <vector>

#include "lesson/internal/lesson_answer_text.h"

namespace meshedit {
namespace {

using Values = std::vector<double>;

TEST(LessonAnswerText, ReadsNumbersFractionsAndPoints) {
  EXPECT_EQ(parse_answer_text("0.375", 1), Values{0.375});
  EXPECT_EQ(parse_answer_text("  3/8 ", 1), Values{0.375});
  EXPECT_EQ(parse_answer_text("-1e-3", 1), Values{-0.001});
  EXPECT_EQ(parse_answer_text(".5", 1), Values{0.5});
  EXPECT_EQ(parse_answer_text("0.5, 1", 2), (Values{0.5, 1.0}));
  EXPECT_EQ(parse_answer_text("(0.5, 1, 0)", 3), (Values{0.5, 1.0, 0.0}));
  EXPECT_EQ(parse_answer_text("0.5 1", 2), (Values{0.5, 1.0}));
  EXPECT_EQ(parse_answer_text("{1/2; -2}", 2), (Values{0.5, -2.0}));
  EXPECT_EQ(parse_answer_text("[1,2]", 2), (Values{1.0, 2.0}));
}

TEST(LessonAnswerText, RefusesAnythingElseWhole) {
  EXPECT_FALSE(parse_answer_text("", 1));
  EXPECT_FALSE(parse_answer_text("three eighths", 1));
  EXPECT_FALSE(parse_answer_text("0.375x", 1));
  EXPECT_FALSE(parse_answer_text("1/0", 1));
  EXPECT_FALSE(parse_answer_text("inf", 1));
  EXPECT_FALSE(parse_answer_text("nan", 1));
  EXPECT_FALSE(parse_answer_text("0x10", 1));
  EXPECT_FALSE(parse_answer_text("1e999", 1));
  EXPECT_FALSE(parse_answer_text("0.5", 2));      // too few
  EXPECT_FALSE(parse_answer_text("1, 2, 3", 2));  // too many
  EXPECT_FALSE(parse_answer_text("(1, 2", 2));    // an unclosed bracket is not a number
}

TEST(LessonAnswerText, SaysHowToWriteEachKind) {
  EXPECT_EQ(answer_text_help(1), "Type a number, like 0.25 or 3/8.");
  EXPECT_EQ(answer_text_help(2), "Type a point as x, y, like 0.5, 1.");
  EXPECT_EQ(answer_text_help(3), "Type a point as x, y, z, like 0.5, 1, 0.");
}

}  // namespace
}  // namespace meshedit
