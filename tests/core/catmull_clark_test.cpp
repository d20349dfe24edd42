// Catmull-Clark subdivision: exact positions worked out by hand on a cube, a tetrahedron and a grid with a
// boundary, counts and validity, the three phases against the one call, and refusals that change nothing.
//
// Expected positions come from the rules with each neighbourhood spelled out (never from the code under test):
//   face point: centroid; interior edge point: (a + b + f0 + f1) / 4; boundary edge point: (a + b) / 2;
//   interior vertex: (F + 2R + (n - 3) P) / n, F the mean of its face points, R the mean of its edge midpoints;
//   boundary vertex: 3/4 P + 1/8 (its two boundary neighbours).
// The shapes are scaled so that most expected coordinates are exact in binary and are compared with ==.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

#include "core/catmull_clark.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

::testing::AssertionResult valid(const HalfedgeMesh& mesh) {
  const ValidationReport report = validate(mesh);
  if (report.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << report.summary();
}

VertexId V(uint32_t i) { return VertexId(i); }

EdgeId edge_between(const HalfedgeMesh& mesh, uint32_t a, uint32_t b) {
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    const uint32_t x = mesh.vertex(h).index, y = mesh.vertex(mesh.twin(h)).index;
    if ((x == a && y == b) || (x == b && y == a)) return e;
  }
  ADD_FAILURE() << "no edge v" << a << "-v" << b;
  return EdgeId(0);
}

// The refined id of the vertex on original edge a-b: after the original vertices, one per edge in id order
// (every edge of these fixtures is live, so edge e's vertex is V + e).
VertexId edge_vertex(const HalfedgeMesh& original, uint32_t a, uint32_t b) {
  return V(original.vertex_capacity() + edge_between(original, a, b).index);
}
// The refined id of face f's vertex: after the edges' vertices.
VertexId face_vertex(const HalfedgeMesh& original, uint32_t f) {
  return V(original.vertex_capacity() + original.edge_capacity() + f);
}

PolygonMesh scaled(PolygonMesh polygons, double factor) {
  for (glm::dvec3& p : polygons.positions) p *= factor;
  return polygons;
}

bool all_quads(const HalfedgeMesh& mesh) {
  for (FaceId f : mesh.faces()) {
    if (mesh.degree(f) != 4) return false;
  }
  return true;
}

double sign(double x) { return x < 0 ? -1.0 : 1.0; }

// The cube [-9, 9]^3 as 6 quads. A corner P = (9, 9, 9) has valence 3; its faces' points are (9,0,0), (0,9,0),
// (0,0,9), so F = (3,3,3); its edges' midpoints are (9,9,0), (9,0,9), (0,9,9), so R = (6,6,6); (F + 2R + 0 P) / 3 =
// (5,5,5) = 5/9 P. An edge from (9,9,9) to (9,9,-9) has faces x = 9 and y = 9: ((18,18,0) + (9,0,0) + (0,9,0)) / 4 =
// (6.75, 6.75, 0). A face's point is its centre, 9 along its axis.
TEST(CatmullClark, CubeOfQuadsExactPositions) {
  const HalfedgeMesh original = build_halfedge_mesh(scaled(make_cube_quads(), 18.0));
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(catmull_clark_subdivide(mesh));
  for (uint32_t i = 0; i < 8; ++i) {
    const glm::dvec3 p = original.position(V(i));
    EXPECT_EQ(mesh.position(V(i)), glm::dvec3(sign(p.x) * 5.0, sign(p.y) * 5.0, sign(p.z) * 5.0)) << "v" << i;
  }
  for (EdgeId e : original.edges()) {
    const HalfedgeId h = original.halfedge(e);
    const glm::dvec3 a = original.position(original.vertex(h));
    const glm::dvec3 b = original.position(original.vertex(original.twin(h)));
    glm::dvec3 expected;
    for (int k = 0; k < 3; ++k) expected[k] = a[k] == b[k] ? sign(a[k]) * 6.75 : 0.0;
    EXPECT_EQ(mesh.position(V(8 + e.index)), expected) << "e" << e.index;
  }
  for (FaceId f : original.faces()) {
    glm::dvec3 sum(0.0);
    original.for_each_face_halfedge(f, [&](HalfedgeId h) { sum += original.position(original.vertex(h)); });
    glm::dvec3 expected;
    for (int k = 0; k < 3; ++k) expected[k] = sum[k] == 0.0 ? 0.0 : sign(sum[k]) * 9.0;
    EXPECT_EQ(mesh.position(face_vertex(original, f.slot())), expected) << "f" << f.slot();
  }
}

