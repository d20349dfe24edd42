// .bzc and .bez: exact control points of small hand-written files, every refusal with its place, and
// the writers' exact round trips.
#include <gtest/gtest.h>

#include <cmath>

#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "io_test_util.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// A patch whose point (row, col) is (col, row, 10*row + col), so every coordinate tells its place.
std::string numbered_patch_text(double offset) {
  std::string text;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) {
      text += std::to_string(col + offset) + " " + std::to_string(row) + " " + std::to_string(10 * row + col) + "  ";
    }
    text += "\n";
  }
  return text;
}

TEST(Bzc, ReadsPointsAcrossAnyWhitespace) {
  const BezierCurve c = parse_bzc("3\n0.2 0.35\t 0.3\n\n0.6   -1e-1 +2\n", "c.bzc");
  ASSERT_EQ(c.control_points.size(), 3u);
  EXPECT_EQ(c.control_points[0], glm::dvec2(0.2, 0.35));
  EXPECT_EQ(c.control_points[1], glm::dvec2(0.3, 0.6));
  EXPECT_EQ(c.control_points[2], glm::dvec2(-0.1, 2.0));
}

TEST(Bzc, RefusesBadFilesWithThePlace) {
  EXPECT_FILE_ERROR(parse_bzc("", "c.bzc"), "c.bzc:1: file is empty");
  EXPECT_FILE_ERROR(parse_bzc("  \n\t", "c.bzc"), "c.bzc:1: file is empty");
  EXPECT_FILE_ERROR(parse_bzc("x", "c.bzc"), "c.bzc:1:", "number of control points", "\"x\"");
  EXPECT_FILE_ERROR(parse_bzc("2.5\n0 0 1 1 2 2", "c.bzc"), "c.bzc:1:", "\"2.5\"");
  EXPECT_FILE_ERROR(parse_bzc("0", "c.bzc"), "c.bzc:1:", "between 1 and");
  EXPECT_FILE_ERROR(parse_bzc("-3\n0 0", "c.bzc"), "c.bzc:1:", "\"-3\"");
  EXPECT_FILE_ERROR(parse_bzc("3\n0 0\n1 1\n2", "c.bzc"),
                    "c.bzc:", "declares 3 control points but holds only 5 numbers");
  EXPECT_FILE_ERROR(parse_bzc("2147483648\n0 0", "c.bzc"), "declares 2147483648 control points but holds only 2");
  EXPECT_FILE_ERROR(parse_bzc("2\n0 0\n1 0.5x", "c.bzc"), "c.bzc:3: expected y of point 2, found \"0.5x\"");
  EXPECT_FILE_ERROR(parse_bzc("2\n0 0\nnan 1", "c.bzc"),
                    "c.bzc:3: x of point 2 must be a finite number, found \"nan\"");
  EXPECT_FILE_ERROR(parse_bzc("2\n0 0\n1 inf", "c.bzc"), "c.bzc:3:", "\"inf\"");
  EXPECT_FILE_ERROR(parse_bzc("2\n0 0\n1 1e400", "c.bzc"), "c.bzc:3:", "out of range", "\"1e400\"");
  EXPECT_FILE_ERROR(parse_bzc("1\n0 0\n\n7", "c.bzc"), "c.bzc:4: unexpected \"7\" after the last control point");
  EXPECT_FILE_ERROR(parse_bzc(std::string("\x7f"
                                          "ELF\x02\x01\0\0",
                                          8),
                              "c.bzc"),
                    "c.bzc:1:", "\"\\x7fELF\\x02\\x01\\x00\\x00\"");
}

TEST(Bzc, WriterRoundTripsExactly) {
  BezierCurve c;
  c.control_points = {{0.1, 1.0 / 3.0}, {-2.5e-12, 1e300}, {0, -0.0}};
  const std::string text = format_bzc(c, "c.bzc");
  const BezierCurve back = parse_bzc(text, "c.bzc");
  ASSERT_EQ(back.control_points.size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(back.control_points[i], c.control_points[i]);
  EXPECT_FILE_ERROR(format_bzc(BezierCurve{}, "c.bzc"), "c.bzc:", "at least one");
  EXPECT_FILE_ERROR(format_bzc(BezierCurve{{{0, std::nan("")}}}, "c.bzc"), "c.bzc: point 1:", "finite");

  const auto path = testing::scratch_dir() / "curve.bzc";
  write_bzc(path, c);
  EXPECT_EQ(read_bzc(path).control_points[1], c.control_points[1]);
}

TEST(Bez, ReadsPatchesRowMajor) {
  const auto patches = parse_bez("2\n" + numbered_patch_text(0) + "\n" + numbered_patch_text(100), "p.bez");
  ASSERT_EQ(patches.size(), 2u);
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) {
      EXPECT_EQ(patches[0].at(row, col), glm::dvec3(col, row, 10 * row + col));
      EXPECT_EQ(patches[1].at(row, col), glm::dvec3(col + 100, row, 10 * row + col));
      EXPECT_EQ(patches[1].points[static_cast<size_t>(row * 4 + col)], patches[1].at(row, col));
    }
  }
}

TEST(Bez, RefusesBadFilesWithThePlace) {
  const std::string one = numbered_patch_text(0);
  EXPECT_FILE_ERROR(parse_bez("", "p.bez"), "p.bez:1: file is empty");
  EXPECT_FILE_ERROR(parse_bez("2\n" + one, "p.bez"), "declares 2 patches but holds only 48 numbers");
  EXPECT_FILE_ERROR(parse_bez("2147483648\n" + one, "p.bez"),
                    "p.bez:", "declares 2147483648 patches but holds only 48 numbers");
  EXPECT_FILE_ERROR(parse_bez("99999999999999999999999\n" + one, "p.bez"), "p.bez:1:", "number of patches");
  EXPECT_FILE_ERROR(parse_bez("0\n", "p.bez"), "p.bez:1:", "between 1 and");
  std::string bad = "1\n" + one;
  bad.replace(bad.find("0.000000 1 10"), 13, "0.000000 1q 10");  // y of point 5 (row 1, col 0), line 3
  EXPECT_FILE_ERROR(parse_bez(bad, "p.bez"), "p.bez:3: expected y of point 5 of patch 1, found \"1q\"");
  std::string nan = "1\n" + one;
  nan.replace(nan.rfind("33"), 2, "nan");
  EXPECT_FILE_ERROR(parse_bez(nan, "p.bez"), "p.bez:5: z of point 16 of patch 1 must be a finite number");
  EXPECT_FILE_ERROR(parse_bez("1\n" + one + "1 2 3\n", "p.bez"), "p.bez:6: unexpected \"1\" after the last patch");
}

TEST(Bez, WriterRoundTripsExactly) {
  auto patches = parse_bez("2\n" + numbered_patch_text(0.1) + numbered_patch_text(1.0 / 3.0), "p.bez");
  patches[1].at(3, 3) = glm::dvec3(1e-300, -7.25, 1.0 / 7.0);
  const auto back = parse_bez(format_bez(patches, "p.bez"), "p.bez");
  ASSERT_EQ(back.size(), 2u);
  for (size_t p = 0; p < 2; ++p) {
    for (size_t i = 0; i < 16; ++i) EXPECT_EQ(back[p].points[i], patches[p].points[i]) << p << " " << i;
  }
  EXPECT_FILE_ERROR(format_bez({}, "p.bez"), "at least one patch");
}

}  // namespace
}  // namespace meshedit
