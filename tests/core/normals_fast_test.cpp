// The whole-mesh vertex normals against the per-element vertex_normal: bit for bit on the checked path (polygons,
// meshes broken by random pointer writes and deletions, where both must give the same, often zero, answers), and
// to rounding on the face-order path that meshes proven valid with triangles take (closed and open meshes, dead
// slots left by edits, a big torus split over threads, where the row path gives the same bits on any number of
// threads). One to five threads, reused buffers.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/primitives.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

// How far the face-order path may be from vertex_normal: the same terms added in another order, each unit
// component off by a few units in the last place.
constexpr double kRounding = 1e-13;

bool bitwise_equal(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool equal_to_rounding(const glm::dvec3& a, const glm::dvec3& b) {
  if (a == glm::dvec3(0.0) || b == glm::dvec3(0.0)) return a == b;  // zero (no area) is no rounding matter
  return std::abs(a.x - b.x) <= kRounding && std::abs(a.y - b.y) <= kRounding && std::abs(a.z - b.z) <= kRounding;
}

// vertex_normals(m) against vertex_normal(m, v) for every slot: bit for bit on the checked path, to rounding on
// the face-order path of a proven mesh.
::testing::AssertionResult same_as_per_vertex(const HalfedgeMesh& m, int threads) {
  const bool face_order = m.proven_valid_triangles() || m.triangle_rows() != nullptr;
  std::vector<glm::dvec3> all;
  for (int round = 0; round < 2; ++round) {  // the second round reuses the vector
    vertex_normals(m, all, threads);
    if (all.size() != m.vertex_capacity()) return ::testing::AssertionFailure() << "size " << all.size();
    for (uint32_t v = 0; v < m.vertex_capacity(); ++v) {
      const glm::dvec3 one = vertex_normal(m, VertexId(v));
      if (face_order ? !equal_to_rounding(one, all[v]) : !bitwise_equal(one, all[v])) {
        return ::testing::AssertionFailure()
               << "v" << v << ": (" << all[v].x << ", " << all[v].y << ", " << all[v].z << ") but vertex_normal gives ("
               << one.x << ", " << one.y << ", " << one.z << ")" << (face_order ? " (face-order path)" : "");
      }
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(NormalsFast, EqualPerVertexNormals) {
  for (const PolygonMesh& p : {make_tetrahedron(), make_cube(), make_cube_quads(), make_icosahedron(), make_grid(6, 4),
                               make_fan(30), make_torus(11, 7)}) {
    const HalfedgeMesh m = build_halfedge_mesh(p);
    EXPECT_TRUE(same_as_per_vertex(m, 1));
  }
}

// A regular icosahedron centred at the origin: five equal faces around each vertex, so every vertex normal is
// the vertex's own direction. On the face-order path.
TEST(NormalsFast, IcosahedronNormalsPointAwayFromTheCentre) {
  const HalfedgeMesh m = build_halfedge_mesh(make_icosahedron());
  ASSERT_TRUE(m.proven_valid_triangles());
  const std::vector<glm::dvec3> all = vertex_normals(m);
  for (VertexId v : m.vertices()) {
    EXPECT_TRUE(equal_to_rounding(all[v.index], glm::normalize(m.position(v)))) << "v" << v.index;
  }
}

// Dead slots among the ids (flips, splits and collapses before the subdivision): the face-order path skips dead
// faces and leaves dead vertices at zero.
TEST(NormalsFast, SubdividedMeshWithDeadSlots) {
  for (uint32_t seed = 1; seed <= 20; ++seed) {
    HalfedgeMesh m = build_halfedge_mesh(seed % 2 ? make_torus(9, 7) : make_grid(8, 6));
    testing::random_local_edits(m, seed, 40);
    if (!loop_subdivide(m, LoopWeights::Loop, 1, 1)) continue;  // edits may leave a mesh Loop refuses
    ASSERT_TRUE(m.proven_valid_triangles());
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_TRUE(same_as_per_vertex(m, 1));
    const std::vector<glm::dvec3> all = vertex_normals(m);
    for (uint32_t v = 0; v < m.vertex_capacity(); ++v) {
      if (!m.alive(VertexId(v))) {
        EXPECT_EQ(all[v], glm::dvec3(0.0)) << "dead v" << v;
      }
    }
  }
}

TEST(NormalsFast, TwoThreadsOnABigSubdividedTorus) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus_with_faces(20000));
  ASSERT_TRUE(loop_subdivide(m, LoopWeights::Loop, 1, 2));
  ASSERT_NE(m.triangle_rows(), nullptr);
  EXPECT_TRUE(same_as_per_vertex(m, 2));
  const std::vector<glm::dvec3> one = vertex_normals(m, 1), two = vertex_normals(m, 2);
  ASSERT_EQ(one.size(), two.size());
  for (size_t v = 0; v < one.size(); ++v) EXPECT_TRUE(bitwise_equal(one[v], two[v])) << "v" << v;
}

// Rows made from faces in a shuffled order: runs of rows share thousands of vertices, whose terms wait for every
// run to finish. Each vertex still gets its terms in row order, so the bits are the same on one to five threads.
TEST(NormalsFast, RowsSplitOverThreadsGiveTheSameBitsWhateverTheirSeam) {
  const PolygonMesh torus = make_torus_with_faces(20000);
  std::vector<size_t> order(torus.num_faces());
  for (size_t f = 0; f < order.size(); ++f) order[f] = f;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  PolygonMesh shuffled;
  shuffled.positions = torus.positions;
  for (size_t f : order) shuffled.add_face(torus.face(f));
  HalfedgeMesh m = build_halfedge_mesh(shuffled);
  ASSERT_TRUE(loop_subdivide(m, LoopWeights::Loop, 1, 1));
  ASSERT_NE(m.triangle_rows(), nullptr);
  EXPECT_TRUE(same_as_per_vertex(m, 4));
  const std::vector<glm::dvec3> one = vertex_normals(m, 1);
  for (int threads = 2; threads <= 5; ++threads) {
    const std::vector<glm::dvec3> more = vertex_normals(m, threads);
    ASSERT_EQ(one.size(), more.size());
    size_t differ = 0;
    for (size_t v = 0; v < one.size(); ++v) differ += bitwise_equal(one[v], more[v]) ? 0 : 1;
    EXPECT_EQ(differ, 0u) << threads << " threads";
  }
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

// The face-order path runs only on meshes vouched for (built from clean triangles, or Loop-subdivided), and any
// change takes the vouching back.
TEST(NormalsFast, OnlyVouchedMeshesTakeTheFaceOrderPath) {
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
