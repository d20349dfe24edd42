// Stanford PLY: files in the layouts MeshLab, Blender and the Stanford scanning repository write (ASCII and
// both binary byte orders, extra vertex properties, other elements, every integer list type), exact
// positions and faces, every refusal with its line or element and byte, and round trips through the writer.
#include "io/ply_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "binary_builder.h"
#include "core/primitives.h"
#include "io_test_util.h"

namespace meshedit {
namespace {

using testing::BinaryBuilder;
using testing::expect_same_mesh;

// MeshLab's ASCII export with normals and colours (VCG writes a space after each face line).
const std::string kMeshLabAscii =
    "ply\n"
    "format ascii 1.0\n"
    "comment VCGLIB generated\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "property float nx\n"
    "property float ny\n"
    "property float nz\n"
    "property uchar red\n"
    "property uchar green\n"
    "property uchar blue\n"
    "property uchar alpha\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 0 0 0 1 255 0 0 255\n"
    "1 0 0 0 0 1 0 255 0 255\n"
    "1 1 0.25 0 0 1 0 0 255 255\n"
    "-0.5 1 -1e-3 0 0 1 255 255 255 255\n"
    "3 0 1 2 \n"
    "4 0 2 3 1 \n";

TEST(Ply, ReadsMeshLabAsciiWithNormalsAndColours) {
  const PolygonMesh m = parse_ply(kMeshLabAscii, "square.ply");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[0], glm::dvec3(0, 0, 0));
  EXPECT_EQ(m.positions[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0.25));
  EXPECT_EQ(m.positions[3], glm::dvec3(-0.5, 1, -0.001));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 7}));
}

// The Stanford repository's scans: "zipper output" with confidence and intensity per vertex, in the
// SGI-era big-endian binary layout; CRLF line ends in the header are tolerated too.
TEST(Ply, ReadsStanfordBigEndianWithConfidenceAndIntensity) {
  const std::string header =
      "ply\r\nformat binary_big_endian 1.0\r\ncomment zipper output\r\nelement vertex 3\r\n"
      "property float x\r\nproperty float y\r\nproperty float z\r\nproperty float confidence\r\n"
      "property float intensity\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n";
  BinaryBuilder b(true, header);
  b.f32(-0.0378297f).f32(0.12794f).f32(0.00447467f).f32(0.850855f).f32(0.5f);
  b.f32(-0.0447794f).f32(0.128887f).f32(0.00190497f).f32(0.900159f).f32(0.5f);
  b.f32(-0.0680095f).f32(0.151244f).f32(0.0371953f).f32(0.398443f).f32(0.5f);
  b.u8(3).i32(2).i32(0).i32(1);
  const PolygonMesh m = parse_ply(b.bytes(), "bun_zipper.ply");
  ASSERT_EQ(m.num_vertices(), 3u);
  EXPECT_EQ(m.positions[0], glm::dvec3(double(-0.0378297f), double(0.12794f), double(0.00447467f)));
  EXPECT_EQ(m.positions[2], glm::dvec3(double(-0.0680095f), double(0.151244f), double(0.0371953f)));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{2, 0, 1}));
}

// Blender's exporter: little endian, normals and texture coordinates, `list uchar uint`.
TEST(Ply, ReadsBlenderLittleEndianWithUvs) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment Created in Blender version 4.1.1\nelement vertex 4\n"
      "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
      "property float nz\nproperty float s\nproperty float t\nelement face 1\n"
      "property list uchar uint vertex_indices\nend_header\n";
  BinaryBuilder b(false, header);
  const float corners[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0.5f}};
  for (const auto& c : corners) b.f32(c[0]).f32(c[1]).f32(c[2]).f32(0).f32(0).f32(1).f32(0.5f).f32(0.5f);
  b.u8(4).u32(0).u32(1).u32(2).u32(3);
  const PolygonMesh m = parse_ply(b.bytes(), "plane.ply");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[1], glm::dvec3(1, -1, 0));
  EXPECT_EQ(m.positions[3], glm::dvec3(-1, 1, 0.5));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 4}));
}

