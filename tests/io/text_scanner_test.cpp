// The shared scanner: tokens, lines, comments, continuations, and the strict number rules every text
// format relies on.
#include "io/text_scanner.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace meshedit {
namespace {

using testing::error_of;

TEST(TextScanner, TokensCarryTheLineTheyStartOn) {
  TextScanner s(" 4\n\n0.2\t0.35\r\n  x", "a.bzc");
  auto t = s.next();
  ASSERT_TRUE(t);
  EXPECT_EQ(t->text, "4");
  EXPECT_EQ(t->line, 1u);
  t = s.next();
  EXPECT_EQ(t->text, "0.2");
  EXPECT_EQ(t->line, 3u);
  EXPECT_EQ(s.count_remaining(), 2u);
  t = s.next();
  EXPECT_EQ(t->text, "0.35");
  t = s.next();
  EXPECT_EQ(t->text, "x");
  EXPECT_EQ(t->line, 4u);
  EXPECT_FALSE(s.next());
  EXPECT_TRUE(s.at_end());
}

TEST(TextScanner, LinesCommentsAndContinuations) {
  TextScanner s("v 1 2 # note\nf 1 \\\n 2 3\n# only\ng", "a.obj", 10);
  s.set_comment_char('#');
  s.set_line_continuations(true);
  EXPECT_EQ(s.next()->text, "v");
  EXPECT_EQ(s.next_on_line()->text, "1");
  EXPECT_EQ(s.next_on_line()->text, "2");
  EXPECT_FALSE(s.next_on_line());  // the comment ends the line
  s.skip_line();
  auto f = s.next();
  EXPECT_EQ(f->text, "f");
  EXPECT_EQ(f->line, 11u);
  EXPECT_EQ(s.next_on_line()->text, "1");
  auto two = s.next_on_line();  // continued onto the next line
  ASSERT_TRUE(two);
  EXPECT_EQ(two->text, "2");
  EXPECT_EQ(two->line, 12u);
  EXPECT_EQ(s.next_on_line()->text, "3");
  EXPECT_FALSE(s.next_on_line());
  s.skip_line();
  auto g = s.next();
  EXPECT_EQ(g->text, "g");
  EXPECT_EQ(g->line, 14u);
}

TEST(TextScanner, NumbersAreStrict) {
  double x = 0;
  EXPECT_EQ(to_real("0.5", x), NumberStatus::Ok);
  EXPECT_EQ(x, 0.5);
  EXPECT_EQ(to_real("-1e3", x), NumberStatus::Ok);
  EXPECT_EQ(x, -1000.0);
  EXPECT_EQ(to_real("+.25", x), NumberStatus::Ok);
  EXPECT_EQ(x, 0.25);
  EXPECT_EQ(to_real("1e-400", x), NumberStatus::Ok);  // underflow is harmless
  EXPECT_EQ(x, 0.0);
  EXPECT_EQ(to_real("0.5x", x), NumberStatus::NotANumber);
  EXPECT_EQ(to_real("", x), NumberStatus::NotANumber);
  EXPECT_EQ(to_real("+", x), NumberStatus::NotANumber);
  EXPECT_EQ(to_real("+-1", x), NumberStatus::NotANumber);
  EXPECT_EQ(to_real("0x10", x), NumberStatus::NotANumber);
  EXPECT_EQ(to_real("1,5", x), NumberStatus::NotANumber);
  EXPECT_EQ(to_real("nan", x), NumberStatus::NotFinite);
  EXPECT_EQ(to_real("-inf", x), NumberStatus::NotFinite);
  EXPECT_EQ(to_real("infinity", x), NumberStatus::NotFinite);
  EXPECT_EQ(to_real("1e999", x), NumberStatus::OutOfRange);
  int64_t i = 0;
  EXPECT_EQ(to_integer("-12", i), NumberStatus::Ok);
  EXPECT_EQ(i, -12);
  EXPECT_EQ(to_integer("3.0", i), NumberStatus::NotANumber);
  EXPECT_EQ(to_integer("99999999999999999999", i), NumberStatus::OutOfRange);
}

TEST(TextScanner, ErrorsQuoteTheTokenWithFileAndLine) {
  TextScanner s("1\n0.5x", "c.bzc");
  s.next();
  EXPECT_EQ(error_of([&] { s.read_real("x of point 1"); }), "c.bzc:2: expected x of point 1, found \"0.5x\"");
  TextScanner n("nan", "c.bzc");
  EXPECT_EQ(error_of([&] { n.read_real("y"); }), "c.bzc:1: y must be a finite number, found \"nan\"");
  TextScanner e("", "c.bzc");
  EXPECT_EQ(error_of([&] { e.read_real("y"); }), "c.bzc:1: file ends where y was expected");
  TextScanner big("1e999", "c.bzc");
  EXPECT_EQ(error_of([&] { big.read_real("z"); }), "c.bzc:1: z is out of range: \"1e999\"");
}

TEST(TextScanner, QuoteEscapesAndShortens) {
  EXPECT_EQ(quote(std::string_view("a\0b\"", 4)), "\"a\\x00b\\\"\"");
  EXPECT_EQ(quote(std::string(50, 'z')), "\"" + std::string(40, 'z') + "...\"");
}

}  // namespace
}  // namespace meshedit
