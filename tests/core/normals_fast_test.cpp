// The whole-mesh vertex normals (triangle fast path, one or two threads, reused buffers) against the per-element
// vertex_normal, bit for bit: on closed and open meshes, polygons, a big torus split over two threads, and meshes
// broken by random pointer writes and deletions, where both must give the same (often zero) answers.
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

::testing::AssertionResult same_as_per_vertex(const HalfedgeMesh& m, int threads) {
  std::vector<glm::dvec3> all;
  for (int round = 0; round < 2; ++round) {  // the second round reuses the vector
    vertex_normals(m, all, threads);
    if (all.size() != m.vertex_capacity()) return ::testing::AssertionFailure() << "size " << all.size();
    for (uint32_t v = 0; v < m.vertex_capacity(); ++v) {
      const glm::dvec3 one = vertex_normal(m, VertexId(v));
      if (std::memcmp(&one, &all[v], sizeof one) != 0) {
        return ::testing::AssertionFailure() << "v" << v << ": (" << all[v].x << ", " << all[v].y << ", " << all[v].z
                                             << ") but vertex_normal gives (" << one.x << ", " << one.y << ", "
                                             << one.z << ")";
      }
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(NormalsFast, EqualPerVertexNormalsBitForBit) {
  for (const PolygonMesh& p : {make_tetrahedron(), make_cube(), make_cube_quads(), make_icosahedron(), make_grid(6, 4),
                               make_fan(30), make_torus(11, 7)}) {
    const HalfedgeMesh m = build_halfedge_mesh(p);
    EXPECT_TRUE(same_as_per_vertex(m, 1));
  }
}

TEST(NormalsFast, TwoThreadsOnABigSubdividedTorus) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus_with_faces(20000));
  ASSERT_TRUE(loop_subdivide(m, LoopWeights::Loop, 1, 2));
  EXPECT_TRUE(same_as_per_vertex(m, 2));
  const std::vector<glm::dvec3> one = vertex_normals(m, 1), two = vertex_normals(m, 2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(glm::dvec3)), 0);
}

TEST(NormalsFast, BrokenMeshesGiveTheSameAnswersAsThePerVertexWalk) {
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    HalfedgeMesh m = build_halfedge_mesh(seed % 2 ? make_torus(6, 5) : make_grid(5, 4));
    std::mt19937 random(seed);
    for (int i = 0; i < 3; ++i) {
      const HalfedgeId h(random() % m.halfedge_capacity());
      switch (random() % 6) {
        case 0: m.set_next(h, random() % 4 ? HalfedgeId(random() % (m.halfedge_capacity() + 3)) : h); break;
        case 1: m.set_twin(h, HalfedgeId(random() % m.halfedge_capacity())); break;
        case 2: m.set_vertex(h, VertexId(random() % (m.vertex_capacity() + 2))); break;
        case 3: m.set_face(h, FaceId::face(random() % (m.face_capacity() + 2))); break;
        case 4: m.delete_element(VertexId(random() % m.vertex_capacity())); break;
        default: m.delete_element(HalfedgeId(random() % m.halfedge_capacity())); break;
      }
    }
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_TRUE(same_as_per_vertex(m, 1));
  }
}

}  // namespace
}  // namespace meshedit

namespace meshedit {
namespace {

// The one-ring path runs only on meshes vouched for (built from clean triangles, or Loop-subdivided), and any
// change takes the vouching back.
TEST(NormalsFast, OnlyVouchedMeshesTakeTheOneRingPath) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(8, 6));
  EXPECT_TRUE(m.proven_valid_triangles());
  EXPECT_TRUE(same_as_per_vertex(m, 1));
  EXPECT_FALSE(build_halfedge_mesh(make_cube_quads()).proven_valid_triangles());
  m.set_position(VertexId(3), m.position(VertexId(3)) + glm::dvec3(0.25, 0.0, 0.0));
  EXPECT_FALSE(m.proven_valid_triangles());
  EXPECT_TRUE(same_as_per_vertex(m, 1));
  ASSERT_TRUE(loop_subdivide(m, LoopWeights::Course, 2, 1));
  EXPECT_TRUE(m.proven_valid_triangles());
  EXPECT_TRUE(same_as_per_vertex(m, 1));
  HalfedgeMesh grid = build_halfedge_mesh(make_grid(7, 5));  // boundary vertices: fans with a boundary halfedge
  ASSERT_TRUE(grid.proven_valid_triangles());
  EXPECT_TRUE(same_as_per_vertex(grid, 2));
}

}  // namespace
}  // namespace meshedit