// Double coordinates, `vertex_index`, 16-bit list types, a face property before the list, and other
// elements (edges, a list-holding element) before and after, all skipped.
TEST(Ply, ReadsDoublesVertexIndexAndSkipsOtherElements) {
  const std::string header =
      "ply\nformat binary_big_endian 1.0\nobj_info made by hand\nelement material 1\nproperty list int uchar name\n"
      "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nproperty list uint8 float extra\n"
      "element face 1\nproperty int16 flags\nproperty list int16 uint16 vertex_index\n"
      "element edge 2\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  BinaryBuilder b(true, header);
  b.i32(3).u8('r').u8('e').u8('d');
  b.f64(0.1).f64(0.2).f64(0.3).u8(0);
  b.f64(1).f64(0).f64(0).u8(2).f32(7).f32(8);
  b.f64(0).f64(1e300).f64(-2).u8(0);
  b.i16(-1).i16(3).u16(0).u16(1).u16(2);
  b.i32(0).i32(1).i32(1).i32(2);
  const PolygonMesh m = parse_ply(b.bytes(), "d.ply");
  ASSERT_EQ(m.num_vertices(), 3u);
  EXPECT_EQ(m.positions[0], glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_EQ(m.positions[2], glm::dvec3(0, 1e300, -2));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(Ply, ReadsEveryIntegerListType) {
  const char* types[] = {"char", "uchar", "short", "ushort", "int",   "uint",
                         "int8", "uint8", "int16", "uint16", "int32", "uint32"};
  for (const char* count_type : types) {
    for (const char* index_type : types) {
      const std::string ascii = std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n") +
                                "property float y\nproperty float z\nelement face 1\nproperty list " + count_type +
                                " " + index_type + " vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n";
      const PolygonMesh m = parse_ply(ascii, "t.ply");
      EXPECT_EQ(m.indices, (std::vector<uint32_t>{2, 1, 0})) << count_type << " " << index_type;
    }
  }
}

const std::string kTriangleHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

std::string binary_triangle(float y1, int32_t last_index) {
  BinaryBuilder b(false, kTriangleHeader);
  b.f32(0).f32(0).f32(0).f32(1).f32(y1).f32(0).f32(0).f32(1).f32(0);
  b.u8(3).i32(0).i32(1).i32(last_index);
  return b.bytes();
}

TEST(Ply, RefusesBadHeadersWithTheLine) {
  EXPECT_FILE_ERROR(parse_ply("", "t.ply"), "t.ply: file is empty");
  EXPECT_FILE_ERROR(parse_ply("solid x\n", "t.ply"), "t.ply:1: not a PLY file");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 3\n", "t.ply"),
                    "t.ply:4: the header has no end_header line");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat binary_middle_endian 1.0\nend_header\n", "t.ply"),
                    "t.ply:2: unknown format \"binary_middle_endian\"");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 2.0\nend_header\n", "t.ply"), "t.ply:2: unsupported PLY version");
  EXPECT_FILE_ERROR(parse_ply("ply\nelement vertex 0\nend_header\n", "t.ply"), "t.ply:3: the header has no format");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nproperty float x\nend_header\n", "t.ply"),
                    "t.ply:3: property before any element");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n", "t.ply"),
                    "t.ply:4: unknown property type \"float128\"");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement f 1\nproperty list float int v\nend_header\n", "t.ply"),
                    "t.ply:4: a list's count type must be an integer type");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 4294967296\nend_header\n", "t.ply"),
                    "t.ply:3: element vertex: count must be a whole number below 2^32");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n", "t.ply"), "t.ply:3:");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nvertex 3\nend_header\n", "t.ply"),
                    "t.ply:3: unknown header line \"vertex 3\"");
}

