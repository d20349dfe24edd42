// OFF: files as Geomview, the Princeton Shape Benchmark and ModelNet write them (comments, COFF colours
// per vertex and per face, counts on the keyword's line, the missing line break of "OFF490 518 0"),
// exact positions and faces, and every refusal with its line.
#include "io/off_io.h"

#include <gtest/gtest.h>

#include "io_test_util.h"

namespace meshedit {
namespace {

TEST(Off, ReadsCommentsAndFaceColours) {
  const char* text =
      "OFF\n"
      "# a square pyramid, by hand\n"
      "5 5 8\n"
      "\n"
      "0 0 0\n"
      "1 0 0   # a comment after a vertex\n"
      "1 1 0\n"
      "0 1 0\n"
      "0.5 0.5 1.5e0\n"
      "4 3 2 1 0\n"
      "3 0 1 4 255 0 0\n"  // a face colour (integers)
      "3 1 2 4 0.0 1.0 0.0 0.75\n"
      "3 2 3 4\n"
      "3 3 0 4\n";
  const PolygonMesh m = parse_off(text, "pyramid.off");
  ASSERT_EQ(m.num_vertices(), 5u);
  EXPECT_EQ(m.positions[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(m.positions[4], glm::dvec3(0.5, 0.5, 1.5));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{3, 2, 1, 0, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 4, 7, 10, 13, 16}));
}

TEST(Off, ReadsCoffWithVertexColours) {
  const PolygonMesh m =
      parse_off("COFF\n3 1 3\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 -2 0 0 255 255\n3 0 1 2\n", "c.off");
  ASSERT_EQ(m.num_vertices(), 3u);
  EXPECT_EQ(m.positions[2], glm::dvec3(0, 1, -2));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(Off, CountsMayShareTheKeywordsLine) {
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 2 1\n";
  for (const std::string start : {"OFF 3 1 0\n", "OFF3 1 0\n", "3 1 0\n", "NOFF\n3 1\n", "STCOFF\n3 1 3\n"}) {
    const PolygonMesh m = parse_off(start + body, "m.off");
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 2, 1})) << start;
    EXPECT_EQ(m.positions[1], glm::dvec3(1, 0, 0)) << start;
  }
}

TEST(Off, RefusesBadFilesWithTheLine) {
  const std::string tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_NO_THROW(parse_off(tri + "3 0 1 2\n", "t.off"));
  EXPECT_FILE_ERROR(parse_off("", "t.off"), "t.off:1: file is empty");
  EXPECT_FILE_ERROR(parse_off("# only a comment\n", "t.off"), "t.off:1: file is empty");
  EXPECT_FILE_ERROR(parse_off("4OFF\n3 1 0\n", "t.off"), "t.off:1: \"4OFF\": 4D and n-dimensional");
  EXPECT_FILE_ERROR(parse_off("OFF BINARY\n3 1 0\n", "t.off"), "t.off:1: binary OFF files are not supported");
  EXPECT_FILE_ERROR(parse_off("XOFF\n3 1 0\n", "t.off"), "t.off:1: expected the keyword OFF");
  EXPECT_FILE_ERROR(parse_off("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "t.off"),
                    "t.off:2: the face count must be between 1 and");
  EXPECT_FILE_ERROR(parse_off(tri + "3 0 1 3\n", "t.off"),
                    "t.off:6: face 0: index \"3\" is not below the vertex count 3");
  EXPECT_FILE_ERROR(parse_off(tri + "3 0 1 -1\n", "t.off"), "t.off:6: face 0: index \"-1\" is not below");
  EXPECT_FILE_ERROR(parse_off(tri + "3 0 1 x\n", "t.off"), "t.off:6: face 0: expected a vertex index, found \"x\"");
  EXPECT_FILE_ERROR(parse_off(tri + "-1 0 1 2\n", "t.off"), "t.off:6: face 0's corner count must be between 0 and");
  EXPECT_FILE_ERROR(parse_off(tri + "4 0 1 2\n0\n", "t.off"),
                    "t.off:6: face 0 declares 4 corners, but its line has 3 indices");
  EXPECT_FILE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2 0 0 0\n", "t.off"),
                    "t.off:4: vertex 1: the line has 2 numbers; x y z are needed");
  EXPECT_FILE_ERROR(parse_off("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "t.off"),
                    "t.off:4: vertex 1 y must be a finite number, found \"nan\"");
  EXPECT_FILE_ERROR(parse_off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 3 2 1 0\n", "t.off"),
                    "t.off:7: file ends where face 1 was expected");
  EXPECT_FILE_ERROR(parse_off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3\n", "t.off"),
                    "t.off:2: declares 3 vertices and 2 faces, but the file holds only 10 numbers after the counts");
}

// A face of fewer than 3 corners, or one that repeats a vertex, is read as the file has it (its colour dropped), for
// the builder to refuse by its number and mesh repair to drop with a report.
TEST(Off, KeepsFacesOfFewerThanThreeCornersForRepair) {
  const PolygonMesh m =
      parse_off("OFF\n3 5 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1 255 0 0\n1 2\n0\n4 1 1 0 0\n", "t.off");
  ASSERT_EQ(m.num_faces(), 5u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 1, 2, 1, 1, 0, 0}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 5, 6, 6, 10}));
}

TEST(Off, HugeDeclaredCountsFailBeforeAllocating) {
  EXPECT_FILE_ERROR(parse_off("OFF\n4000000000 1 0\n", "t.off"),
                    "t.off:2: the vertex count must be between 0 and 16777216");
  EXPECT_FILE_ERROR(parse_off("OFF\n16000000 1 0\n0 0 0\n", "t.off"),
                    "t.off:2: declares 16000000 vertices and 1 faces, but the file holds only 3 numbers");
  EXPECT_FILE_ERROR(parse_off("OFF\n3 30000000 0\n", "t.off"), "t.off:2: the face count must be between 1 and");
}

}  // namespace
}  // namespace meshedit
