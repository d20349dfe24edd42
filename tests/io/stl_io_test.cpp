// STL: ASCII files as CAD tools and Blender write them, binary files with an 80-byte header (one starting
// with "solid", as SolidWorks writes), welding by exact position, every refusal with its line or triangle
// and byte, and round trips through the writer.
#include "io/stl_io.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "binary_builder.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/primitives.h"
#include "io_test_util.h"

namespace meshedit {
namespace {

using testing::BinaryBuilder;

// Two triangles of a square sharing the edge (0,0,0)-(1,1,0); -0 and 0 are the same coordinate.
const std::string kAsciiSquare =
    "solid Square exported by hand\n"
    "  facet normal 0.000000e+00 0.000000e+00 1.000000e+00\n"
    "    outer loop\n"
    "      vertex 0.000000e+00 0.000000e+00 0.000000e+00\n"
    "      vertex 1.000000e+00 0.000000e+00 0.000000e+00\n"
    "      vertex 1.000000e+00 1.000000e+00 0.000000e+00\n"
    "    endloop\n"
    "  endfacet\n"
    "  facet normal -nan -nan -nan\n"
    "    outer loop\n"
    "      vertex -0.000000e+00 0.000000e+00 0.000000e+00\n"
    "      vertex 1 1 0\n"
    "      vertex 0 1 2.5e-1\n"
    "    endloop\n"
    "  endfacet\n"
    "endsolid Square exported by hand\n";

TEST(Stl, ReadsAsciiAndWeldsCornersByPosition) {
  const PolygonMesh m = parse_stl(kAsciiSquare, "square.stl");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[0], glm::dvec3(0, 0, 0));
  EXPECT_EQ(m.positions[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
  EXPECT_EQ(m.positions[3], glm::dvec3(0, 1, 0.25));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 6}));
}

TEST(Stl, ReadsSeveralSolidsAndCrlf) {
  std::string two =
      "solid a\r\nfacet normal 0 0 1\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 0 0\r\nvertex 0 1 0\r\n"
      "endloop\r\nendfacet\r\nendsolid a\r\n"
      "solid b\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid\n";
  const PolygonMesh m = parse_stl(two, "two.stl");
  EXPECT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(m.positions[3], glm::dvec3(1, 1, 0));
}

std::string binary_stl(const std::string& header80, const std::vector<std::array<float, 9>>& triangles) {
  BinaryBuilder b(false, header80);
  b.u32(static_cast<uint32_t>(triangles.size()));
  for (const auto& t : triangles) {
    b.f32(0).f32(0).f32(1);
    for (float v : t) b.f32(v);
    b.u16(0);
  }
  return b.bytes();
}

std::string header(const std::string& text) { return text + std::string(80 - text.size(), '\0'); }

TEST(Stl, ReadsBinaryEvenWhenTheHeaderStartsWithSolid) {
  const std::vector<std::array<float, 9>> square = {{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0.5f}};
  for (const std::string& h : {header("Exported from Blender-4.1.1"), header("solid PART1 by SolidWorks")}) {
    const PolygonMesh m = parse_stl(binary_stl(h, square), "part.stl");
    ASSERT_EQ(m.num_vertices(), 4u) << h;
    EXPECT_EQ(m.positions[3], glm::dvec3(0, 1, 0.5));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  }
  // Bytes after the triangles (some exporters pad) are ignored when the header does not say "solid".
  const PolygonMesh padded = parse_stl(binary_stl(header("x"), square) + std::string(7, '\0'), "p.stl");
  EXPECT_EQ(padded.num_faces(), 2u);
}

// A triangle whose corners merge is kept as the file has it: the builder names it, and repair drops it and says so.
TEST(Stl, KeepsTrianglesWithoutAreaForTheBuilderToName) {
  const PolygonMesh m =
      parse_stl(binary_stl(header("x"), {{0, 0, 0, 1, 0, 0, 1, 0, 0}, {0, 0, 0, 1, 0, 0, 0, 1, 0}}), "d.stl");
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 1, 0, 1, 2}));
  try {
    build_halfedge_mesh(m);
    ADD_FAILURE() << "the builder took a face that uses a vertex twice";
  } catch (const MeshError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("face 0 is degenerate: it uses vertex 1 twice", 0), 0u) << e.what();
  }
  const RepairResult repaired = repair_polygons(m);
  EXPECT_EQ(repaired.polygons.indices, (std::vector<uint32_t>{0, 1, 2}));
  ASSERT_EQ(repaired.report.changes.size(), 1u);
  EXPECT_NE(repaired.report.changes[0].find("face 0"), std::string::npos) << repaired.report.changes[0];
  EXPECT_FILE_ERROR(parse_stl(binary_stl(header("x"), {}), "d.stl"), "d.stl: file holds no triangles");
}

TEST(Stl, RefusesBadBinaryFilesWithTriangleAndByte) {
  EXPECT_FILE_ERROR(parse_stl("", "t.stl"), "t.stl: file is empty");
  EXPECT_FILE_ERROR(parse_stl("not an stl", "t.stl"), "t.stl: not an STL file: 10 bytes");
  std::string claims = binary_stl(header("x"), {{0, 0, 0, 1, 0, 0, 0, 1, 0}});
  claims[80] = '\xff';
  claims[81] = '\xff';
  claims[82] = '\xff';
  claims[83] = '\xff';  // 4294967295 triangles
  EXPECT_FILE_ERROR(parse_stl(claims, "t.stl"),
                    "t.stl: byte 80: the header declares 4294967295 triangles (214748364834 bytes), but the file "
                    "has 134 bytes");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FILE_ERROR(
      parse_stl(binary_stl(header("x"), {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, nan, 0, 0, 1, 0}}), "t.stl"),
      "t.stl: triangle 1, byte 162: corner 1 is not a finite position");
}

