// The fast Loop subdivision against the teaching path on every real course mesh (../shared/data/cs184; skipped
// when absent; the .bez patches tessellated as the app shows them): the same mesh id for id, pointer for pointer and
// bit for bit, two levels, both weight sets, one and two threads. tests/core/loop_fast_test.cpp covers the generated
// and randomly edited meshes.
#include <filesystem>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/patch_tessellation.h"
#include "io/mesh_file.h"
#include "support/loop_equality.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(LoopFastCourseFiles, SameAsPhasesOnEveryCourseMesh) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  size_t compared = 0;
  for (const char* folder : {"dae", "bez"}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir / folder)) {
      if (!entry.is_regular_file() || entry.path().filename().string()[0] == '.') continue;
      SCOPED_TRACE(entry.path().string());
      const LoadedFile file = load_file(entry.path());
      const HalfedgeMesh mesh =
          build_halfedge_mesh(file.kind == FileKind::Patches ? tessellate_patches(file.patches) : file.mesh);
      ASSERT_TRUE(can_loop_subdivide(mesh)) << can_loop_subdivide(mesh).reason;
      const int levels = mesh.num_faces() > 20000 ? 1 : 2;
      EXPECT_TRUE(testing::loop_paths_agree(mesh, LoopWeights::Course, levels, 1));
      EXPECT_TRUE(testing::loop_paths_agree(mesh, LoopWeights::Loop, levels, 2));
      ++compared;
    }
  }
  EXPECT_GE(compared, 10u);
}

}  // namespace
}  // namespace meshedit
