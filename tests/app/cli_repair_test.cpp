// The real `meshedit` binary's triangulate and repair commands, and what info says a file would need repaired.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/cli_test_support.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

using testing::CommandRun;

CommandRun meshedit(const std::vector<std::string>& args) { return testing::run_meshedit(args, "cli-repair"); }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CliTriangulate, QuadCubeBecomesTwelveTrianglesThatSubdivide) {
  const fs::path dir = testing::scratch_dir();
  save_mesh(dir / "cube.obj", make_cube_quads());
  const CommandRun refused =
      meshedit({"subdivide", (dir / "cube.obj").string(), "-n", "1", "-o", (dir / "s.obj").string()});
  EXPECT_NE(refused.status, 0);
  EXPECT_TRUE(contains(refused.err, "meshedit triangulate IN -o OUT")) << refused.err;

  const CommandRun run = meshedit({"triangulate", (dir / "cube.obj").string(), "-o", (dir / "tri.obj").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(contains(run.out, "6 polygons split into 12 triangles")) << run.out;
  const PolygonMesh tris = load_mesh(dir / "tri.obj");
  ASSERT_EQ(tris.num_faces(), 12u);
  EXPECT_EQ(tris.positions, make_cube_quads().positions);
  for (size_t f = 0; f < tris.num_faces(); ++f) EXPECT_EQ(tris.face(f).size(), 3u);
  EXPECT_TRUE(validate(build_halfedge_mesh(tris)).ok());
  const CommandRun subdivided =
      meshedit({"subdivide", (dir / "tri.obj").string(), "-n", "1", "-o", (dir / "s.obj").string()});
  EXPECT_EQ(subdivided.status, 0) << subdivided.err;
  EXPECT_EQ(load_mesh(dir / "s.obj").num_faces(), 48u);
}

TEST(CliTriangulate, NeedsAnOutput) {
  const CommandRun run = meshedit({"triangulate", "x.obj"});
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(contains(run.err, "triangulate needs -o OUT")) << run.err;
}

// Two triangles touching at vertex 1 (a bow-tie), vertex 0 unused, and face 2 repeating face 0.
constexpr const char* kBowTieObj =
    "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\n"
    "f 2 3 4\nf 2 5 6\nf 3 4 2\n";

TEST(CliRepair, ListsEveryChangeAndWritesAMeshThatBuilds) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "bowtie.obj") << kBowTieObj;
  const CommandRun run = meshedit({"repair", (dir / "bowtie.obj").string(), "-o", (dir / "fixed.obj").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(contains(run.out, "  face 2 repeated face 0: dropped\n")) << run.out;
  EXPECT_TRUE(contains(run.out, "  vertex 1 was a bow-tie: split into 1 and new vertex 5 (face 1 moved)\n")) << run.out;
  EXPECT_TRUE(contains(run.out, "  vertex 0 was used by no face: dropped\n")) << run.out;
  EXPECT_TRUE(contains(run.out, "repaired: 1 bow-tie vertex split, 1 repeated face dropped, 1 unused vertex dropped"))
      << run.out;
  const PolygonMesh fixed = load_mesh(dir / "fixed.obj");
  ASSERT_EQ(fixed.num_vertices(), 6u);
  EXPECT_EQ(fixed.positions[0], glm::dvec3(0, 0, 0));
  EXPECT_EQ(fixed.positions[5], glm::dvec3(0, 0, 0));
  ASSERT_EQ(fixed.num_faces(), 2u);
  EXPECT_EQ(std::vector<uint32_t>(fixed.face(0).begin(), fixed.face(0).end()), (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(std::vector<uint32_t>(fixed.face(1).begin(), fixed.face(1).end()), (std::vector<uint32_t>{5, 3, 4}));
  EXPECT_TRUE(validate(build_halfedge_mesh(fixed)).ok());
}

TEST(CliRepair, AGoodFileHasNothingToRepair) {
  const fs::path dir = testing::scratch_dir();
  save_mesh(dir / "ico.obj", make_icosahedron());
  const CommandRun run = meshedit({"repair", (dir / "ico.obj").string(), "-o", (dir / "same.obj").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(contains(run.out, "nothing to repair")) << run.out;
  const PolygonMesh same = load_mesh(dir / "same.obj");
  EXPECT_EQ(same.indices, make_icosahedron().indices);
  const CommandRun info = meshedit({"info", (dir / "ico.obj").string()});
  EXPECT_FALSE(contains(info.out, "repair")) << info.out;
}

TEST(CliInfo, SaysWhatRepairWouldChangeAndStillRefuses) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "bowtie.obj") << kBowTieObj;
  const CommandRun run = meshedit({"info", (dir / "bowtie.obj").string()});
  EXPECT_EQ(run.status, 1);
  EXPECT_TRUE(contains(run.out, "meshedit repair would: repaired: 1 bow-tie vertex split")) << run.out;
  EXPECT_TRUE(contains(run.out, "    vertex 1 was a bow-tie")) << run.out;
  EXPECT_EQ(run.err.rfind("meshedit: ", 0), 0u) << run.err;
  EXPECT_TRUE(contains(run.err, "bowtie.obj")) << run.err;
}

TEST(CliInfo, ABuildableFileWithUnusedVerticesMentionsTheRepair) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "extra.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n";
  const CommandRun run = meshedit({"info", (dir / "extra.obj").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(contains(run.out, "meshedit repair would: repaired: 1 unused vertex dropped")) << run.out;
  EXPECT_TRUE(contains(run.out, "    vertex 3 was used by no face: dropped")) << run.out;
  const CommandRun json = meshedit({"info", (dir / "extra.obj").string(), "--json"});
  ASSERT_EQ(json.status, 0) << json.err;
  const nlohmann::json info = nlohmann::json::parse(json.out);
  EXPECT_EQ(info["repair"]["summary"], "repaired: 1 unused vertex dropped");
  EXPECT_EQ(info["repair"]["changes"], nlohmann::json::array({"vertex 3 was used by no face: dropped"}));
  EXPECT_EQ(info["faces"], 1);
}

}  // namespace
}  // namespace meshedit
