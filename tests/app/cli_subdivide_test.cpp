// `meshedit subdivide --scheme ...` on the shell: Catmull-Clark and linear subdivision write the refined mesh with
// the counts and positions the schemes give, and a wrong scheme or a Loop-only option is a one-line usage error.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "app/cli_test_support.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

using testing::CommandRun;

CommandRun meshedit(const std::vector<std::string>& args) { return testing::run_meshedit(args, "cli-subdivide"); }

// The cube [-9, 9]^3 of 6 quads: one Catmull-Clark level puts every corner at +-5 (5/9 of it), 26 vertices and
// 24 quads; a second level gives 98 vertices and 96 quads.
TEST(CliSubdivide, CatmullClarkOfACubeOfQuads) {
  const fs::path dir = testing::scratch_dir();
  PolygonMesh cube = make_cube_quads();
  for (glm::dvec3& p : cube.positions) p *= 18.0;
  save_mesh(dir / "cube.obj", cube);
  const CommandRun one = meshedit({"subdivide", (dir / "cube.obj").string(), "-n", "1", "--scheme", "catmull-clark",
                                   "-o", (dir / "cc1.obj").string()});
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_NE(one.out.find("catmull-clark"), std::string::npos) << one.out;
  const PolygonMesh refined = load_mesh(dir / "cc1.obj");
  ASSERT_EQ(refined.num_vertices(), 26u);
  ASSERT_EQ(refined.num_faces(), 24u);
  for (size_t f = 0; f < refined.num_faces(); ++f) EXPECT_EQ(refined.face(f).size(), 4u);
  for (size_t i = 0; i < 8; ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(std::abs(refined.positions[i][k]), 5.0) << "v" << i;
  }
  const CommandRun two = meshedit({"subdivide", (dir / "cube.obj").string(), "-n", "2", "--scheme", "catmull-clark",
                                   "-o", (dir / "cc2.obj").string()});
  ASSERT_EQ(two.status, 0) << two.err;
  const HalfedgeMesh twice = build_halfedge_mesh(load_mesh(dir / "cc2.obj"));
  EXPECT_EQ(twice.num_vertices(), 98u);
  EXPECT_EQ(twice.num_faces(), 96u);
}

// Linear subdivision of the icosahedron: 12 + 30 vertices, 80 triangles, the original vertices where they were.
TEST(CliSubdivide, LinearKeepsTheOriginalVertices) {
  const fs::path dir = testing::scratch_dir();
  save_mesh(dir / "ico.obj", make_icosahedron());
  const PolygonMesh original = load_mesh(dir / "ico.obj");
  const CommandRun run = meshedit(
      {"subdivide", (dir / "ico.obj").string(), "-n", "1", "--scheme", "linear", "-o", (dir / "lin.obj").string()});
  ASSERT_EQ(run.status, 0) << run.err;
  const PolygonMesh refined = load_mesh(dir / "lin.obj");
  ASSERT_EQ(refined.num_vertices(), 42u);
  EXPECT_EQ(refined.num_faces(), 80u);
  for (size_t i = 0; i < 12; ++i) EXPECT_EQ(refined.positions[i], original.positions[i]) << "v" << i;
}

TEST(CliSubdivide, WrongSchemeOrLoopOnlyWeightsAreUsageErrors) {
  const fs::path dir = testing::scratch_dir();
  save_mesh(dir / "cube.obj", make_cube_quads());
  const CommandRun bad = meshedit(
      {"subdivide", (dir / "cube.obj").string(), "-n", "1", "--scheme", "butterfly", "-o", (dir / "o.obj").string()});
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("--scheme must be \"loop\", \"catmull-clark\" or \"linear\", not 'butterfly'"),
            std::string::npos)
      << bad.err;
  const CommandRun weights = meshedit({"subdivide", (dir / "cube.obj").string(), "-n", "1", "--scheme", "linear",
                                       "--weights", "loop", "-o", (dir / "o.obj").string()});
  EXPECT_NE(weights.status, 0);
  EXPECT_NE(weights.err.find("--weights is for --scheme loop only"), std::string::npos) << weights.err;
  // The default is still Loop, which refuses quads.
  const CommandRun loop =
      meshedit({"subdivide", (dir / "cube.obj").string(), "-n", "1", "-o", (dir / "o.obj").string()});
  EXPECT_NE(loop.status, 0);
  EXPECT_NE(loop.err.find("Loop subdivision needs triangles"), std::string::npos) << loop.err;
}

}  // namespace
}  // namespace meshedit
