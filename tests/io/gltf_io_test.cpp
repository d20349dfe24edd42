// glTF and GLB: exact positions and triangles of small hand-built files (strides, index widths, modes,
// sparse accessors, node transforms, scene choice), every refusal with the glTF object it names, and
// round trips through the writers.
#include "io/gltf_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/primitives.h"
#include "gltf_test_files.h"
#include "io/file_access.h"
#include "io_test_util.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::base64;
using testing::bytes_of;
using testing::error_of;
using testing::glb;
using testing::gltf;
using testing::kSquareBuffer;
using testing::kSquareParts;

TEST(Gltf, ReadsStridedPositionsAndShortIndicesWithTrs) {
  const std::string body =
      "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0,\"translation\":[10,0,0],\"scale\":[2,2,2]}]," +
      kSquareParts;
  const PolygonMesh m = parse_gltf(gltf(body, kSquareBuffer), "sq.gltf");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[0], glm::dvec3(10, 0, 0));
  EXPECT_EQ(m.positions[1], glm::dvec3(12, 0, 0));
  EXPECT_EQ(m.positions[2], glm::dvec3(12, 2, 0));
  EXPECT_EQ(m.positions[3], glm::dvec3(10, 2, 0));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(m.face_offsets, (std::vector<uint32_t>{0, 3, 6}));
}

TEST(Gltf, WithoutNodesEveryMeshComesUntransformed) {
  const PolygonMesh m = parse_gltf(gltf(kSquareParts, kSquareBuffer), "sq.gltf");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
}

TEST(Gltf, GlbReadsTheBinaryChunk) {
  std::string json = "{\"asset\":{\"version\":\"2.0\"}," + kSquareParts +
                     ",\"buffers\":[{\"byteLength\":" + std::to_string(kSquareBuffer.size()) + "}]}";
  const PolygonMesh m = parse_glb(glb(json, kSquareBuffer), "sq.glb");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(Gltf, ModesSharedAccessorsAndByteIndices) {
  // Five positions; primitives: TRIANGLES without indices over a 3-vertex accessor, a STRIP and a FAN
  // with uint8 indices into the 5-vertex accessor (sharing its vertices), and POINTS (skipped).
  const std::string buffer = bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 2, 2}) +
                             bytes_of(std::vector<uint8_t>{0, 1, 3, 2, 4}) + bytes_of(std::vector<uint8_t>{4, 0, 1, 2});
  const std::string body =
      "\"meshes\":[{\"primitives\":["
      "{\"attributes\":{\"POSITION\":1},\"mode\":4},"
      "{\"attributes\":{\"POSITION\":0},\"indices\":2,\"mode\":5},"
      "{\"attributes\":{\"POSITION\":0},\"indices\":3,\"mode\":6},"
      "{\"attributes\":{\"POSITION\":0},\"mode\":0}]}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":5,\"type\":\"VEC3\"},"
      "{\"bufferView\":0,\"byteOffset\":12,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
      "{\"bufferView\":1,\"componentType\":5121,\"count\":5,\"type\":\"SCALAR\"},"
      "{\"bufferView\":2,\"componentType\":5121,\"count\":4,\"type\":\"SCALAR\"}],"
      "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":60},"
      "{\"buffer\":0,\"byteOffset\":60,\"byteLength\":5},{\"buffer\":0,\"byteOffset\":68,\"byteLength\":4}]";
  const PolygonMesh m = parse_gltf(gltf(body, buffer), "modes.gltf");
  ASSERT_EQ(m.num_vertices(), 8u);  // 3 for the first primitive, 5 shared by the strip and the fan
  EXPECT_EQ(m.positions[0], glm::dvec3(1, 0, 0));
  EXPECT_EQ(m.positions[3], glm::dvec3(0, 0, 0));
  EXPECT_EQ(m.positions[7], glm::dvec3(2, 2, 2));
  // strip 0 1 3 2 4 -> (0 1 3) (3 1 2) (3 2 4); fan 4 0 1 2 -> (4 0 1) (4 1 2); all offset by 3.
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 6, 6, 4, 5, 6, 5, 7, 7, 3, 4, 7, 4, 5}));
}