TEST(Ply, RefusesMissingElementsAndProperties) {
  const std::string start = "ply\nformat ascii 1.0\n";
  EXPECT_FILE_ERROR(parse_ply(start + "element face 0\nend_header\n", "t.ply"), "t.ply: the header declares no vertex");
  EXPECT_FILE_ERROR(parse_ply(start + "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                                      "end_header\n",
                              "t.ply"),
                    "t.ply: file holds no faces");
  EXPECT_FILE_ERROR(parse_ply(start + "element vertex 1\nproperty float x\nproperty float y\nelement face 0\n"
                                      "property list uchar int vertex_indices\nend_header\n0 0\n",
                              "t.ply"),
                    "t.ply:3: the vertex element has no scalar property z");
  EXPECT_FILE_ERROR(parse_ply(start + "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                                      "element face 0\nproperty list uchar int corners\nend_header\n",
                              "t.ply"),
                    "t.ply:7: the face element has no list property vertex_indices");
  EXPECT_FILE_ERROR(parse_ply(start + "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                                      "element face 0\nproperty list uchar float vertex_indices\nend_header\n",
                              "t.ply"),
                    "t.ply:7: face vertex indices must have an integer type");
  EXPECT_FILE_ERROR(parse_ply(start + "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                                      "element face 0\nproperty list uchar int vertex_indices\nend_header\n",
                              "t.ply"),
                    "t.ply: file holds no faces");
  EXPECT_FILE_ERROR(parse_ply(start + "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                                      "element edge 0\nproperty int vertex1\nend_header\n",
                              "t.ply"),
                    "t.ply: file holds no faces (the header declares no face or tristrips element)");
}

TEST(Ply, HugeDeclaredCountsFailBeforeAllocating) {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  EXPECT_FILE_ERROR(parse_ply("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n" + xyz +
                                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n",
                              "t.ply"),
                    "t.ply:3: declares 4000000000 vertices; MeshEdit reads up to 16777216");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + xyz +
                                  "element face 4000000000\nproperty list uchar int vertex_indices\nend_header\n",
                              "t.ply"),
                    "t.ply:7: declares 4000000000 faces");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat binary_little_endian 1.0\nelement vertex 16000000\n" + xyz +
                                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n",
                              "t.ply"),
                    "t.ply:3: declares 16000000 vertex elements, but the body holds only 0 bytes");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 3\n" + xyz +
                                  "element face 1\nproperty list uchar int vertex_indices\nelement junk 3000000000\n"
                                  "property int a\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                              "t.ply"),
                    "t.ply:9: declares 3000000000 junk elements, but the body holds only 13 numbers");
}

TEST(Ply, RefusesBadBinaryBodiesWithElementAndByte) {
  const size_t body = kTriangleHeader.size();
  EXPECT_NO_THROW(parse_ply(binary_triangle(0, 2), "t.ply"));
  const std::string index_byte = "t.ply: face 0, byte " + std::to_string(body + 36 + 9) + ": ";
  const std::string y_byte = "t.ply: vertex 1, byte " + std::to_string(body + 12 + 4) + ": ";
  const std::string index_3 = index_byte + "index 3 is not below the vertex count 3";
  const std::string index_minus_1 = index_byte + "index -1 is not below";
  const std::string ends = index_byte + "file ends where a vertex index was expected";
  const std::string y_not_finite = y_byte + "y is not a finite number";
  EXPECT_FILE_ERROR(parse_ply(binary_triangle(0, 3), "t.ply"), index_3.c_str());
  EXPECT_FILE_ERROR(parse_ply(binary_triangle(0, -1), "t.ply"), index_minus_1.c_str());
  EXPECT_FILE_ERROR(parse_ply(binary_triangle(std::numeric_limits<float>::quiet_NaN(), 2), "t.ply"),
                    y_not_finite.c_str());
  EXPECT_FILE_ERROR(parse_ply(binary_triangle(std::numeric_limits<float>::infinity(), 2), "t.ply"),
                    y_not_finite.c_str());
  const std::string whole = binary_triangle(0, 2);
  EXPECT_FILE_ERROR(parse_ply(whole.substr(0, whole.size() - 2), "t.ply"), ends.c_str());
  std::string two_corners = whole;  // the third index's bytes are then past the last element, and ignored
  two_corners[body + 36] = 2;
  EXPECT_EQ(parse_ply(two_corners, "t.ply").indices, (std::vector<uint32_t>{0, 1}));
}

