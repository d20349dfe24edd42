// Counts, sizes and rounded numbers as people read them (core/value_format.h): the noun agrees with the count, a
// byte size is rounded up so it never reads as less than it is, and a rounded number keeps the digits asked for.
#include <limits>

#include <gtest/gtest.h>

#include "core/value_format.h"

namespace meshedit {
namespace {

TEST(ValueFormat, PluralAgreesWithTheCount) {
  EXPECT_EQ(plural(0, "face", "faces"), "0 faces");
  EXPECT_EQ(plural(1, "face", "faces"), "1 face");
  EXPECT_EQ(plural(2, "vertex", "vertices"), "2 vertices");
}

TEST(ValueFormat, BytesAreKilobytesBelowAMegabyteAndRoundedUp) {
  EXPECT_EQ(format_bytes(0), "0 KB");
  EXPECT_EQ(format_bytes(1), "1 KB");
  EXPECT_EQ(format_bytes(1024), "1 KB");
  EXPECT_EQ(format_bytes(1025), "2 KB");
  EXPECT_EQ(format_bytes(size_t(1) << 20), "1 MB");
  EXPECT_EQ(format_bytes((size_t(32) << 20) + 1), "33 MB");
  EXPECT_EQ(format_bytes(size_t(512) << 20), "512 MB");
}

TEST(ValueFormat, RoundedKeepsSignificantDigitsAndDropsTrailingZeros) {
  EXPECT_EQ(format_rounded(1.0 / 3), "0.333333");
  EXPECT_EQ(format_rounded(0.5, 3), "0.5");
  EXPECT_EQ(format_rounded(1234.5678, 3), "1.23e+03");
  EXPECT_EQ(format_rounded(0.1 + 0.2, 10), "0.3");
  EXPECT_EQ(format_rounded(0.1 + 0.2, 17), "0.30000000000000004");
  EXPECT_EQ(format_rounded(0.1, 40), "0.10000000000000001");  // more than 17 digits is 17
  EXPECT_EQ(format_rounded(-0.0), "-0");
  EXPECT_EQ(format_rounded(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_rounded(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(ValueFormat, FixedKeepsExactlyTheDecimalsAsked) {
  EXPECT_EQ(format_fixed(0.5, 4), "0.5000");
  EXPECT_EQ(format_fixed(16.66, 1), "16.7");
  EXPECT_EQ(format_fixed(-0.00004, 4), "-0.0000");
  EXPECT_EQ(format_fixed(2.5, 0), "2");  // printf rounds half to even
  EXPECT_EQ(format_fixed(std::numeric_limits<double>::max(), 0).size(), 309u);
  EXPECT_EQ(format_fixed(-std::numeric_limits<double>::infinity(), 2), "-inf");
}

}  // namespace
}  // namespace meshedit