TEST(Gltf, SparseAccessorsOverrideTheBase) {
  const std::string buffer = bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}) +
                             bytes_of(std::vector<uint16_t>{2}) + bytes_of(std::vector<float>{5, 6, 7});
  const std::string body =
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
      "\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":1,\"componentType\":5123},"
      "\"values\":{\"bufferView\":2}}}],"
      "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":2},"
      "{\"buffer\":0,\"byteOffset\":40,\"byteLength\":12}]";
  const PolygonMesh m = parse_gltf(gltf(body, buffer), "sparse.gltf");
  ASSERT_EQ(m.num_vertices(), 3u);
  EXPECT_EQ(m.positions[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(m.positions[2], glm::dvec3(5, 6, 7));
}

TEST(Gltf, NodeTreesComposeAndTheDefaultSceneChooses) {
  // Node 0 (matrix: translate x+5) has child 1 (rotation 180 degrees about z); node 2 (scale -1 in x)
  // is a root of scene 1 only. Scene 0 is the default.
  const std::string nodes =
      "\"nodes\":[{\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 5,0,0,1],\"children\":[1]},"
      "{\"mesh\":0,\"rotation\":[0,0,1,0]},{\"mesh\":0,\"scale\":[-1,1,1]}],";
  const PolygonMesh m = parse_gltf(
      gltf(nodes + "\"scene\":0,\"scenes\":[{\"nodes\":[0]},{\"nodes\":[2]}]," + kSquareParts, kSquareBuffer),
      "tree.gltf");
  ASSERT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.positions[1], glm::dvec3(4, 0, 0));  // (1,0,0) rotated to (-1,0,0), then x+5
  EXPECT_EQ(m.positions[2], glm::dvec3(4, -1, 0));
  // Without a default scene, every root node (0 and 2) is drawn; node 2 mirrors, so its triangles turn.
  const PolygonMesh all = parse_gltf(
      gltf(nodes + "\"scenes\":[{\"nodes\":[0]},{\"nodes\":[2]}]," + kSquareParts, kSquareBuffer), "tree.gltf");
  ASSERT_EQ(all.num_vertices(), 8u);
  EXPECT_EQ(all.positions[5], glm::dvec3(-1, 0, 0));
  EXPECT_EQ(all.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6}));
}

TEST(Gltf, RefusesHostileAccessorsWithTheObject) {
  const auto square_with = [](std::string parts) {
    return [parts](const std::string& from, const std::string& to) {
      std::string changed = parts;
      const size_t at = changed.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      if (at != std::string::npos) changed.replace(at, from.size(), to);
      return gltf(changed, kSquareBuffer);
    };
  }(kSquareParts);
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"count\":4,", "\"count\":4000000000,"), "h.gltf"),
                    "h.gltf: accessor 0: count 4000000000 is too large");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"count\":4,", "\"count\":5,"), "h.gltf"),
                    "h.gltf: accessor 0: reads bytes 0 + 76, beyond the 64 bytes of bufferView 0");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"count\":6,", "\"count\":7,"), "h.gltf"),
                    "h.gltf: accessor 1: reads bytes 0 + 14, beyond the 12 bytes of bufferView 1");
  EXPECT_FILE_ERROR(
      parse_gltf(square_with("\"byteOffset\":64,\"byteLength\":12", "\"byteOffset\":64,\"byteLength\":13"), "h.gltf"),
      "h.gltf: bufferView 1: bytes 64 + 13 exceed buffer 0 of 76 bytes");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"byteStride\":16", "\"byteStride\":8"), "h.gltf"),
                    "h.gltf: accessor 0: byteStride 8 of bufferView 0 does not fit elements of 12 bytes");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"type\":\"VEC3\"", "\"type\":\"VEC2\""), "h.gltf"),
                    "h.gltf: accessor 0: POSITION must be a float VEC3 accessor");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"componentType\":5123", "\"componentType\":5126"), "h.gltf"),
                    "h.gltf: accessor 1: indices must be an unsigned byte, short or int SCALAR accessor");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"POSITION\":0", "\"NORMAL\":0"), "h.gltf"),
                    "h.gltf: mesh 0 primitive 0: has no POSITION attribute");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"POSITION\":0", "\"POSITION\":7"), "h.gltf"),
                    "h.gltf: mesh 0 primitive 0: refers to accessor 7, which does not exist");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"indices\":1", "\"indices\":1,\"mode\":9"), "h.gltf"),
                    "h.gltf: mesh 0 primitive 0: unknown mode 9");
  EXPECT_FILE_ERROR(parse_gltf(square_with("\"count\":6,", "\"count\":5,"), "h.gltf"),
                    "h.gltf: mesh 0 primitive 0: 5 indices do not form whole triangles");

  // An index past the vertices, and a NaN position.
  std::string bad_index = kSquareBuffer;
  bad_index[64 + 2 * 4] = 4;
  EXPECT_FILE_ERROR(parse_gltf(gltf(kSquareParts, bad_index), "h.gltf"),
                    "h.gltf: accessor 1: index 4 refers to vertex 4, but the POSITION accessor has only 4");
  std::string nan = kSquareBuffer;
  const float not_a_number = std::nanf("");
  std::memcpy(nan.data() + 16 * 2 + 4, &not_a_number, 4);
  EXPECT_FILE_ERROR(parse_gltf(gltf(kSquareParts, nan), "h.gltf"), "h.gltf: accessor 0: position 2 is not finite");
}

