// Counts and sizes as people read them (core/value_format.h): the noun agrees with the count, and a byte size is
// rounded up so it never reads as less than it is.
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

}  // namespace
}  // namespace meshedit
