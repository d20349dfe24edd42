// Every CS184 course mesh (../shared/data/cs184/dae; skipped when absent) through the PLY and STL writers
// and back: PLY keeps it exactly, STL keeps each triangle's corners as floats, welded into shared vertices
// that still build a half-edge mesh with the course mesh's counts.
#include <gtest/gtest.h>

#include "core/halfedge_mesh.h"
#include "core/mesh_build.h"
#include "io/dae_reader.h"
#include "io/ply_io.h"
#include "io/stl_io.h"
#include "io_test_util.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(CourseFormats, EveryCourseMeshSurvivesPlyAndStl) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  size_t meshes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "dae")) {
    if (entry.path().extension() != ".dae") continue;
    SCOPED_TRACE(entry.path().string());
    const PolygonMesh mesh = read_dae(entry.path());
    testing::expect_same_mesh(parse_ply(format_ply(mesh, "m.ply"), "m.ply"), mesh);

    const PolygonMesh back = parse_stl(format_stl(mesh, "m.stl"), "m.stl");
    PolygonMesh as_floats = mesh;
    for (glm::dvec3& p : as_floats.positions) {
      for (int a = 0; a < 3; ++a) {
        volatile float rounded = static_cast<float>(p[a]);  // volatile: see Stl.RoundTrips... in stl_io_test
        p[a] = rounded;
      }
    }
    testing::expect_same_face_positions(back, as_floats);
    const HalfedgeMesh original = build_halfedge_mesh(mesh);
    const HalfedgeMesh welded = build_halfedge_mesh(back);
    EXPECT_EQ(welded.num_faces(), original.num_faces());
    EXPECT_EQ(welded.num_vertices(), original.num_vertices());
    ++meshes;
  }
  EXPECT_GE(meshes, 8u);
}

}  // namespace
}  // namespace meshedit
