// The real CS184 course files (../shared/data/cs184; skipped when absent): every file opens, counts
// match the published table (research/cs184.md §3.4), every .dae builds a half-edge mesh.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "core/halfedge_mesh.h"
#include "core/mesh_build.h"
#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "io/dae_reader.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(CourseFiles, EveryFileOpens) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  size_t opened = 0;
  for (const char* folder : {"dae", "bez", "bzc"}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir / folder)) {
      if (!entry.is_regular_file() || entry.path().filename().string()[0] == '.') continue;
      SCOPED_TRACE(entry.path().string());
      const LoadedFile loaded = load_file(entry.path());
      EXPECT_TRUE(loaded.mesh.num_faces() > 0 || !loaded.patches.empty() || !loaded.curve.control_points.empty());
      ++opened;
    }
  }
  EXPECT_GE(opened, 12u);
}

TEST(CourseFiles, DaeCountsMatchTheTableAndEveryMeshBuilds) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  const std::map<std::string, std::pair<size_t, size_t>> table = {
      {"teapot.dae", {1232, 2464}}, {"beetle.dae", {4063, 7558}},  {"cow.dae", {2930, 5856}},
      {"bean.dae", {812, 1620}},    {"peter.dae", {20013, 40018}}, {"quadball.dae", {386, 768}},
      {"weird.dae", {4650, 9296}},  {"cube.dae", {8, 12}}};
  for (const auto& [name, counts] : table) {
    SCOPED_TRACE(name);
    const PolygonMesh polygons = read_dae(dir / "dae" / name);
    EXPECT_EQ(polygons.num_vertices(), counts.first);
    EXPECT_EQ(polygons.num_faces(), counts.second);
    EXPECT_EQ(polygons.indices.size(), 3 * counts.second);  // all triangles
    BuildReport report;
    const HalfedgeMesh mesh = build_halfedge_mesh(polygons, &report);
    EXPECT_EQ(mesh.num_vertices(), counts.first);
    EXPECT_EQ(mesh.num_faces(), counts.second);
    EXPECT_EQ(report.unused_vertices, 0u);
    if (name == "beetle.dae") {
      EXPECT_GT(mesh.num_boundaries(), 0u);
    } else {
      EXPECT_EQ(mesh.num_boundaries(), 0u);
    }
  }
}

TEST(CourseFiles, TeapotDaeStartsWithTheFilesFirstVertexAndTriangle) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  const PolygonMesh m = read_dae(dir / "dae" / "teapot.dae");
  // The polylist's <p> begins "33 0 14 1 23 2": VERTEX is offset 0 of 2 inputs.
  ASSERT_GE(m.num_faces(), 1u);
  EXPECT_EQ(std::vector<uint32_t>(m.face(0).begin(), m.face(0).end()), (std::vector<uint32_t>{33, 14, 23}));
}

TEST(CourseFiles, CubeDaeHasItsScaleTwoMatrixApplied) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  const PolygonMesh m = read_dae(dir / "dae" / "cube.dae");
  ASSERT_EQ(m.num_vertices(), 8u);
  // File vertex 0 is (1, 1, -1); the node matrix is diag(1.999999, 2, 2).
  EXPECT_EQ(m.positions[0], glm::dvec3(1.999999, 2, -2));
  // File vertex 2 is (-1, -0.9999998, -1).
  EXPECT_EQ(m.positions[2], glm::dvec3(-1.999999, 2 * -0.9999998, -2));
  EXPECT_EQ(std::vector<uint32_t>(m.face(0).begin(), m.face(0).end()), (std::vector<uint32_t>{0, 1, 2}));
}

TEST(CourseFiles, PatchesAndCurves) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  const auto teapot = read_bez(dir / "bez" / "teapot.bez");
  ASSERT_EQ(teapot.size(), 32u);
  EXPECT_EQ(teapot[0].at(0, 0), glm::dvec3(1.4, 0.0, 2.4));
  EXPECT_EQ(teapot[0].at(0, 1), glm::dvec3(1.4, -0.784, 2.4));
  EXPECT_EQ(teapot[0].at(1, 0), glm::dvec3(1.337, 0.0, 2.531));
  EXPECT_EQ(read_bez(dir / "bez" / "wavy_cube.bez").size(), 6u);

  const BezierCurve curve1 = read_bzc(dir / "bzc" / "curve1.bzc");
  ASSERT_EQ(curve1.control_points.size(), 4u);
  EXPECT_EQ(curve1.control_points[0], glm::dvec2(0.2, 0.35));
  EXPECT_EQ(curve1.control_points[3], glm::dvec2(0.9, 0.45));
  const BezierCurve curve2 = read_bzc(dir / "bzc" / "curve2.bzc");
  ASSERT_EQ(curve2.control_points.size(), 5u);
  EXPECT_EQ(curve2.control_points[4], glm::dvec2(1.0, 0.9));
}

}  // namespace
}  // namespace meshedit
