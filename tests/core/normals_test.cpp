// Face normals, face areas and area-weighted vertex normals: exact values worked out by hand on the
// shared fixtures, the case where area weighting differs from plain averaging, n-gons, zero-area faces,
// and broken meshes (zero vectors, no hang).
#include <cmath>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/primitives.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

constexpr double kTol = 1e-12;

::testing::AssertionResult near(const glm::dvec3& actual, const glm::dvec3& expected, double tol = kTol) {
  return testing::near(actual, expected, tol);
}

VertexId V(uint32_t i) { return VertexId(i); }
FaceId F(uint32_t i) { return FaceId::face(i); }

TEST(Normals, TetrahedronFacesPointAwayFromTheOppositeVertex) {
  const HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  // Faces (0,1,2) (0,3,1) (0,2,3) (1,3,2) are opposite v3, v2, v1, v0; a regular tetrahedron centred at
  // the origin has each face normal equal to minus the opposite vertex's direction.
  const uint32_t opposite[4] = {3, 2, 1, 0};
  for (uint32_t f = 0; f < 4; ++f) {
    SCOPED_TRACE(f);
    EXPECT_TRUE(near(face_normal(m, F(f)), -m.position(V(opposite[f])) / std::sqrt(3.0)));
    // Edge length 2 sqrt(2): area = sqrt(3)/4 * 8.
    EXPECT_NEAR(face_area(m, F(f)), 2.0 * std::sqrt(3.0), kTol);
  }
  // Face 0 worked out: cross((0,-2,-2), (-2,0,-2)) = (4,4,-4).
  EXPECT_TRUE(near(face_normal(m, F(0)), glm::dvec3(1, 1, -1) / std::sqrt(3.0)));
}

TEST(Normals, TetrahedronVertexNormalsAreRadial) {
  const HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  for (uint32_t v = 0; v < 4; ++v) {
    SCOPED_TRACE(v);
    EXPECT_TRUE(near(vertex_normal(m, V(v)), m.position(V(v)) / std::sqrt(3.0)));
  }
}

TEST(Normals, CubeVertexNormalsFollowItsTriangulation) {
  // make_cube splits each side quad (q0,q1,q2,q3) into (q0,q1,q2) and (q0,q2,q3); every triangle has
  // area 1/2. Per vertex, the triangles it lies in (side normal x area):
  //   v0: both of z-, y-, x-          -> (-1,-1,-1)
  //   v1: (0,3,1) z-, (0,1,5) y-, both x+  -> (1, -1/2, -1/2)
  //   v2: (0,2,3) z-, both y+, (0,6,2) x-  -> (-1/2, 1, -1/2)
  //   v3: both z-, (2,7,3) y+, (1,3,7) x+  -> (1/2, 1/2, -1)
  //   v4: both z+, (0,5,4) y-, (0,4,6) x-  -> (-1/2, -1/2, 1)
  //   v5: (4,5,7) z+, both y-, (1,7,5) x+  -> (1/2, -1, 1/2)
  //   v6: (4,7,6) z+, (2,6,7) y+, both x-  -> (-1, 1/2, 1/2)
  //   v7: both of z+, y+, x+          -> (1, 1, 1)
  const HalfedgeMesh m = build_halfedge_mesh(make_cube());
  const double s3 = std::sqrt(3.0), s6 = std::sqrt(6.0);
  const glm::dvec3 expected[8] = {glm::dvec3(-1, -1, -1) / s3, glm::dvec3(2, -1, -1) / s6, glm::dvec3(-1, 2, -1) / s6,
                                  glm::dvec3(1, 1, -2) / s6,   glm::dvec3(-1, -1, 2) / s6, glm::dvec3(1, -2, 1) / s6,
                                  glm::dvec3(-2, 1, 1) / s6,   glm::dvec3(1, 1, 1) / s3};
  const std::vector<glm::dvec3> all = vertex_normals(m);
  ASSERT_EQ(all.size(), 8u);
  for (uint32_t v = 0; v < 8; ++v) {
    SCOPED_TRACE(v);
    EXPECT_TRUE(near(vertex_normal(m, V(v)), expected[v]));
    EXPECT_TRUE(near(all[v], expected[v]));
  }
  for (FaceId f : m.faces()) EXPECT_NEAR(face_area(m, f), 0.5, kTol) << format_id(f);
  // Face 0 is (0,2,3) on the z = -0.5 side.
  EXPECT_TRUE(near(face_normal(m, F(0)), {0, 0, -1}));
}

