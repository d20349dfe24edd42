// The fast Loop subdivision (loop_subdivide) against the teaching path (loop_subdivide_by_phases, which splits and
// flips one edge at a time): the same mesh id for id, pointer for pointer and position bit for bit, on closed
// meshes, meshes with boundaries, meshes whose ids have holes after random flips, splits and collapses, several
// levels, both weight sets, and one or two threads. The course files are compared in tests/io.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/triangulate.h"
#include "core/validate.h"
#include "support/loop_equality.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

const std::vector<std::pair<std::string, PolygonMesh>>& fixtures() {
  static const std::vector<std::pair<std::string, PolygonMesh>> all = {{"tetrahedron", make_tetrahedron()},
                                                                       {"cube", make_cube()},
                                                                       {"icosahedron", make_icosahedron()},
                                                                       {"grid 3x2", make_grid(3, 2)},
                                                                       {"grid 7x5", make_grid(7, 5)},
                                                                       {"fan 9", make_fan(9)},
                                                                       {"fan 50", make_fan(50)},
                                                                       {"torus 6x5", make_torus(6, 5)}};
  return all;
}

TEST(LoopFast, SameAsPhasesOnEveryFixture) {
  for (const auto& [name, polygons] : fixtures()) {
    for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
      SCOPED_TRACE(name);
      EXPECT_TRUE(testing::loop_paths_agree(build_halfedge_mesh(polygons), w, 1, 1));
      EXPECT_TRUE(testing::loop_paths_agree(build_halfedge_mesh(polygons), w, 3, 1));
    }
  }
}

TEST(LoopFast, SameAsPhasesWithTwoThreads) {
  // Big enough for parallel_for to split every pass (at least kMinItemsPerThread elements per thread).
  for (const PolygonMesh& polygons : {make_torus_with_faces(40000), make_grid(150, 120)}) {
    EXPECT_TRUE(testing::loop_paths_agree(build_halfedge_mesh(polygons), LoopWeights::Loop, 1, 2));
    EXPECT_TRUE(testing::loop_paths_agree(build_halfedge_mesh(polygons), LoopWeights::Course, 2, 2));
  }
}

// Dead edges and a boundary on a mesh big enough for two chunks: the boundary edges found on the loops are counted in
// the chunk that holds them.
TEST(LoopFast, SameAsPhasesWithTwoThreadsAfterRandomEdits) {
  for (uint32_t seed = 1; seed <= 2; ++seed) {
    HalfedgeMesh m = build_halfedge_mesh(make_grid(150, 120));
    testing::random_local_edits(m, seed, 200);
    ASSERT_TRUE(validate(m).ok());
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_TRUE(testing::loop_paths_agree(m, LoopWeights::Loop, 1, 2));
  }
}

// Random flips, splits and collapses leave dead slots among the ids and an irregular order of edges around each
// face, so the triangles' edges are split in every order and from both sides.
TEST(LoopFast, SameAsPhasesAfterRandomEdits) {
  for (uint32_t seed = 1; seed <= 12; ++seed) {
    HalfedgeMesh m = build_halfedge_mesh(seed % 2 ? make_torus(9, 7) : make_grid(8, 6));
    testing::random_local_edits(m, seed, 60);
    ASSERT_TRUE(validate(m).ok());
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_TRUE(testing::loop_paths_agree(m, seed % 3 ? LoopWeights::Course : LoopWeights::Loop, 2, 1));
  }
}

// Dead slots that never held anything (a face, edge and vertex made and deleted at once, pointers invalid) are
// skipped by every pass, wherever they sit among the live ids.
TEST(LoopFast, DeadSlotsWithInvalidPointers) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(20, 12));
  for (int i = 0; i < 40; ++i) {
    m.delete_element(m.new_face());
    m.delete_element(m.new_edge());
    m.delete_element(m.new_vertex());
    m.delete_element(m.new_halfedge());
  }
  ASSERT_TRUE(validate(m).ok());
  EXPECT_TRUE(testing::loop_paths_agree(m, LoopWeights::Loop, 2, 1));
}

