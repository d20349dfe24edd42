// In-process fuzzing of every reader: thousands of deterministic mutations (fixed seeds) of valid files,
// hand-written and, when present, the course files. Each parse must either succeed or throw FileError:
// no other exception, no crash, no hang, and no single allocation far beyond the input's size.
// Deeper runs: MESHEDIT_FUZZ_SCALE=20 multiplies every iteration count, MESHEDIT_FUZZ_SEED=n shifts every
// seed (best in a -fsanitize=address,undefined build).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>
#include <string>
#include <vector>

#include "binary_builder.h"
#include "core/primitives.h"
#include "fuzz_mutator.h"
#include "gltf_test_files.h"
#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "io/dae_reader.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/gltf_io.h"
#include "io/obj_io.h"
#include "io/off_io.h"
#include "io/ply_io.h"
#include "io/stl_io.h"
#include "support/test_support.h"

// The largest single allocation since the last reset, for the "never allocate absurdly" check. This
// replaces the global operator new of the io_tests binary; it only records sizes and calls malloc.
namespace {
std::atomic<size_t> g_largest_allocation{0};
}

void* operator new(std::size_t size) {
  size_t seen = g_largest_allocation.load(std::memory_order_relaxed);
  while (size > seen && !g_largest_allocation.compare_exchange_weak(seen, size, std::memory_order_relaxed)) {
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// GCC cannot see that the replaced operator new above uses malloc, so it warns about free() here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace meshedit {
namespace {

using testing::Mutator;

using Parse = std::function<void(const std::string&)>;
using Mutate = std::function<std::string(Mutator&, const std::string&)>;

std::string plain_mutation(Mutator& m, const std::string& text) { return m.mutate(text); }

uint64_t from_environment(const char* name, uint64_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtoull(value, nullptr, 10) : fallback;
}

// Runs `iterations` mutations of the seeds through `parse`.
void fuzz(const std::string& format, const std::vector<std::string>& seeds, size_t iterations, uint64_t seed,
          const Parse& parse, const Mutate& mutate = plain_mutation) {
  ASSERT_FALSE(seeds.empty());
  for (size_t s = 0; s < seeds.size(); ++s) {
    EXPECT_NO_THROW(parse(seeds[s])) << format << " seed file " << s << " must parse before mutation";
  }
  iterations *= from_environment("MESHEDIT_FUZZ_SCALE", 1);
  seed += from_environment("MESHEDIT_FUZZ_SEED", 0);
  Mutator mutator(seed);
  size_t parsed = 0, refused = 0;
  for (size_t i = 0; i < iterations; ++i) {
    const std::string input = mutate(mutator, seeds[i % seeds.size()]);
    g_largest_allocation = 0;
    try {
      parse(input);
      ++parsed;
    } catch (const FileError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << format << " case " << i << " (seed " << seed << ") threw a non-FileError: " << e.what();
    } catch (...) {
      ADD_FAILURE() << format << " case " << i << " (seed " << seed << ") threw a non-exception";
    }
    const size_t limit = (size_t(32) << 20) + 32 * input.size();
    EXPECT_LE(g_largest_allocation.load(), limit) << format << " case " << i << " allocated too much at once";
  }
  std::printf("%s: %zu parsed, %zu refused\n", format.c_str(), parsed, refused);
  // Both outcomes must occur, or the mutations prove nothing.
  EXPECT_GT(parsed, 0u) << format;
  EXPECT_GT(refused, iterations / 10) << format;
}

std::vector<std::string> course_files(const char* folder, std::initializer_list<const char*> names) {
  std::vector<std::string> out;
  if (const auto dir = meshedit::testing::course_data_dir()) {
    for (const char* name : names) {
      const auto path = *dir / folder / name;
      if (std::filesystem::exists(path)) out.push_back(read_file(path));
    }
  }
  return out;
}

TEST(Fuzz, Bzc) {
  std::vector<std::string> seeds = {"4\n0.200 0.350   0.300 0.600   0.800 0.750   0.900 0.450\n", "1 -5e-3 +7"};
  for (auto& s : course_files("bzc", {"curve1.bzc", "curve2.bzc"})) seeds.push_back(std::move(s));
  fuzz("bzc", seeds, 6000, 1, [](const std::string& t) { parse_bzc(t, "f.bzc"); });
}

TEST(Fuzz, Bez) {
  std::string patch;
  for (int i = 0; i < 16; ++i) patch += std::to_string(i % 4) + " " + std::to_string(i / 4) + " 0.5\n";
  std::vector<std::string> seeds = {"1\n" + patch, "2 " + patch + patch};
  for (auto& s : course_files("bez", {"teapot.bez", "wavy_cube.bez"})) seeds.push_back(std::move(s));
  fuzz("bez", seeds, 5000, 2, [](const std::string& t) { parse_bez(t, "f.bez"); });
}

TEST(Fuzz, Obj) {
  const std::vector<std::string> seeds = {
      format_obj(make_torus(4, 3), "t.obj"), format_obj(make_cube_quads(), "c.obj"),
      "# corners\nv 0 0 0\nv 1 0 0 1\nv 1 1 0\nv 0 1 0 0.5 0.5 0.5\nvt 0 0\nvn 0 0 1\n"
      "g g\nf 1/1/1 2/1/1 3//1 4/1\nf -4 -2 \\\n -1\ns 1\nusemtl m\n",
      // What other exporters write: a byte order mark, nan colours, empty index parts, faces of fewer than 3 corners.
      "\xEF\xBB\xBFv 0 0 0 nan 0 1\nv 1 0 0 0.5 -nan inf\nv 0 1 0\nv 0 0 1 1 1 1\n"
      "f 1// 2/1/ 3/\nf 1 2\nf\nf 1 4 3 3\nf 2// 4/1/ 3//1\n"};
  fuzz("obj", seeds, 8000, 3, [](const std::string& t) { parse_obj(t, "f.obj"); });
}

const std::string kDaeSeed =
    "<?xml version=\"1.0\"?>\n<COLLADA version=\"1.4.1\">\n<library_geometries>\n"
    "<geometry id=\"G\"><mesh>\n<source id=\"G-pos\">\n<float_array count=\"15\">0 0 0 1 0 0 1 1 0 0 1 0 0.5 0.5 1"
    "</float_array>\n<technique_common><accessor source=\"#a\" count=\"5\" stride=\"3\"/></technique_common>\n"
    "</source>\n<vertices id=\"G-vtx\"><input semantic=\"POSITION\" source=\"#G-pos\"/></vertices>\n"
    "<triangles count=\"2\">\n<input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/>\n"
    "<input semantic=\"NORMAL\" source=\"#n\" offset=\"1\"/>\n<p>0 0 2 0 1 0 0 0 3 0 2 0</p>\n</triangles>\n"
    "<polylist count=\"2\">\n<input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/>\n<vcount>3 3</vcount>\n"
    "<p>0 1 4 1 2 4</p>\n</polylist>\n"
    "<polylist count=\"3\">\n<input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/>\n<vcount>2 0 3</vcount>\n"
    "<p>0 1 2 3 4</p>\n</polylist>\n"
    "<polygons count=\"1\"><input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/><p>1 3</p></polygons>\n"
    "<tristrips count=\"1\"><input semantic=\"VERTEX\" source=\"#G-vtx\" offset=\"0\"/><p>2 3 4 0</p></tristrips>\n"
    "</mesh></geometry>\n</library_geometries>\n<library_visual_scenes>\n<visual_scene id=\"S\">\n"
    "<node><matrix>2 0 0 1 0 2 0 0 0 0 2 0 0 0 0 1</matrix>\n<instance_geometry url=\"#G\"/>\n"
    "<node><translate>0 0 1</translate><rotate>0 1 0 30</rotate><scale>1 -1 1</scale>\n"
    "<instance_geometry url=\"#G\"/></node>\n</node>\n</visual_scene>\n</library_visual_scenes>\n"
    "<scene><instance_visual_scene url=\"#S\"/></scene>\n</COLLADA>\n";

TEST(Fuzz, Dae) {
  std::vector<std::string> seeds = {kDaeSeed};
  for (auto& s : course_files("dae", {"cube.dae"})) seeds.push_back(std::move(s));
  fuzz("dae", seeds, 6000, 4, [](const std::string& t) { parse_dae(t, "f.dae"); });
}

TEST(Fuzz, DaeCourseTeapot) {
  const std::vector<std::string> seeds = course_files("dae", {"teapot.dae"});
  if (seeds.empty()) GTEST_SKIP() << "course files not found";
  fuzz("teapot.dae", seeds, 200, 5, [](const std::string& t) { parse_dae(t, "teapot.dae"); });
}

std::vector<std::string> gltf_seeds() {
  using meshedit::testing::gltf;
  using meshedit::testing::kSquareBuffer;
  using meshedit::testing::kSquareParts;
  const std::string sparse_buffer = meshedit::testing::bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}) +
                                    meshedit::testing::bytes_of(std::vector<uint16_t>{2}) +
                                    meshedit::testing::bytes_of(std::vector<float>{5, 6, 7});
  return {format_gltf(make_cube_quads(), "c.gltf"),
          gltf("\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"children\":[1],\"translation\":[1,2,3]},"
               "{\"mesh\":0,\"rotation\":[0,0,1,0],\"scale\":[2,2,2]}]," +
                   kSquareParts,
               kSquareBuffer),
          gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":5}]}],"
               "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
               "\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":1,\"componentType\":5123},\"values\":{"
               "\"bufferView\":2}}}],"
               "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":2},"
               "{\"buffer\":0,\"byteOffset\":40,\"byteLength\":12}]",
               sparse_buffer)};
}

