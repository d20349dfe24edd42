// The quick sufficient checks (quick_check.h) never accept what the full checks refuse: on valid fixtures they
// say yes (or the speed-up would be lost), and on hundreds of meshes broken by random pointer writes, deletions,
// non-finite positions and local operations, a yes always comes with validate().ok() / can_loop_subdivide(), on
// one thread or several.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_storage.h"
#include "core/parallel_for.h"
#include "core/primitives.h"
#include "core/quick_check.h"
#include "core/validate.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

TEST(QuickCheck, AcceptsTheValidFixtures) {
  for (const PolygonMesh& p :
       {make_tetrahedron(), make_cube(), make_icosahedron(), make_grid(6, 4), make_fan(30), make_torus(11, 7)}) {
    const HalfedgeMesh m = build_halfedge_mesh(p);
    EXPECT_TRUE(mesh_is_clean(m));
    EXPECT_TRUE(loop_input_is_clean(m));
  }
  const HalfedgeMesh quads = build_halfedge_mesh(make_cube_quads());
  EXPECT_TRUE(mesh_is_clean(quads));
  EXPECT_FALSE(loop_input_is_clean(quads));  // not triangles
}

TEST(QuickCheck, AcceptsMeshesAfterLocalOperationsWithDeadSlots) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(9, 7));
  testing::random_local_edits(m, 7, 200);
  ASSERT_TRUE(validate_without_shortcut(m).ok());
  EXPECT_TRUE(mesh_is_clean(m));
}

// A vouched mesh is trusted without a walk (the status bar validates every new state, 0.75 s at 2.5M faces after
// L): shown by vouching, as only a builder or Loop may, for a mesh the walk would refuse. The vouching ends with the
// next change, and the walk is back.
TEST(QuickCheck, TrustsAVouchedMeshUntilItChanges) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(9, 7));
  const HalfedgeId h(4);
  m.set_next(h, m.next(m.next(h)));
  ASSERT_FALSE(mesh_is_clean(m));
  MeshStorage::vouch_valid_triangles(m);
  EXPECT_TRUE(mesh_is_clean(m));
  EXPECT_TRUE(validate(m).ok());
  m.set_position(VertexId(0), m.position(VertexId(0)));
  EXPECT_FALSE(mesh_is_clean(m));
  EXPECT_FALSE(validate(m).ok());

  HalfedgeMesh subdivided = build_halfedge_mesh(make_torus(9, 7));
  ASSERT_TRUE(loop_subdivide(subdivided, LoopWeights::Course, 2).ok);
  ASSERT_TRUE(subdivided.proven_valid_triangles());
  EXPECT_TRUE(mesh_is_clean(subdivided));
  EXPECT_TRUE(validate_without_shortcut(subdivided).ok());
}

// One face id on two cycles (the halfedges of a face that shares no edge with f0 relabelled as f0's, that face
// deleted): every pointer is live and paired, but not every halfedge of f0 is in f0's cycle.
TEST(QuickCheck, RefusesAFaceWithTwoCycles) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(6, 5));
  const FaceId f0 = FaceId::face(0);
  FaceId f1;
  for (FaceId f : m.faces()) {
    bool touches = f == f0;
    m.for_each_face_halfedge(f, [&](HalfedgeId h) { touches = touches || m.face(m.twin(h)) == f0; });
    if (!touches) {
      f1 = f;
      break;
    }
  }
  ASSERT_TRUE(f1.valid());
  std::vector<HalfedgeId> cycle;
  m.for_each_face_halfedge(f1, [&](HalfedgeId h) { cycle.push_back(h); });
  for (HalfedgeId h : cycle) m.set_face(h, f0);
  m.delete_element(f1);
  ASSERT_FALSE(validate_without_shortcut(m).ok());
  EXPECT_FALSE(mesh_is_clean(m));
  EXPECT_FALSE(validate(m).ok());
}

TEST(QuickCheck, NeverAcceptsWhatTheFullChecksRefuse) {
  size_t refused = 0;
  for (uint32_t seed = 1; seed <= 600; ++seed) {
    HalfedgeMesh m = build_halfedge_mesh(seed % 3 == 0   ? make_grid(4, 3)
                                         : seed % 3 == 1 ? make_torus(6, 5)
                                                         : make_cube());
    std::mt19937 random(seed);
    testing::break_randomly(m, random);
    const ValidationReport full = validate_without_shortcut(m);
    refused += full.ok() ? 0 : 1;
    SCOPED_TRACE("seed " + std::to_string(seed));
    if (mesh_is_clean(m)) {
      EXPECT_TRUE(full.ok()) << full.summary();
    }
    if (loop_input_is_clean(m)) {
      EXPECT_TRUE(can_loop_subdivide_without_shortcut(m).ok);
    }
  }
  EXPECT_GT(refused, 400u);  // the fuzz really breaks meshes
}

// Two twin pairs on one edge (the second pair's edge deleted and its halfedges pointed at the first's edge): every
// pointer is live and paired, but the edge holds four halfedges. The quick check counts none; it finds this because
// the edge's halfedge belongs to only one of the two pairs.
TEST(QuickCheck, RefusesTwoTwinPairsOnOneEdge) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(6, 5));
  const EdgeId kept(0), merged(20);
  const HalfedgeId b = m.halfedge(merged), b_twin = m.twin(b);
  ASSERT_NE(m.halfedge(kept), b);
  ASSERT_NE(m.halfedge(kept), b_twin);
  m.set_edge(b, kept);
  m.set_edge(b_twin, kept);
  m.delete_element(merged);
  ASSERT_FALSE(validate_without_shortcut(m).ok());
  for (const int threads : {1, 2}) {
    EXPECT_FALSE(mesh_is_clean(m, threads));
    EXPECT_FALSE(loop_input_is_clean(m, threads));
  }
}

// On a mesh big enough to be split across threads, the answer does not depend on the thread count, and a yes on any
// count still comes with the full checks' yes. Some meshes are left whole, so that the yes is exercised too.
TEST(QuickCheck, GivesTheSameAnswerOnAnyThreadCount) {
  const HalfedgeMesh torus = build_halfedge_mesh(make_torus(160, 120));
  ASSERT_GT(torus.halfedge_capacity(), 4 * kMinItemsPerThread);
  size_t accepted = 0;
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    HalfedgeMesh m = torus;
    std::mt19937 random(seed);
    if (seed % 4 != 0) testing::break_randomly(m, random);
    SCOPED_TRACE("seed " + std::to_string(seed));
    const bool clean = mesh_is_clean(m, 1), loop_clean = loop_input_is_clean(m, 1);
    for (const int threads : {2, 3}) {
      EXPECT_EQ(mesh_is_clean(m, threads), clean);
      EXPECT_EQ(loop_input_is_clean(m, threads), loop_clean);
      EXPECT_EQ(validate(m, kListedViolations, threads).ok(), validate(m).ok());
    }
    if (clean) {
      ++accepted;
      EXPECT_TRUE(validate_without_shortcut(m).ok());
    }
  }
  EXPECT_GE(accepted, 10u);
}

}  // namespace
}  // namespace meshedit