TEST(Gltf, RefusesBadNodesAndFiles) {
  const auto with_nodes = [](const std::string& nodes) { return gltf(nodes + "," + kSquareParts, kSquareBuffer); };
  EXPECT_FILE_ERROR(parse_gltf(with_nodes("\"nodes\":[{\"mesh\":0,\"children\":[1]},{\"children\":[0]}],"
                                          "\"scene\":0,\"scenes\":[{\"nodes\":[0]}]"),
                               "n.gltf"),
                    "n.gltf: node 0: is reached twice; glTF nodes must form a tree");
  EXPECT_FILE_ERROR(parse_gltf(with_nodes("\"nodes\":[{\"mesh\":3}]"), "n.gltf"),
                    "n.gltf: node 0: refers to mesh 3, which does not exist");
  EXPECT_FILE_ERROR(parse_gltf(with_nodes("\"nodes\":[{\"mesh\":0,\"rotation\":[0,0,0]}]"), "n.gltf"),
                    "n.gltf: node 0: rotation has 3 numbers, expected 4");
  EXPECT_FILE_ERROR(parse_gltf(with_nodes("\"nodes\":[{\"mesh\":0,\"rotation\":[0,0,0,0]}]"), "n.gltf"),
                    "n.gltf: node 0: rotation is not a unit quaternion");
  EXPECT_FILE_ERROR(parse_gltf(with_nodes("\"nodes\":[{\"mesh\":0,\"scale\":[1e38,1e38,1e38]},"
                                          "{\"mesh\":0,\"children\":[0],\"scale\":[1e300,1,1]}]"),
                               "n.gltf"),
                    "n.gltf: mesh 0 primitive 0: the transform of node 0 moves vertex 0 to a non-finite position");
  EXPECT_FILE_ERROR(parse_gltf("", "e.gltf"), "e.gltf: file is empty");
  EXPECT_FILE_ERROR(parse_gltf("{\"asset\":", "e.gltf"), "e.gltf: ");
  EXPECT_FILE_ERROR(parse_gltf(std::string("\x00\xff\x13garbage", 10), "e.gltf"), "e.gltf: ");
  EXPECT_FILE_ERROR(parse_glb("glTF\x02\0\0\0", "e.glb"), "e.glb: ");
  const std::string whole = format_glb(make_cube(), "c.glb");
  EXPECT_FILE_ERROR(parse_glb(whole.substr(0, whole.size() / 2), "e.glb"), "e.glb: ");  // truncated
  EXPECT_FILE_ERROR(parse_glb(whole.substr(0, 30), "e.glb"), "e.glb: ");
  EXPECT_FILE_ERROR(parse_glb("not a glb at all, just words", "e.glb"), "e.glb: ");
  EXPECT_FILE_ERROR(parse_gltf("{\"asset\":{\"version\":\"2.0\"}}", "e.gltf"), "e.gltf: file holds no triangles");
  // An external buffer is never read when parsing from memory.
  std::string external = gltf(kSquareParts, kSquareBuffer);
  const size_t uri = external.find("data:");
  external.replace(uri, external.find('"', uri) - uri, "square.bin");
  const std::string message = error_of([&] { parse_gltf(external, "x.gltf"); });
  EXPECT_EQ(message.rfind("x.gltf: ", 0), 0u) << message;
  EXPECT_NE(message.find("square.bin"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot be read when parsing from memory"), std::string::npos) << message;
}

TEST(Gltf, ReadsExternalBuffersBesideTheFile) {
  const auto dir = testing::scratch_dir();
  std::string text = gltf(kSquareParts, kSquareBuffer);
  const size_t uri = text.find("data:");
  text.replace(uri, text.find('"', uri) - uri, "square.bin");
  write_file(dir / "square.gltf", text);
  EXPECT_FILE_ERROR(read_gltf(dir / "square.gltf"), "square.gltf: ", "square.bin");
  // A FIFO in its place is refused without waiting for a writer.
  ASSERT_EQ(mkfifo((dir / "square.bin").c_str(), 0600), 0);
  EXPECT_FILE_ERROR(read_gltf(dir / "square.gltf"), "square.gltf: ", "square.bin: cannot open: not a regular file");
  std::filesystem::remove(dir / "square.bin");
  write_file(dir / "square.bin", kSquareBuffer);
  const PolygonMesh m = read_gltf(dir / "square.gltf");
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
}

// What a glTF round trip must give: positions rounded to float, faces fan-triangulated.
PolygonMesh as_stored_in_gltf(const PolygonMesh& m) {
  PolygonMesh out;
  for (const glm::dvec3& p : m.positions) {
    out.add_vertex(glm::dvec3(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)));
  }
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const auto face = m.face(f);
    for (size_t i = 1; i + 1 < face.size(); ++i) out.add_face({face[0], face[i], face[i + 1]});
  }
  return out;
}