TEST(Normals, CubeQuadsUseNewellForNgons) {
  const HalfedgeMesh m = build_halfedge_mesh(make_cube_quads());
  // Sides in make_cube_quads order: z-, z+, y-, y+, x-, x+; each a unit square.
  const glm::dvec3 expected[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  const std::vector<glm::dvec3> all = face_normals(m);
  ASSERT_EQ(all.size(), 6u);
  for (uint32_t f = 0; f < 6; ++f) {
    SCOPED_TRACE(f);
    EXPECT_TRUE(near(face_normal(m, F(f)), expected[f]));
    EXPECT_TRUE(near(all[f], expected[f]));
    EXPECT_NEAR(face_area(m, F(f)), 1.0, kTol);
  }
  // Each corner touches three unit squares, one per axis: the normal is the corner's own direction.
  // (Unlike the triangulated cube, where v1 gets (2,-1,-1)/sqrt(6).)
  for (uint32_t v = 0; v < 8; ++v) {
    SCOPED_TRACE(v);
    EXPECT_TRUE(near(vertex_normal(m, V(v)), 2.0 * m.position(V(v)) / std::sqrt(3.0)));
  }
}

TEST(Normals, PentagonFarFromTheOriginHasExactNormalAndArea) {
  PolygonMesh p;
  const glm::dvec3 offset(1000.0, -2000.0, 5.0);
  for (int i = 0; i < 5; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 5.0;
    p.add_vertex(offset + glm::dvec3(std::cos(a), std::sin(a), 0.0));
  }
  p.add_face({0, 1, 2, 3, 4});
  const HalfedgeMesh m = build_halfedge_mesh(p);
  EXPECT_TRUE(near(face_normal(m, F(0)), {0, 0, 1}));
  // A regular n-gon of circumradius 1 has area n/2 sin(2 pi / n).
  EXPECT_NEAR(face_area(m, F(0)), 2.5 * std::sin(2.0 * std::numbers::pi / 5.0), 1e-10);
  for (uint32_t v = 0; v < 5; ++v) EXPECT_TRUE(near(vertex_normal(m, V(v)), {0, 0, 1})) << v;
  // The boundary loop is skipped: b0 is not part of any vertex normal, but as a polygon it faces down.
  EXPECT_TRUE(near(face_normal(m, FaceId::boundary(0)), {0, 0, -1}));
}

TEST(Normals, GridIsFlatEverywhereIncludingBoundaryAndCorners) {
  const HalfedgeMesh m = build_halfedge_mesh(make_grid(3, 2));
  const std::vector<glm::dvec3> all = vertex_normals(m);
  ASSERT_EQ(all.size(), 12u);
  for (uint32_t v = 0; v < 12; ++v) {
    SCOPED_TRACE(v);
    EXPECT_TRUE(near(vertex_normal(m, V(v)), {0, 0, 1}));
    EXPECT_TRUE(near(all[v], {0, 0, 1}));
  }
  // Corner v3 = (3,0) lies in a single triangle; corner v0 in two.
  EXPECT_TRUE(m.is_boundary(V(3)));
  EXPECT_EQ(m.degree(V(3)), 2u);
  for (FaceId f : m.faces()) {
    EXPECT_TRUE(near(face_normal(m, f), {0, 0, 1})) << format_id(f);
    EXPECT_NEAR(face_area(m, f), 0.5, kTol) << format_id(f);
  }
}

TEST(Normals, FlatFanAndCone) {
  {
    const HalfedgeMesh m = build_halfedge_mesh(make_fan(7));
    for (uint32_t v = 0; v < 8; ++v) EXPECT_TRUE(near(vertex_normal(m, V(v)), {0, 0, 1})) << v;
  }
  // A square cone: centre lifted to (0,0,1), rim (1,0,0) (0,1,0) (-1,0,0) (0,-1,0).
  // Face (0,1,2): cross((1,0,-1), (0,1,-1)) = (1,1,1); face (0,4,1): cross((0,-1,-1), (1,0,-1)) = (1,-1,1).
  // All four faces have the same area, so v1 = normalize((1,1,1) + (1,-1,1)) = (1,0,1)/sqrt(2) and the
  // apex sums the four (+-1,+-1,1) to (0,0,4).
  PolygonMesh p = make_fan(4);
  p.positions[0] = {0, 0, 1};
  const HalfedgeMesh m = build_halfedge_mesh(p);
  const double s2 = std::sqrt(2.0);
  EXPECT_TRUE(near(vertex_normal(m, V(0)), {0, 0, 1}));
  EXPECT_TRUE(near(vertex_normal(m, V(1)), glm::dvec3(1, 0, 1) / s2));
  EXPECT_TRUE(near(vertex_normal(m, V(2)), glm::dvec3(0, 1, 1) / s2));
  EXPECT_TRUE(near(vertex_normal(m, V(3)), glm::dvec3(-1, 0, 1) / s2));
  EXPECT_TRUE(near(vertex_normal(m, V(4)), glm::dvec3(0, -1, 1) / s2));
  EXPECT_TRUE(near(face_normal(m, F(0)), glm::dvec3(1, 1, 1) / std::sqrt(3.0)));
  EXPECT_NEAR(face_area(m, F(0)), std::sqrt(3.0) / 2.0, kTol);
}

TEST(Normals, AreaWeightingDiffersFromAveragingUnitNormals) {
  // Two triangles sharing the edge v0-v1: (0,1,2) in the z = 0 plane, area 1/2, normal (0,0,1);
  // (1,0,3) in the y = 0 plane, cross((-1,0,0), (-1,0,-2)) = (0,-2,0): area 1, normal (0,-1,0).
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -2}};
  p.add_face({0, 1, 2});
  p.add_face({1, 0, 3});
  const HalfedgeMesh m = build_halfedge_mesh(p);
  EXPECT_NEAR(face_area(m, F(0)), 0.5, kTol);
  EXPECT_NEAR(face_area(m, F(1)), 1.0, kTol);
  EXPECT_TRUE(near(face_normal(m, F(1)), {0, -1, 0}));

  // Area-weighted: 1/2 (0,0,1) + 1 (0,-1,0) = (0,-1,1/2) -> (0,-2,1)/sqrt(5).
  const glm::dvec3 weighted = glm::dvec3(0, -2, 1) / std::sqrt(5.0);
  // Plain average of unit normals: (0,-1,1)/sqrt(2).
  const glm::dvec3 naive = glm::dvec3(0, -1, 1) / std::sqrt(2.0);
  EXPECT_TRUE(near(vertex_normal(m, V(0)), weighted));
  EXPECT_TRUE(near(vertex_normal(m, V(1)), weighted));
  EXPECT_GT(glm::length(weighted - naive), 0.1);
  EXPECT_FALSE(near(vertex_normal(m, V(0)), naive, 1e-3));
  EXPECT_TRUE(near(vertex_normals(m)[0], weighted));
}