TEST(Stl, RefusesBadAsciiFilesWithTheLine) {
  auto broken = [](const std::string& from, const std::string& to) {
    std::string text = kAsciiSquare;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  EXPECT_FILE_ERROR(
      parse_stl(broken("      vertex 1.000000e+00 1.000000e+00 0.000000e+00\n    endloop", "    endloop"), "t.stl"),
      "t.stl:6: expected \"vertex\", found \"endloop\"");
  EXPECT_FILE_ERROR(parse_stl(broken("vertex 0 1 2.5e-1", "vertex 0 1 x"), "t.stl"),
                    "t.stl:13: expected a vertex coordinate, found \"x\"");
  EXPECT_FILE_ERROR(parse_stl(broken("vertex 1 1 0", "vertex 1 inf 0"), "t.stl"),
                    "t.stl:12: a vertex coordinate must be a finite number");
  EXPECT_FILE_ERROR(parse_stl(broken("endsolid Square exported by hand\n", ""), "t.stl"),
                    "t.stl:16: file ends where \"endsolid\" was expected");
  EXPECT_FILE_ERROR(parse_stl(broken("  facet normal -nan", "  facit normal -nan"), "t.stl"),
                    "t.stl:9: expected \"facet\" or \"endsolid\", found \"facit\"");
  EXPECT_FILE_ERROR(parse_stl("solid empty\nendsolid empty\n", "t.stl"), "t.stl: file holds no triangles");
}

TEST(Stl, RoundTripsTrianglesAndSplitsPolygonsIntoFans) {
  for (const PolygonMesh& mesh : {make_icosahedron(), make_torus(6, 4), make_cube()}) {
    const PolygonMesh back = parse_stl(format_stl(mesh, "m.stl"), "m.stl");
    EXPECT_EQ(back.num_vertices(), mesh.num_vertices());
    // Positions come back as floats, the format's only number type.
    PolygonMesh as_floats = mesh;
    // Through a volatile float: GCC 12's SLP vectorizer at -O2 drops a double -> float -> double round trip of
    // a glm::dvec3's coordinates stored back into the vector.
    for (glm::dvec3& p : as_floats.positions) {
      for (int a = 0; a < 3; ++a) {
        volatile float rounded = static_cast<float>(p[a]);
        p[a] = rounded;
      }
    }
    testing::expect_same_face_positions(back, as_floats);
  }
  const std::string bytes = format_stl(make_cube_quads(), "q.stl");
  EXPECT_EQ(bytes.size(), 84u + 12 * 50);
  EXPECT_NE(bytes.compare(0, 5, "solid"), 0);
  const PolygonMesh back = parse_stl(bytes, "q.stl");
  EXPECT_EQ(back.num_faces(), 12u);
  EXPECT_EQ(back.num_vertices(), 8u);
  // The first quad's two triangles: its corners only, covering its area, facing its way.
  const PolygonMesh quads = make_cube_quads();
  const auto q = quads.face(0);
  const glm::dvec3 quad_normal =
      glm::cross(quads.positions[q[1]] - quads.positions[q[0]], quads.positions[q[2]] - quads.positions[q[0]]);
  double area = 0;
  for (size_t f = 0; f < 2; ++f) {
    const auto t = back.face(f);
    for (const uint32_t corner : t) {
      EXPECT_TRUE(
          std::any_of(q.begin(), q.end(), [&](uint32_t c) { return quads.positions[c] == back.positions[corner]; }));
    }
    const glm::dvec3 n =
        glm::cross(back.positions[t[1]] - back.positions[t[0]], back.positions[t[2]] - back.positions[t[0]]);
    EXPECT_GT(glm::dot(n, quad_normal), 0.0);
    area += 0.5 * glm::length(n);
  }
  EXPECT_DOUBLE_EQ(area, glm::length(quad_normal));
}

// A non-convex face (an L-shaped hexagon from whose first corner a fan would cross the notch, making a triangle that
// faces the other way) is written as triangles inside it, each facing the face's way, their areas adding up to the L's.
TEST(Stl, WriterCutsANonConvexFaceInsideItself) {
  PolygonMesh l_shape;
  for (const glm::dvec3& p : {glm::dvec3(0, 2, 0), glm::dvec3(0, 0, 0), glm::dvec3(2, 0, 0), glm::dvec3(2, 1, 0),
                              glm::dvec3(1, 1, 0), glm::dvec3(1, 2, 0)}) {
    l_shape.add_vertex(p);
  }
  l_shape.add_face({0, 1, 2, 3, 4, 5});
  const PolygonMesh back = parse_stl(format_stl(l_shape, "l.stl"), "l.stl");
  ASSERT_EQ(back.num_faces(), 4u);
  double area = 0;
  for (size_t f = 0; f < back.num_faces(); ++f) {
    const auto t = back.face(f);
    const glm::dvec3 n =
        glm::cross(back.positions[t[1]] - back.positions[t[0]], back.positions[t[2]] - back.positions[t[0]]);
    EXPECT_GT(n.z, 0.0) << "triangle " << f << " faces the polygon's way";
    area += 0.5 * n.z;
  }
  EXPECT_DOUBLE_EQ(area, 3.0);
}

TEST(Stl, WriterRefusesPositionsBeyondFloats) {
  PolygonMesh big = make_cube();
  big.positions[5].z = 1e300;
  EXPECT_FILE_ERROR(format_stl(big, "big.stl"), "big.stl: vertex 5: position does not fit STL's float coordinates");
}

}  // namespace
}  // namespace meshedit