TEST(Fuzz, Gltf) {
  fuzz("gltf", gltf_seeds(), 6000, 6, [](const std::string& t) { parse_gltf(t, "f.gltf"); });
}

// GLB: half the time mutate the raw bytes (headers, chunk lengths), half the time mutate the JSON or
// the binary chunk and rebuild valid chunk headers, so the mutations reach the accessors.
std::string mutate_glb(Mutator& m, const std::string& bytes) {
  if (m.below(2) == 0 || bytes.size() < 28) return m.mutate(bytes);
  uint32_t json_length = 0, bin_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  std::string json = bytes.substr(20, json_length);
  std::string bin;
  if (20 + json_length + 8 <= bytes.size()) {
    std::memcpy(&bin_length, bytes.data() + 20 + json_length, 4);
    bin = bytes.substr(28 + json_length, bin_length);
  }
  if (m.below(3) == 0) {
    for (size_t flips = 1 + m.below(4); flips > 0 && !bin.empty(); --flips) {
      bin[m.below(bin.size())] ^= static_cast<char>(1u << m.below(8));
    }
  } else {
    json = m.mutate(json);
  }
  return meshedit::testing::glb(json, bin);
}

TEST(Fuzz, Glb) {
  std::vector<std::string> seeds = {format_glb(make_torus(3, 3), "t.glb")};
  seeds.push_back(meshedit::testing::glb(
      "{\"asset\":{\"version\":\"2.0\"}," + meshedit::testing::kSquareParts + ",\"buffers\":[{\"byteLength\":76}]}",
      meshedit::testing::kSquareBuffer));
  fuzz(
      "glb", seeds, 6000, 7, [](const std::string& t) { parse_glb(t, "f.glb"); }, mutate_glb);
}