TEST(Normals, ZeroAreaFaceGivesZeroAndDoesNotDisturbItsNeighbours) {
  // f1 = (2,1,3) is collinear: v3 = (2,-1) lies on the line x + y = 1 through v1 and v2.
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({2, 1, 3});
  const HalfedgeMesh m = build_halfedge_mesh(p);
  EXPECT_EQ(face_normal(m, F(1)), glm::dvec3(0.0));
  EXPECT_EQ(face_area(m, F(1)), 0.0);
  EXPECT_EQ(vertex_normal(m, V(3)), glm::dvec3(0.0));  // no area around it
  EXPECT_EQ(vertex_normals(m)[3], glm::dvec3(0.0));
  EXPECT_TRUE(near(vertex_normal(m, V(1)), {0, 0, 1}));
  EXPECT_TRUE(near(vertex_normal(m, V(2)), {0, 0, 1}));
}

TEST(Normals, NearlyCollinearRoundingNoiseIsNotADirection) {
  // p, p + d, p + 2d with coordinates that are not exact in binary: the cross products leave rounding
  // noise, which must still read as zero area.
  const glm::dvec3 base(0.1, 0.2, 0.3), d(0.1, 0.7, 0.3);
  PolygonMesh p;
  p.positions = {base, base + d, base + 2.0 * d};
  p.add_face({0, 1, 2});
  const HalfedgeMesh m = build_halfedge_mesh(p);
  EXPECT_EQ(face_normal(m, F(0)), glm::dvec3(0.0));
  EXPECT_EQ(face_area(m, F(0)), 0.0);
  for (uint32_t v = 0; v < 3; ++v) EXPECT_EQ(vertex_normal(m, V(v)), glm::dvec3(0.0)) << v;
}