// The cube [-1, 1]^3: the corner (1,1,1) goes to (5/9, 5/9, 5/9), edge points to (3/4, 3/4, 0), face points to the
// face centres.
TEST(CatmullClark, UnitCubeCornerGoesToFiveNinths) {
  const HalfedgeMesh original = build_halfedge_mesh(scaled(make_cube_quads(), 2.0));
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(catmull_clark_subdivide(mesh));
  for (uint32_t i = 0; i < 8; ++i) {
    const glm::dvec3 p = original.position(V(i));
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(mesh.position(V(i))[k], p[k] * 5.0 / 9.0) << "v" << i;
  }
  // make_cube_quads numbers vertex i at x = i & 1, y = i >> 1 & 1, z = i >> 2 & 1: v0 = (-1,-1,-1), v1 = (1,-1,-1).
  EXPECT_EQ(mesh.position(edge_vertex(original, 0, 1)), glm::dvec3(0.0, -0.75, -0.75));
  EXPECT_EQ(mesh.position(edge_vertex(original, 6, 7)), glm::dvec3(0.0, 0.75, 0.75));
}

TEST(CatmullClark, CubeCountsAndValidity) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  ASSERT_TRUE(catmull_clark_subdivide(mesh));
  EXPECT_EQ(mesh.num_vertices(), 8u + 12u + 6u);
  EXPECT_EQ(mesh.num_edges(), 2u * 12u + 24u);
  EXPECT_EQ(mesh.num_faces(), 24u);
  EXPECT_EQ(mesh.num_boundaries(), 0u);
  EXPECT_TRUE(all_quads(mesh));
  EXPECT_TRUE(valid(mesh));
  ASSERT_TRUE(catmull_clark_subdivide(mesh));
  EXPECT_EQ(mesh.num_vertices(), 26u + 48u + 24u);
  EXPECT_EQ(mesh.num_faces(), 96u);
  EXPECT_TRUE(valid(mesh));
}

// 2 x 2 quads over [0,2]^2, vertex i at (i % 3, i / 3) with heights z(v1) = 4, z(v4) = 8 and 0 elsewhere.
//   faces A = (v0 v1 v4 v3) point (0.5, 0.5, 3), B = (v1 v2 v5 v4) (1.5, 0.5, 3), C = (v3 v4 v7 v6) (0.5, 1.5, 2),
//   D = (v4 v5 v8 v7) (1.5, 1.5, 2).
//   v4 (interior, n = 4): F = (1, 1, 2.5); midpoints to v1, v5, v7, v3: (1,.5,6), (1.5,1,4), (1,1.5,4), (.5,1,4), so
//     R = (1, 1, 4.5); (F + 2R + P) / 4 = ((1,1,2.5) + (2,2,9) + (1,1,8)) / 4 = (1, 1, 4.875).
//   v1 (boundary, neighbours v0, v2): 3/4 (1,0,4) + 1/8 ((0,0,0) + (2,0,0)) = (1, 0, 3).
//   v0 (corner, neighbours v1, v3): 1/8 ((1,0,4) + (0,1,0)) = (0.125, 0.125, 0.5).
//   v2 (corner, neighbours v1, v5): 3/4 (2,0,0) + 1/8 ((1,0,4) + (2,1,0)) = (1.875, 0.125, 0.5).
//   boundary edge v0-v1: (0.5, 0, 2); interior edge v1-v4 (faces A, B): ((1,0,4) + (1,1,8) + (.5,.5,3) + (1.5,.5,3))
//     / 4 = (1, 0.5, 4.5); interior edge v3-v4 (faces A, C): ((0,1,0) + (1,1,8) + (.5,.5,3) + (.5,1.5,2)) / 4 =
//     (0.5, 1, 3.25).
PolygonMesh quad_grid_with_heights() {
  PolygonMesh grid;
  for (uint32_t i = 0; i < 9; ++i) grid.add_vertex(glm::dvec3(i % 3, i / 3, 0.0));
  grid.positions[1].z = 4.0;
  grid.positions[4].z = 8.0;
  grid.add_face({0, 1, 4, 3});
  grid.add_face({1, 2, 5, 4});
  grid.add_face({3, 4, 7, 6});
  grid.add_face({4, 5, 8, 7});
  return grid;
}