// Binary formats: a third of the time the raw bytes are mutated (headers, counts, truncation), otherwise
// only bytes past the text header flip, so the file keeps its size and layout and the mutations reach the
// values: counts, indices, NaN and infinite coordinates.
std::string mutate_binary_body(Mutator& m, const std::string& bytes, size_t body_start) {
  if (m.below(3) == 0 || bytes.size() <= body_start) return m.mutate(bytes);
  std::string out = bytes;
  for (size_t flips = 1 + m.below(4); flips > 0; --flips) {
    const size_t at = body_start + m.below(out.size() - body_start);
    out[at] = m.below(4) == 0 ? static_cast<char>(0xff) : static_cast<char>(out[at] ^ (1u << m.below(8)));
  }
  return out;
}

std::string mutate_ply(Mutator& m, const std::string& bytes) {
  const size_t end = bytes.find("end_header\n");
  if (end == std::string::npos || bytes.find("format ascii") != std::string::npos) return m.mutate(bytes);
  if (m.below(3) == 0) return m.mutate(bytes.substr(0, end)) + bytes.substr(end);  // the header only
  return mutate_binary_body(m, bytes, end + 11);
}

std::vector<std::string> ply_seeds() {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string ascii =
      "ply\nformat ascii 1.0\ncomment by hand\nelement vertex 4\n" + xyz +
      "property uchar red\nproperty list uchar float uv\nelement face 2\nproperty list uchar int vertex_indices\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "0 0 0 255 0\n1 0 0 0 2 0.5 0.5\n1 1 0 7 0\n0 1 0.5 9 0\n3 0 1 2\n4 0 2 3 1\n0 1\n";
  testing::BinaryBuilder big(true, "ply\nformat binary_big_endian 1.0\nelement vertex 3\n" + xyz +
                                       "property float confidence\nelement face 1\n"
                                       "property list uchar int vertex_indices\nend_header\n");
  big.f32(0).f32(0).f32(0).f32(1).f32(1).f32(0).f32(0).f32(1).f32(0).f32(1).f32(0).f32(1);
  big.u8(3).i32(0).i32(1).i32(2);
  // Triangle strips (-1 between strips, degenerate joins) beside faces of fewer than 3 corners, and the strips alone
  // in the big-endian layout of the old Stanford scans.
  const std::string strips =
      "ply\nformat ascii 1.0\nelement vertex 6\n" + xyz +
      "element face 3\nproperty list uchar int vertex_indices\nelement tristrips 1\n"
      "property list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n"
      "1 4\n0\n3 0 0 1\n12 0 1 3 4 -1 1 2 4 5 5 2 2\n";
  testing::BinaryBuilder big_strips(true,
                                    "ply\nformat binary_big_endian 1.0\nelement vertex 4\n" + xyz +
                                        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n");
  for (int i = 0; i < 12; ++i) big_strips.f32(float((i * 7) % 3));
  big_strips.i32(7).i32(0).i32(1).i32(2).i32(-1).i32(1).i32(2).i32(3);
  return {ascii, big.bytes(), format_ply(make_torus(4, 3), "t.ply"), strips, big_strips.bytes()};
}

TEST(Fuzz, Ply) {
  fuzz(
      "ply", ply_seeds(), 8000, 8, [](const std::string& t) { parse_ply(t, "f.ply"); }, mutate_ply);
}

std::string mutate_stl(Mutator& m, const std::string& bytes) {
  if (bytes.compare(0, 5, "solid") == 0) return m.mutate(bytes);
  return mutate_binary_body(m, bytes, 80);
}

TEST(Fuzz, Stl) {
  const std::string ascii =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 1 0\n  vertex 0 1 1e-3\n endloop\nendfacet\n"
      "endsolid s\n";
  const std::vector<std::string> seeds = {ascii, format_stl(make_cube_quads(), "c.stl"),
                                          format_stl(make_icosahedron(), "i.stl")};
  fuzz(
      "stl", seeds, 8000, 9, [](const std::string& t) { parse_stl(t, "f.stl"); }, mutate_stl);
}

TEST(Fuzz, Off) {
  std::vector<std::string> seeds = {
      "OFF\n# pyramid\n5 5 8\n0 0 0\n1 0 0 # x\n1 1 0\n0 1 0\n0.5 0.5 1\n4 3 2 1 0\n3 0 1 4 255 0 0\n"
      "3 1 2 4\n3 2 3 4 0.5 0.5 0.5 1\n3 3 0 4\n",
      "COFF 3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n",
      "OFF\n3 4 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1 255 0 0\n0\n4 1 1 0 0\n"};
  // A ModelNet-style file: the counts glued to the keyword, a larger mesh.
  const PolygonMesh torus = make_torus(4, 3);
  std::string modelnet =
      "OFF" + std::to_string(torus.num_vertices()) + " " + std::to_string(torus.num_faces()) + " 0\n";
  for (const glm::dvec3& p : torus.positions) {
    modelnet += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  for (size_t f = 0; f < torus.num_faces(); ++f) {
    modelnet += std::to_string(torus.face(f).size());
    for (uint32_t v : torus.face(f)) modelnet += " " + std::to_string(v);
    modelnet += "\n";
  }
  seeds.push_back(modelnet);
  fuzz("off", seeds, 8000, 10, [](const std::string& t) { parse_off(t, "f.off"); });
}

}  // namespace
}  // namespace meshedit