TEST(Ply, RefusesBadAsciiBodiesWithTheLine) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_NO_THROW(parse_ply(header + vertices + "3 0 1 2\n3 2 1 0\n", "t.ply"));
  EXPECT_FILE_ERROR(parse_ply(header + vertices + "3 0 1 2\n3 2 1 3\n", "t.ply"),
                    "t.ply:14: face 1: index 3 is not below the vertex count 3");
  EXPECT_FILE_ERROR(parse_ply(header + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n3 2 1 0\n", "t.ply"),
                    "t.ply:11: vertex 1: expected y (a finite number), found \"nan\"");
  EXPECT_FILE_ERROR(parse_ply(header + vertices + "3 0 1 2\n256 2 1 0\n", "t.ply"),
                    "t.ply:14: face 1: expected the face's corner count (uchar), found \"256\"");
  EXPECT_FILE_ERROR(parse_ply(header + vertices + "3 0 1 2\n3 2 1.5 0\n", "t.ply"),
                    "t.ply:14: face 1: expected a vertex index (int), found \"1.5\"");
  EXPECT_FILE_ERROR(parse_ply(header + vertices + "3 0 1 2\n3 2 1\n", "t.ply"),
                    "face 1: file ends where a vertex index was expected");
}

// A face of fewer than 3 corners or one that repeats a vertex is read as the file has it, for the builder to refuse
// by its number and mesh repair to drop with a report; a negative corner count is no face at all.
TEST(Ply, KeepsFacesOfFewerThanThreeCornersForRepair) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list char int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  const PolygonMesh m = parse_ply(header + "3 0 1 2\n1 2\n0\n3 0 0 1\n", "t.ply");
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 2, 0, 0, 1}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 4, 4, 7}));
  EXPECT_FILE_ERROR(parse_ply(header + "3 0 1 2\n-1 2\n0\n3 0 0 1\n", "t.ply"),
                    "t.ply:14: face 1: face has a negative corner count -1");
}

const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";

// A square of 3 x 2 vertices:  3 4 5  (y = 1)
//                               0 1 2  (y = 0)
const std::string kGridVertices = "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n";

// Strips as some of the old Stanford scans store their triangles: one list per tristrips item, strips separated by
// -1; every other triangle of a strip flipped, so all face +z here; the degenerate triangles that join strips skipped.
TEST(Ply, ReadsTriangleStripsAsTrianglesFacingOneWay) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 6\n" + kXyz +
                             "element tristrips 2\nproperty list int int vertex_indices\nend_header\n" + kGridVertices;
  // Item 0: the left square as a strip, -1, then the right square, ending in a repeated vertex whose degenerate
  // triangle is skipped; item 1: an empty list.
  const PolygonMesh m = parse_ply(header + "10 0 1 3 4 -1 1 2 4 5 5\n0\n", "strips.ply");
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 3, 3, 1, 4, 1, 2, 4, 4, 2, 5}));
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const glm::dvec3 a = m.positions[m.face(f)[0]], b = m.positions[m.face(f)[1]], c = m.positions[m.face(f)[2]];
    EXPECT_GT((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 0) << "triangle " << f << " faces -z";
  }
  // Degenerate triangles inside one strip keep the parity: 0 1 3 4 4 1 1 2 4 5 is the same two squares.
  const PolygonMesh joined = parse_ply(header + "10 0 1 3 4 4 1 1 2 4 5\n0\n", "strips.ply");
  EXPECT_EQ(joined.num_faces(), 4u);
  EXPECT_EQ(joined.indices, (std::vector<uint32_t>{0, 1, 3, 3, 1, 4, 1, 2, 4, 4, 2, 5}));
}

// Faces and strips in one file, in their elements' order; a binary big-endian strip as the Stanford files have it.
TEST(Ply, ReadsFacesAndStripsTogetherAndBinaryStrips) {
  const std::string both = "ply\nformat ascii 1.0\nelement vertex 6\n" + kXyz +
                           "element tristrips 1\nproperty list uchar int vertex_index\nproperty uchar flags\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
                           kGridVertices + "4 0 1 3 4 7\n4 1 2 5 4\n";
  const PolygonMesh m = parse_ply(both, "both.ply");
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 3, 3, 1, 4, 1, 2, 5, 4}));
  BinaryBuilder b(true, "ply\nformat binary_big_endian 1.0\nelement vertex 4\n" + kXyz +
                            "property float confidence\nelement tristrips 1\nproperty list int int vertex_indices\n"
                            "end_header\n");
  for (const float p : {0.f, 0.f, 0.f, 0.5f, 1.f, 0.f, 0.f, 0.5f, 0.f, 1.f, 0.f, 0.5f, 1.f, 1.f, 0.f, 0.5f}) b.f32(p);
  b.i32(5).i32(0).i32(1).i32(2).i32(3).i32(-1);
  EXPECT_EQ(parse_ply(b.bytes(), "strips.ply").indices, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
}