TEST(CatmullClark, GridWithBoundaryExactPositions) {
  const HalfedgeMesh original = build_halfedge_mesh(quad_grid_with_heights());
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(catmull_clark_subdivide(mesh));
  EXPECT_EQ(mesh.position(V(4)), glm::dvec3(1.0, 1.0, 4.875));
  EXPECT_EQ(mesh.position(V(1)), glm::dvec3(1.0, 0.0, 3.0));
  EXPECT_EQ(mesh.position(V(0)), glm::dvec3(0.125, 0.125, 0.5));
  EXPECT_EQ(mesh.position(V(2)), glm::dvec3(1.875, 0.125, 0.5));
  EXPECT_EQ(mesh.position(edge_vertex(original, 0, 1)), glm::dvec3(0.5, 0.0, 2.0));
  EXPECT_EQ(mesh.position(edge_vertex(original, 1, 4)), glm::dvec3(1.0, 0.5, 4.5));
  EXPECT_EQ(mesh.position(edge_vertex(original, 3, 4)), glm::dvec3(0.5, 1.0, 3.25));
  EXPECT_EQ(mesh.position(face_vertex(original, 0)), glm::dvec3(0.5, 0.5, 3.0));
  EXPECT_EQ(mesh.position(face_vertex(original, 3)), glm::dvec3(1.5, 1.5, 2.0));
  // V + E + F = 9 + 12 + 4 vertices; 16 quads; 2E + 16 = 40 edges; still one boundary loop.
  EXPECT_EQ(mesh.num_vertices(), 25u);
  EXPECT_EQ(mesh.num_edges(), 40u);
  EXPECT_EQ(mesh.num_faces(), 16u);
  EXPECT_EQ(mesh.num_boundaries(), 1u);
  EXPECT_TRUE(all_quads(mesh));
  EXPECT_TRUE(valid(mesh));
}

// A tetrahedron with corners a = (9,9,9), b = (9,-9,-9), c = (-9,9,-9), d = (-9,-9,9) (they sum to 0, so the face
// missing a corner has point -corner/3). For a: F = -(b + c + d)/9 = a/9, R = (3a + b + c + d)/6 = a/3, n = 3:
// (F + 2R)/3 = 7a/27. Edge a-b (faces missing c and d): (a + b - (c + d)/3)/4 = (a + b)/3 = (6, 0, 0).
TEST(CatmullClark, TetrahedronOfTrianglesBecomesQuads) {
  PolygonMesh tet;
  tet.add_vertex({9, 9, 9});
  tet.add_vertex({9, -9, -9});
  tet.add_vertex({-9, 9, -9});
  tet.add_vertex({-9, -9, 9});
  tet.add_face({0, 1, 2});
  tet.add_face({0, 3, 1});
  tet.add_face({0, 2, 3});
  tet.add_face({1, 3, 2});
  const HalfedgeMesh original = build_halfedge_mesh(tet);
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(catmull_clark_subdivide(mesh));
  EXPECT_TRUE(testing::near(mesh.position(V(0)), glm::dvec3(7.0 / 3.0), 1e-13));
  EXPECT_TRUE(testing::near(mesh.position(V(3)), glm::dvec3(-7.0 / 3.0, -7.0 / 3.0, 7.0 / 3.0), 1e-13));
  EXPECT_EQ(mesh.position(edge_vertex(original, 0, 1)), glm::dvec3(6.0, 0.0, 0.0));
  EXPECT_EQ(mesh.position(face_vertex(original, 3)), glm::dvec3(-3.0, -3.0, -3.0));  // f3 misses a
  EXPECT_EQ(mesh.num_vertices(), 4u + 6u + 4u);
  EXPECT_EQ(mesh.num_faces(), 12u);
  EXPECT_TRUE(all_quads(mesh));
  EXPECT_TRUE(valid(mesh));
}

