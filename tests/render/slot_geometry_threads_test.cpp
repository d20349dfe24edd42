// build_slot_geometry on several threads: every slot array, list, count and the bounds are the same bytes as on
// one thread, on meshes big enough that every pass is split (kMinItemsPerThread elements per chunk): a subdivided
// torus, a quad torus (polygons: extra fan triangles, corners added past the first triangle), and a torus broken by
// raw writes and deletions (dead slots, faces that do not close, a cycle that runs into itself, non-finite
// positions). One thread is the build the incremental-update tests hold to the patched arrays.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/parallel_for.h"
#include "core/primitives.h"
#include "quad_torus.h"
#include "support/random_edits.h"
#include "update_test_support.h"

namespace meshedit {
namespace {

void expect_same_on_any_thread_count(const HalfedgeMesh& mesh) {
  ASSERT_GT(mesh.face_capacity(), 3 * kMinItemsPerThread);  // every pass splits on 2 and 3 threads
  ASSERT_GT(mesh.vertex_capacity(), 3 * kMinItemsPerThread);
  const SlotGeometry one = build_slot_geometry(mesh, 1);
  for (const int threads : {2, 3}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    const SlotGeometry many = build_slot_geometry(mesh, threads);
    testing::expect_same_slots(many, one);
    EXPECT_EQ(many.bounds.min, one.bounds.min);
    EXPECT_EQ(many.bounds.max, one.bounds.max);
  }
}

TEST(SlotGeometryThreads, SubdividedTorus) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(150, 120));
  ASSERT_TRUE(loop_subdivide(mesh, LoopWeights::Course, 1, 2).ok);
  const SlotGeometry g = build_slot_geometry(mesh, 2);
  EXPECT_EQ(g.counts.triangles, mesh.num_faces());
  EXPECT_EQ(g.counts.skipped_faces, 0u);
  expect_same_on_any_thread_count(mesh);
}

TEST(SlotGeometryThreads, QuadTorus) {
  const HalfedgeMesh mesh = build_halfedge_mesh(quad_torus(300, 200));
  const SlotGeometry g = build_slot_geometry(mesh, 2);
  EXPECT_EQ(g.counts.triangles, 2 * mesh.num_faces());
  ASSERT_EQ(g.extra_faces.size(), mesh.num_faces());
  for (size_t i = 1; i < g.extra_faces.size(); ++i) ASSERT_LT(g.extra_faces[i - 1], g.extra_faces[i]);
  expect_same_on_any_thread_count(mesh);
}

TEST(SlotGeometryThreads, BrokenTorus) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(300, 200));
  std::mt19937 random(11);
  for (int i = 0; i < 3000; ++i) testing::random_edit_or_write(mesh, random);
  // A face whose cycle runs into itself away from its start (the walk must stop at the repeat), in the second
  // thread's half, and a non-finite corner.
  FaceId f = FaceId::face(mesh.face_capacity() * 3 / 4);
  const auto closed_triangle = [&](FaceId g) {
    if (!mesh.alive(g)) return false;
    const HalfedgeId h = mesh.halfedge(g);
    return mesh.face(h) == g && mesh.face(mesh.next(h)) == g && mesh.face(mesh.next(mesh.next(h))) == g &&
           mesh.next(mesh.next(mesh.next(h))) == h;
  };
  while (!closed_triangle(f)) f = FaceId::face(f.slot() + 1);
  ASSERT_NE(build_slot_geometry(mesh, 1).triangles[3 * f.slot() + 1], 0u);
  mesh.set_next(mesh.next(mesh.next(mesh.halfedge(f))), mesh.next(mesh.halfedge(f)));
  mesh.set_position(VertexId(mesh.vertex_capacity() / 2 + 5), glm::dvec3(INFINITY, 0.0, 0.0));
  const SlotGeometry g = build_slot_geometry(mesh, 2);
  EXPECT_GT(g.counts.skipped_faces, 0u);
  EXPECT_GT(g.counts.skipped_edges, 0u);
  EXPECT_EQ(g.triangles[3 * f.slot()], 0u);
  EXPECT_EQ(g.triangles[3 * f.slot() + 1], 0u);
  expect_same_on_any_thread_count(mesh);
}

}  // namespace
}  // namespace meshedit