TEST(Ply, RefusesBadStripsWithTheLineOrTheByte) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 6\n" + kXyz +
                             "element tristrips 1\nproperty list int int vertex_indices\nend_header\n" + kGridVertices;
  EXPECT_FILE_ERROR(parse_ply(header + "4 0 1 3 6\n", "s.ply"),
                    "s.ply:16: tristrips 0: index 6 is not below the vertex count 6");
  EXPECT_FILE_ERROR(parse_ply(header + "4 0 1 -2 4\n", "s.ply"), "s.ply:16: tristrips 0: index -2 is not below");
  EXPECT_FILE_ERROR(parse_ply(header + "-4 0 1 3 4\n", "s.ply"),
                    "s.ply:16: tristrips 0: the strips have a negative index count -4");
  EXPECT_FILE_ERROR(parse_ply(header + "5 0 1 3 4\n", "s.ply"),
                    "tristrips 0: file ends where a vertex index was expected");
  EXPECT_FILE_ERROR(parse_ply(header + "4 -1 -1 -1 -1\n", "s.ply"), "s.ply: file holds no faces");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 6\n" + kXyz +
                                  "element tristrips 1\nproperty list int float vertex_indices\nend_header\n",
                              "s.ply"),
                    "s.ply:7: tristrips vertex indices must have an integer type");
  EXPECT_FILE_ERROR(parse_ply("ply\nformat ascii 1.0\nelement vertex 6\n" + kXyz +
                                  "element tristrips 1\nproperty list int int strip\nend_header\n",
                              "s.ply"),
                    "s.ply:7: the tristrips element has no list property vertex_indices");
  BinaryBuilder b(false, "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + kXyz +
                             "element tristrips 1\nproperty list int int vertex_indices\nend_header\n");
  const size_t body = b.bytes().size();
  for (int i = 0; i < 9; ++i) b.f32(float(i % 2));
  b.i32(3).i32(0).i32(1).i32(3);
  const std::string third_index =
      "s.ply: tristrips 0, byte " + std::to_string(body + 36 + 12) + ": index 3 is not below";
  EXPECT_FILE_ERROR(parse_ply(b.bytes(), "s.ply"), third_index.c_str());
}

TEST(Ply, RoundTripsExactly) {
  for (const PolygonMesh& mesh : {make_torus(5, 4), make_cube_quads(), make_icosahedron()}) {
    const std::string bytes = format_ply(mesh, "m.ply");
    expect_same_mesh(parse_ply(bytes, "m.ply"), mesh);
  }
  // Coordinates that are not floats are written as doubles; a face of 300 corners gets a uint count.
  PolygonMesh fine;
  std::vector<uint32_t> ring;
  for (uint32_t i = 0; i < 300; ++i) {
    fine.add_vertex({std::cos(i * 0.021), std::sin(i * 0.021), 0.1});
    ring.push_back(i);
  }
  fine.add_face(ring);
  const std::string bytes = format_ply(fine, "fine.ply");
  EXPECT_NE(bytes.find("property double x\n"), std::string::npos);
  EXPECT_NE(bytes.find("property list uint int vertex_indices\n"), std::string::npos);
  expect_same_mesh(parse_ply(bytes, "fine.ply"), fine);
  EXPECT_NE(format_ply(make_cube_quads(), "c.ply").find("property float x\n"), std::string::npos);
}

TEST(Ply, WriterRefusesMeshesItsReaderWouldRefuse) {
  PolygonMesh bad = make_cube();
  bad.positions[2].y = std::nan("");
  EXPECT_FILE_ERROR(format_ply(bad, "bad.ply"), "bad.ply: vertex 2: position is not finite");
}

}  // namespace
}  // namespace meshedit