// One pentagon, all boundary: 5 quads around its centroid; the corners follow the boundary rule.
TEST(CatmullClark, LonePentagon) {
  PolygonMesh pentagon;
  for (int i = 0; i < 5; ++i) {
    const double angle = 2.0 * 3.14159265358979323846 * i / 5.0;
    pentagon.add_vertex({std::cos(angle), std::sin(angle), 0.0});
  }
  pentagon.add_face({0, 1, 2, 3, 4});
  const HalfedgeMesh original = build_halfedge_mesh(pentagon);
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(catmull_clark_subdivide(mesh));
  EXPECT_EQ(mesh.num_vertices(), 11u);
  EXPECT_EQ(mesh.num_edges(), 15u);
  EXPECT_EQ(mesh.num_faces(), 5u);
  EXPECT_TRUE(all_quads(mesh));
  EXPECT_TRUE(valid(mesh));
  const glm::dvec3 expected =
      0.75 * original.position(V(0)) + 0.125 * (original.position(V(1)) + original.position(V(4)));
  EXPECT_TRUE(testing::near(mesh.position(V(0)), expected, 1e-15));
  EXPECT_TRUE(testing::near(mesh.position(face_vertex(original, 0)), glm::dvec3(0.0), 1e-15));
}

// The phases: phase 1 changes nothing, phase 2 gives the refined mesh with every original vertex where it was and
// new ones at midpoints and centroids, phase 3 gives the one call's mesh exactly.
void expect_phases_match(const HalfedgeMesh& original) {
  HalfedgeMesh one_call = original;
  ASSERT_TRUE(catmull_clark_subdivide(one_call));
  HalfedgeMesh phased = original;
  OpResult<CatmullClarkState> state = catmull_clark_compute_points(phased);
  ASSERT_TRUE(state.ok()) << state.check.reason;
  EXPECT_TRUE(phased.same_as(original));
  catmull_clark_refine(phased, state.value);
  EXPECT_TRUE(valid(phased));
  EXPECT_EQ(phased.num_vertices(), original.num_vertices() + original.num_edges() + original.num_faces());
  for (VertexId v : original.vertices()) EXPECT_EQ(phased.position(v), original.position(v));
  for (EdgeId e : original.edges()) {
    const HalfedgeId h = original.halfedge(e);
    const glm::dvec3 mid =
        0.5 * (original.position(original.vertex(h)) + original.position(original.vertex(original.twin(h))));
    EXPECT_EQ(phased.position(V(state.value.layout.edge_vertex[e.index])), mid);
  }
  catmull_clark_commit_positions(phased, state.value);
  EXPECT_TRUE(valid(phased));
  EXPECT_TRUE(phased.same_as(one_call));
  HalfedgeMesh by_phases = original;
  ASSERT_TRUE(catmull_clark_subdivide_by_phases(by_phases));
  EXPECT_TRUE(by_phases.same_as(one_call));
}

TEST(CatmullClark, PhasesGiveTheOneCallsMesh) {
  expect_phases_match(build_halfedge_mesh(make_cube_quads()));
  expect_phases_match(build_halfedge_mesh(quad_grid_with_heights()));
  expect_phases_match(build_halfedge_mesh(make_icosahedron()));
  expect_phases_match(build_halfedge_mesh(make_grid(3, 2)));
  // Dead slots: a collapse leaves dead vertices, edges and faces the refinement must skip.
  HalfedgeMesh collapsed = build_halfedge_mesh(make_torus(8, 6));
  ASSERT_TRUE(collapse(collapsed, EdgeId(5)).ok());
  expect_phases_match(collapsed);
}

TEST(CatmullClark, TwoLevelsInOneCallEqualTwoPhasedLevels) {
  const HalfedgeMesh original = build_halfedge_mesh(quad_grid_with_heights());
  HalfedgeMesh one_call = original;
  ASSERT_TRUE(catmull_clark_subdivide(one_call, 2));
  HalfedgeMesh phased = original;
  ASSERT_TRUE(catmull_clark_subdivide_by_phases(phased));
  ASSERT_TRUE(catmull_clark_subdivide_by_phases(phased));
  EXPECT_TRUE(phased.same_as(one_call));
  EXPECT_EQ(one_call.num_faces(), 64u);
}

TEST(CatmullClark, BrokenMeshIsRefusedAndUnchanged) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  mesh.set_next(HalfedgeId(0), HalfedgeId(0));
  const HalfedgeMesh before = mesh;
  const Check done = catmull_clark_subdivide(mesh);
  EXPECT_FALSE(done);
  EXPECT_NE(done.reason.find("Catmull-Clark subdivision needs a valid mesh"), std::string::npos) << done.reason;
  EXPECT_TRUE(mesh.same_as(before));
  EXPECT_FALSE(catmull_clark_compute_points(mesh).ok());
  EXPECT_FALSE(catmull_clark_subdivide_by_phases(mesh));
  EXPECT_TRUE(mesh.same_as(before));
}

}  // namespace
}  // namespace meshedit
