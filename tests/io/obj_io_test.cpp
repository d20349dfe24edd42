// Wavefront .obj: exact positions and faces, every corner form, every refusal with its line, and exact
// round trips through the writer.
#include "io/obj_io.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/primitives.h"
#include "io_test_util.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::expect_same_mesh;

TEST(Obj, ReadsVerticesAndEveryCornerForm) {
  const char* text =
      "# a square and a triangle\n"
      "mtllib square.mtl\n"
      "o square\n"
      "v 0 0 0\n"
      "v 1 0 0 1.0\n"             // w is dropped
      "v 1 1 0 0.5 0.25 0.125\n"  // vertex colours are dropped
      "v 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\n"
      "vn 0 0 1\n"
      "g faces\nusemtl red\ns off\n"
      "f 1/1/1 2/2/1 3/3/1 4//1\n"  // i/t/n and i//n
      "v 2 0.5 -1e-3\n"
      "f -4 -1 2/2\n"  // relative and i/t
      "l 1 2\n"
      "unknown statement 1 2 3\n";
  const PolygonMesh m = parse_obj(text, "sq.obj");
  ASSERT_EQ(m.num_vertices(), 5u);
  EXPECT_EQ(m.positions[0], glm::dvec3(0, 0, 0));
  EXPECT_EQ(m.positions[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
  EXPECT_EQ(m.positions[4], glm::dvec3(2, 0.5, -0.001));
  ASSERT_EQ(m.num_faces(), 2u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 1, 4, 1}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 4, 7}));
}

TEST(Obj, CommentsContinuationsAndForwardReferences) {
  const PolygonMesh m =
      parse_obj("f 1 2 \\\n 3 # a face before its vertices\r\nv 0 0 0\nv 1 0 0 # x\nv 0 1 0\n", "f.obj");
  ASSERT_EQ(m.num_faces(), 1u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(m.positions[1], glm::dvec3(1, 0, 0));
}

// What other exporters write: corners with an empty texture or normal part (Wings3D's "1//"), colours after the
// position even when nan, and a UTF-8 byte order mark before the first statement.
TEST(Obj, ReadsEmptyIndexPartsNanColoursAndAByteOrderMark) {
  const PolygonMesh m = parse_obj(
      "\xEF\xBB\xBFv 0 0 0 nan nan nan\nv 1 0 0 1 -nan inf\nv 1 1 0 1e999 0 0\nv 0 1 0 1 0.5 0.25 1\n"
      "f 1// 2/1/ 3/ 4/1/1\n",
      "e.obj");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[0], glm::dvec3(0, 0, 0));
  EXPECT_EQ(m.positions[3], glm::dvec3(0, 1, 0));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3}));
  // A byte order mark anywhere else is not one: here it starts an unknown statement, skipped.
  EXPECT_EQ(parse_obj("v 0 0 0\n\xEF\xBB\xBFv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n", "e.obj").num_vertices(), 3u);
}

// A face of fewer than 3 corners (a loose edge written as "f 1 2", even an empty "f") or one that repeats a vertex is
// read as the file has it, for the builder to refuse by its number and mesh repair to drop with a report.
TEST(Obj, KeepsFacesOfFewerThanThreeCornersForRepair) {
  const PolygonMesh m = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\nf 3\nf\nf 1 1 2\n", "t.obj");
  ASSERT_EQ(m.num_faces(), 5u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 1, 2, 0, 0, 1}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 5, 6, 6, 9}));
}

TEST(Obj, RefusesBadFilesWithTheLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_FILE_ERROR(parse_obj("", "t.obj"), "t.obj:1: file is empty");
  EXPECT_FILE_ERROR(parse_obj("# nothing\n", "t.obj"), "t.obj:1: file is empty");
  EXPECT_FILE_ERROR(parse_obj(tri, "t.obj"), "t.obj: file holds no faces");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 4\n", "t.obj"), "t.obj:4: face refers to vertex 4, but only 3 are defined");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 99999999999\n", "t.obj"), "t.obj:4: face refers to vertex 99999999999");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 -4\n", "t.obj"),
                    "t.obj:4: face refers to vertex -4 (counting back), but only 3 are defined so far");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 0\n", "t.obj"), "t.obj:4: face corner \"0\": OBJ indices start at 1");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 3x\n", "t.obj"), "t.obj:4:", "vertex index \"3x\" is not a whole number");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 /3\n", "t.obj"), "t.obj:4:", "vertex index \"\" is not a whole number");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 3/x/\n", "t.obj"), "t.obj:4:", "texture index \"x\"");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 3//1.5\n", "t.obj"), "t.obj:4:", "normal index \"1.5\"");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 3/0/\n", "t.obj"), "t.obj:4:", "OBJ indices start at 1");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 3/1/1/1\n", "t.obj"), "t.obj:4:", "more than 3 parts");
  EXPECT_FILE_ERROR(parse_obj("v 0 0\n", "t.obj"), "t.obj:1: vertex has 2 coordinates; 3 are needed");
  EXPECT_FILE_ERROR(parse_obj("v 0 0 0 1 1 1 1 1\n", "t.obj"), "t.obj:1:", "more than 7 numbers");
  EXPECT_FILE_ERROR(parse_obj("v 0 0 0\nv 0 nan 0\n", "t.obj"),
                    "t.obj:2: vertex y must be a finite number, found \"nan\"");
  EXPECT_FILE_ERROR(parse_obj("v 0 0 0\n\nv 0 0 -inf\n", "t.obj"), "t.obj:3:", "\"-inf\"");
  EXPECT_FILE_ERROR(parse_obj("v 0 0 0 0.5 red 1\n", "t.obj"), "t.obj:1: expected vertex red, found \"red\"");
  EXPECT_FILE_ERROR(parse_obj("v 0 0.5x 0\n", "t.obj"), "t.obj:1: expected vertex y, found \"0.5x\"");
  EXPECT_FILE_ERROR(parse_obj("v 1e999 0 0\n", "t.obj"), "t.obj:1: vertex x is out of range");
  EXPECT_FILE_ERROR(parse_obj(tri + "f 1 2 3\nv 0 0", "t.obj"), "t.obj:5: vertex has 2 coordinates");  // truncated
  EXPECT_FILE_ERROR(parse_obj(std::string("\n\nv \xff\xfe\0\x01 0 0", 12), "t.obj"),
                    "t.obj:3: expected vertex x, found \"\\xff\\xfe\\x00\\x01\"");
  // The forward reference is reported at the first line that used the largest missing index.
  EXPECT_FILE_ERROR(parse_obj("f 1 2 9\n" + tri + "f 1 2 3\n", "t.obj"),
                    "t.obj:1: face refers to vertex 9, but only 3");
}

TEST(Obj, WriterRoundTripsPrimitivesExactly) {
  for (const PolygonMesh& m :
       {make_tetrahedron(), make_cube(), make_cube_quads(), make_icosahedron(), make_torus(6, 5), make_fan(7)}) {
    const std::string text = format_obj(m, "m.obj");
    EXPECT_EQ(text.rfind("# MeshEdit OBJ: ", 0), 0u);
    expect_same_mesh(parse_obj(text, "m.obj"), m);
  }
}

TEST(Obj, WriterUsesOneBasedFacesAndShortNumbers) {
  PolygonMesh m;
  m.add_vertex({0.5, -1, 1e-7});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  EXPECT_EQ(format_obj(m, "m.obj"), "# MeshEdit OBJ: 3 vertices, 1 faces\nv 0.5 -1 1e-07\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
}

TEST(Obj, WriterRefusesMeshesItsReaderWouldRefuse) {
  PolygonMesh m = make_tetrahedron();
  m.indices[5] = 9;
  EXPECT_FILE_ERROR(format_obj(m, "m.obj"), "m.obj: face 1: refers to vertex 9, but the mesh has 4 vertices");
  PolygonMesh nan = make_tetrahedron();
  nan.positions[2].y = std::nan("");
  EXPECT_FILE_ERROR(format_obj(nan, "m.obj"), "m.obj: vertex 2: position is not finite");
  PolygonMesh line;
  line.add_vertex({0, 0, 0});
  line.add_vertex({1, 0, 0});
  line.add_face({0, 1});
  EXPECT_FILE_ERROR(format_obj(line, "m.obj"), "m.obj: face 0: has 2 corners");
  EXPECT_FILE_ERROR(format_obj(PolygonMesh{}, "m.obj"), "m.obj: mesh has no faces");
}

TEST(Obj, WritesAndReadsFiles) {
  const auto dir = testing::scratch_dir();
  write_obj(dir / "cube.obj", make_cube());
  expect_same_mesh(read_obj(dir / "cube.obj"), make_cube());
  EXPECT_FALSE(std::filesystem::exists(dir / "cube.obj.meshedit-tmp"));
}

}  // namespace
}  // namespace meshedit