TEST(Normals, BrokenFaceCycleGivesZeroWithoutHanging) {
  HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  // f0 is h0 h1 h2 leaving v0 v1 v2; h1 -> h1 makes the walk from h0 never return.
  m.set_next(HalfedgeId(1), HalfedgeId(1));
  EXPECT_EQ(face_normal(m, F(0)), glm::dvec3(0.0));
  EXPECT_EQ(face_area(m, F(0)), 0.0);
  // Every vertex of f0 has f0 in its fan, so its normal is unknown: zero.
  const std::vector<glm::dvec3> all = vertex_normals(m);
  for (uint32_t v = 0; v < 3; ++v) {
    EXPECT_EQ(vertex_normal(m, V(v)), glm::dvec3(0.0)) << v;
    EXPECT_EQ(all[v], glm::dvec3(0.0)) << v;
  }
  // Untouched faces keep their normals.
  EXPECT_TRUE(near(face_normal(m, F(3)), -m.position(V(0)) / std::sqrt(3.0)));
}

TEST(Normals, BrokenPointersGiveZeroVectors) {
  {
    HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
    m.set_twin(HalfedgeId(0), HalfedgeId());  // v0's fan cannot go past h0
    EXPECT_EQ(vertex_normal(m, V(0)), glm::dvec3(0.0));
    EXPECT_EQ(vertex_normals(m)[0], glm::dvec3(0.0));
  }
  {
    HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
    m.set_vertex(HalfedgeId(0), VertexId(999));  // out of range: must not be read
    EXPECT_EQ(face_normal(m, F(0)), glm::dvec3(0.0));
    EXPECT_EQ(face_normals(m)[0], glm::dvec3(0.0));
  }
  {
    HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
    m.set_face(HalfedgeId(3), FaceId::face(77));  // v0's fan meets a face that does not exist
    EXPECT_EQ(vertex_normal(m, V(0)), glm::dvec3(0.0));
    EXPECT_EQ(vertex_normals(m)[0], glm::dvec3(0.0));
  }
  {
    HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
    m.set_halfedge(V(2), HalfedgeId(4242));
    EXPECT_EQ(vertex_normal(m, V(2)), glm::dvec3(0.0));
  }
  const HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  EXPECT_EQ(vertex_normal(m, V(4)), glm::dvec3(0.0));  // past the end
  EXPECT_EQ(face_normal(m, F(4)), glm::dvec3(0.0));
}

TEST(Normals, WholeMeshVersionsMatchPerElementExactlyAndZeroDeadSlots) {
  PolygonMesh p = make_torus(12, 7);
  p.add_vertex({5, 5, 5});  // unused: a dead vertex slot
  const HalfedgeMesh m = build_halfedge_mesh(p);
  const std::vector<glm::dvec3> vn = vertex_normals(m);
  const std::vector<glm::dvec3> fn = face_normals(m);
  ASSERT_EQ(vn.size(), m.vertex_capacity());
  ASSERT_EQ(fn.size(), m.face_capacity());
  EXPECT_FALSE(m.alive(V(84)));
  EXPECT_EQ(vn[84], glm::dvec3(0.0));
  for (VertexId v : m.vertices()) {
    EXPECT_EQ(vn[v.index], vertex_normal(m, v)) << format_id(v);
    EXPECT_NEAR(glm::length(vn[v.index]), 1.0, kTol) << format_id(v);
  }
  for (FaceId f : m.faces()) EXPECT_EQ(fn[f.slot()], face_normal(m, f)) << format_id(f);
  // Torus outer equator vertex (ring 0, side 0) at (1.35, 0, 0). The diagonals run (i,j)-(i+1,j+1), so
  // no mirror maps the triangulation to itself, but the half turn about the x axis (i,j) -> (-i,-j) does
  // and fixes v0: its normal is +x.
  EXPECT_TRUE(near(vn[0], {1, 0, 0}, 1e-12));
}

}  // namespace
}  // namespace meshedit
