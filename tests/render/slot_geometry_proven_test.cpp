// build_slot_geometry_of_proven_triangles (slot_geometry_proven.h) against the general build by walks, byte for byte,
// on meshes vouched valid with triangles: closed and open fixtures, Loop-subdivided meshes (one and two threads),
// and subdivisions of edited meshes that carry dead slots. And build_slot_geometry takes the short path only for
// vouched meshes: after any edit it walks, and still agrees.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "render/slot_geometry_proven.h"
#include "support/random_edits.h"
#include "update_test_support.h"

namespace meshedit {
namespace {

using testing::same_bytes;

void expect_same(const SlotGeometry& a, const SlotGeometry& b) {
  EXPECT_TRUE(same_bytes(a.positions, b.positions));
  EXPECT_TRUE(same_bytes(a.smooth_normals, b.smooth_normals));
  EXPECT_TRUE(same_bytes(a.points, b.points));
  EXPECT_TRUE(same_bytes(a.triangles, b.triangles));
  EXPECT_TRUE(same_bytes(a.face_normals, b.face_normals));
  EXPECT_TRUE(same_bytes(a.extra_triangles, b.extra_triangles));
  EXPECT_TRUE(same_bytes(a.extra_faces, b.extra_faces));
  EXPECT_TRUE(same_bytes(a.edges, b.edges));
  EXPECT_EQ(a.boundary_edges, b.boundary_edges);
  EXPECT_TRUE(a.counts == b.counts);
  EXPECT_EQ(a.bounds.min, b.bounds.min);
  EXPECT_EQ(a.bounds.max, b.bounds.max);
}

void expect_proven_path_agrees(const HalfedgeMesh& mesh, const std::string& name) {
  SCOPED_TRACE(name);
  ASSERT_TRUE(mesh.proven_valid_triangles());
  const SlotGeometry fast = build_slot_geometry_of_proven_triangles(mesh);
  expect_same(fast, build_slot_geometry_by_walks(mesh));
  expect_same(fast, build_slot_geometry(mesh));
}

TEST(SlotGeometryProven, SameBytesAsTheWalksOnFixtures) {
  expect_proven_path_agrees(build_halfedge_mesh(make_tetrahedron()), "tetrahedron");
  expect_proven_path_agrees(build_halfedge_mesh(make_icosahedron()), "icosahedron");
  expect_proven_path_agrees(build_halfedge_mesh(make_torus(9, 7)), "torus");
  expect_proven_path_agrees(build_halfedge_mesh(make_grid(6, 4)), "grid (boundary)");
  expect_proven_path_agrees(build_halfedge_mesh(make_fan(7)), "fan (boundary)");
}

TEST(SlotGeometryProven, SameBytesAsTheWalksAfterLoopSubdivision) {
  HalfedgeMesh torus = build_halfedge_mesh(make_torus(12, 8));
  ASSERT_TRUE(loop_subdivide(torus, LoopWeights::Course, 2, 1));
  expect_proven_path_agrees(torus, "torus x2");
  HalfedgeMesh grid = build_halfedge_mesh(make_grid(9, 5));
  ASSERT_TRUE(loop_subdivide(grid, LoopWeights::Loop, 2, 2));
  expect_proven_path_agrees(grid, "grid x2, two threads");
}

TEST(SlotGeometryProven, SameBytesAsTheWalksWithDeadSlots) {
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    HalfedgeMesh m = testing::edited_torus(seed);
    EXPECT_FALSE(m.proven_valid_triangles());
    expect_same(build_slot_geometry(m), build_slot_geometry_by_walks(m));
    if (!loop_subdivide(m)) continue;  // an edit history Loop refuses: nothing to vouch for
    expect_proven_path_agrees(m, "edited torus " + std::to_string(seed) + ", subdivided");
  }
}

TEST(SlotGeometryProven, AnEditTakesTheWalksAgain) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(6, 5));
  m.set_position(VertexId(4), glm::dvec3(std::nan(""), 0.0, 0.0));  // not finite: the walks hide its faces
  ASSERT_FALSE(m.proven_valid_triangles());
  const SlotGeometry g = build_slot_geometry(m);
  EXPECT_GT(g.counts.skipped_faces, 0u);
  EXPECT_EQ(g.points[4].vertex, kInvalidIndex);
  expect_same(g, build_slot_geometry_by_walks(m));
}

}  // namespace
}  // namespace meshedit