TEST(Gltf, WritersRoundTripPrimitives) {
  for (const PolygonMesh& m :
       {make_tetrahedron(), make_cube(), make_cube_quads(), make_icosahedron(), make_torus(6, 5), make_grid(3, 2)}) {
    const PolygonMesh expected = as_stored_in_gltf(m);
    testing::expect_same_mesh(parse_gltf(format_gltf(m, "m.gltf"), "m.gltf"), expected);
    testing::expect_same_mesh(parse_glb(format_glb(m, "m.glb"), "m.glb"), expected);
  }
  // Exactly representable coordinates survive unchanged, quads become two triangles each.
  const PolygonMesh cube = parse_gltf(format_gltf(make_cube_quads(), "c.gltf"), "c.gltf");
  testing::expect_same_mesh(PolygonMesh{cube.positions, {}, {0}}, PolygonMesh{make_cube_quads().positions, {}, {0}});
  EXPECT_EQ(cube.num_faces(), 12u);
}

TEST(Gltf, WrittenGlbIsWellFormed) {
  const std::string bytes = format_glb(make_cube(), "c.glb");
  ASSERT_GE(bytes.size(), 28u);
  uint32_t version, length, json_length;
  std::memcpy(&version, bytes.data() + 4, 4);
  std::memcpy(&length, bytes.data() + 8, 4);
  std::memcpy(&json_length, bytes.data() + 12, 4);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(version, 2u);
  EXPECT_EQ(length, bytes.size());
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
  uint32_t bin_length;
  std::memcpy(&bin_length, bytes.data() + 20 + json_length, 4);
  EXPECT_EQ(bin_length % 4, 0u);
  EXPECT_EQ(bytes.substr(24 + json_length, 4), std::string("BIN\0", 4));
  EXPECT_EQ(20u + json_length + 8u + bin_length, bytes.size());
  // A written .gltf is one self-contained file.
  EXPECT_NE(format_gltf(make_cube(), "c.gltf").find("data:application/octet-stream;base64,"), std::string::npos);
}

TEST(Gltf, WritersRefuseWhatCannotBeStored) {
  PolygonMesh big = make_tetrahedron();
  big.positions[1].x = 1e39;
  EXPECT_FILE_ERROR(format_gltf(big, "b.gltf"), "b.gltf: vertex 1: coordinate does not fit a 32-bit float");
  PolygonMesh bad = make_tetrahedron();
  bad.indices[0] = 77;
  EXPECT_FILE_ERROR(format_glb(bad, "b.glb"), "b.glb: face 0: refers to vertex 77");
}

TEST(Gltf, WritesAndReadsFiles) {
  const auto dir = testing::scratch_dir();
  write_gltf(dir / "t.gltf", make_torus(4, 3));
  write_glb(dir / "t.glb", make_torus(4, 3));
  const PolygonMesh expected = as_stored_in_gltf(make_torus(4, 3));
  testing::expect_same_mesh(read_gltf(dir / "t.gltf"), expected);
  testing::expect_same_mesh(read_gltf(dir / "t.glb"), expected);
}

}  // namespace
}  // namespace meshedit