TEST(LoopFast, RefusesLikeThePhasesAndChangesNothing) {
  HalfedgeMesh quads = build_halfedge_mesh(make_cube_quads());
  const HalfedgeMesh before = quads;
  const uint64_t version = quads.version();
  const Check refused = loop_subdivide(quads, LoopWeights::Course, 3, 2);
  EXPECT_FALSE(refused.ok);
  EXPECT_EQ(refused.reason, std::string("f0 has 4 sides; Loop subdivision needs triangles; ") + kHowToTriangulate);
  EXPECT_TRUE(quads.same_as(before));
  EXPECT_EQ(quads.version(), version);

  HalfedgeMesh broken = build_halfedge_mesh(make_cube());
  broken.set_next(HalfedgeId(0), HalfedgeId(0));
  const HalfedgeMesh broken_before = broken;
  const Check broken_refused = loop_subdivide(broken);
  EXPECT_FALSE(broken_refused.ok);
  EXPECT_EQ(broken_refused.reason, can_loop_subdivide(broken_before).reason);
  EXPECT_TRUE(broken.same_as(broken_before));
}

// A mesh is vouched valid (proven_valid_triangles) only as validate() would find it, finite positions included: not
// when built from a non-finite position, and not when subdividing overflowed one. Loop then refuses the first like
// the teaching path, and a mesh that overflowed shows up as invalid.
TEST(LoopFast, VouchesOnlyForFinitePositions) {
  PolygonMesh with_nan = make_tetrahedron();
  with_nan.positions[2].y = std::nan("");
  HalfedgeMesh m = build_halfedge_mesh(with_nan);
  EXPECT_FALSE(m.proven_valid_triangles());
  EXPECT_FALSE(validate(m).ok());
  const HalfedgeMesh before = m;
  const Check refused = loop_subdivide(m);
  EXPECT_FALSE(refused.ok);
  EXPECT_EQ(refused.reason, can_loop_subdivide(before).reason);
  EXPECT_TRUE(m.same_as(before));

  PolygonMesh huge = make_icosahedron();
  for (glm::dvec3& p : huge.positions) p *= 1e308;  // finite, but a sum of five neighbours is not
  HalfedgeMesh big = build_halfedge_mesh(huge);
  ASSERT_TRUE(big.proven_valid_triangles());
  ASSERT_TRUE(loop_subdivide(big, LoopWeights::Course, 1, 1));
  EXPECT_FALSE(big.proven_valid_triangles());
  EXPECT_FALSE(validate(big).ok());

  HalfedgeMesh fine = build_halfedge_mesh(make_icosahedron());
  ASSERT_TRUE(loop_subdivide(fine, LoopWeights::Course, 2, 2));
  EXPECT_TRUE(fine.proven_valid_triangles());
}

TEST(LoopFast, ZeroLevelsChangesNothing) {
  HalfedgeMesh m = build_halfedge_mesh(make_cube());
  const HalfedgeMesh before = m;
  EXPECT_TRUE(loop_subdivide(m, LoopWeights::Course, 0));
  EXPECT_TRUE(m.same_as(before));
}

TEST(LoopFast, SubdividedCubeHasTheCountsAndAValidMesh) {
  HalfedgeMesh m = build_halfedge_mesh(make_cube());  // 8 vertices, 18 edges, 12 faces
  ASSERT_TRUE(loop_subdivide(m, LoopWeights::Course, 2, 1));
  EXPECT_EQ(m.num_vertices(), 8u + 18u + 72u);  // V' = V + E per level: 26, then 26 + 72
  EXPECT_EQ(m.num_faces(), 12u * 16u);
  EXPECT_EQ(m.num_edges(), 2u * 72u + 3u * 48u);
  EXPECT_TRUE(validate(m).ok());
}

}  // namespace
}  // namespace meshedit
