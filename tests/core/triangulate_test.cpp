// Triangulation: non-convex, star and nearly planar polygons are covered exactly by triangles that keep the
// polygon's orientation; quad meshes become triangle meshes that build, validate and Loop-subdivide.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/triangulate.h"
#include "core/validate.h"

namespace meshedit {
namespace {

// Signed area of triangle abc seen from `normal` (unit): positive when abc turns counter-clockwise around it.
double signed_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& normal) {
  return 0.5 * glm::dot(glm::cross(b - a, c - a), normal);
}

// Whether 2D point (x, y) is inside the polygon's xy projection (even-odd rule).
bool inside_xy(const std::vector<glm::dvec3>& polygon, double x, double y) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::dvec3& a = polygon[i];
    const glm::dvec3& b = polygon[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

// Checks a planar polygon in the z = 0 plane: n - 2 triangles using each corner number in range, every triangle
// counter-clockwise with positive area and its centroid inside the polygon, areas summing to the polygon's.
void expect_exact_cover(const std::vector<glm::dvec3>& polygon, double polygon_area) {
  bool fan = true;
  const std::vector<uint32_t> t = triangulate_polygon(polygon, &fan);
  EXPECT_FALSE(fan);
  ASSERT_EQ(t.size(), 3 * (polygon.size() - 2));
  double sum = 0;
  for (size_t i = 0; i < t.size(); i += 3) {
    ASSERT_LT(t[i], polygon.size());
    ASSERT_LT(t[i + 1], polygon.size());
    ASSERT_LT(t[i + 2], polygon.size());
    const glm::dvec3 &a = polygon[t[i]], &b = polygon[t[i + 1]], &c = polygon[t[i + 2]];
    const double area = signed_area(a, b, c, {0, 0, 1});
    EXPECT_GT(area, 1e-9) << "triangle " << i / 3 << " is flipped or empty";
    const glm::dvec3 centroid = (a + b + c) / 3.0;
    EXPECT_TRUE(inside_xy(polygon, centroid.x, centroid.y)) << "triangle " << i / 3 << " is outside";
    sum += area;
  }
  EXPECT_NEAR(sum, polygon_area, 1e-12);
}

TEST(Triangulate, LShapedHexagonIsCoveredExactly) {
  // Starting at (2, 1) so that a fan from corner 0 would cross outside: corner 1 at (1, 1) is the reflex one.
  const std::vector<glm::dvec3> l = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
  expect_exact_cover(l, 3.0);
  // No triangle may join corners 0 and 2 without corner 1: that diagonal runs outside the polygon.
  const std::vector<uint32_t> t = triangulate_polygon(l);
  for (size_t i = 0; i < t.size(); i += 3) {
    const std::set<uint32_t> corners = {t[i], t[i + 1], t[i + 2]};
    EXPECT_FALSE(corners.count(0) && corners.count(2) && !corners.count(1));
  }
}

TEST(Triangulate, FivePointedStarIsCoveredExactly) {
  std::vector<glm::dvec3> star;
  for (int i = 0; i < 10; ++i) {
    const double angle = M_PI / 2 + i * M_PI / 5;
    const double r = i % 2 == 0 ? 2.0 : 0.8;
    star.push_back({r * std::cos(angle), r * std::sin(angle), 0});
  }
  double area = 0;  // shoelace
  for (size_t i = 0; i < star.size(); ++i) {
    const glm::dvec3& a = star[i];
    const glm::dvec3& b = star[(i + 1) % star.size()];
    area += 0.5 * (a.x * b.y - b.x * a.y);
  }
  ASSERT_GT(area, 0);
  expect_exact_cover(star, area);
}

TEST(Triangulate, TiltedStarKeepsItsOrientation) {
  // The same star in a tilted plane, corners given clockwise seen from +z: triangles face the polygon's way.
  const glm::dvec3 u = glm::normalize(glm::dvec3(1, 0, 1)), v(0, 1, 0);
  std::vector<glm::dvec3> star;
  for (int i = 0; i < 10; ++i) {
    const double angle = -(M_PI / 2 + i * M_PI / 5);
    const double r = i % 2 == 0 ? 2.0 : 0.8;
    star.push_back(3.0 + r * std::cos(angle) * u + r * std::sin(angle) * v);
  }
  const glm::dvec3 normal = glm::normalize(newell_normal(star));
  EXPECT_NEAR(glm::dot(normal, glm::cross(v, u)), 1.0, 1e-12);  // clockwise in (u, v): the normal is v x u
  const std::vector<uint32_t> t = triangulate_polygon(star);
  ASSERT_EQ(t.size(), 24u);
  double sum = 0;
  for (size_t i = 0; i < t.size(); i += 3) {
    const double a = signed_area(star[t[i]], star[t[i + 1]], star[t[i + 2]], normal);
    EXPECT_GT(a, 1e-9);
    sum += a;
  }
  EXPECT_NEAR(sum, 0.5 * glm::length(newell_normal(star)), 1e-12);
}

TEST(Triangulate, NearlyPlanarQuadGivesTwoTrianglesFacingUp) {
  PolygonMesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0.01}, {1, 1, 0}, {0, 1, 0.01}};
  quad.add_face({0, 1, 2, 3});
  TriangulationReport report;
  const PolygonMesh tris = triangulate(quad, &report);
  EXPECT_EQ(report.polygons_split, 1u);
  EXPECT_EQ(report.triangles_made, 2u);
  EXPECT_EQ(report.fan_fallbacks, 0u);
  ASSERT_EQ(tris.num_faces(), 2u);
  EXPECT_EQ(tris.positions, quad.positions);
  for (size_t f = 0; f < 2; ++f) {
    const auto c = tris.face(f);
    const glm::dvec3 n =
        glm::cross(tris.positions[c[1]] - tris.positions[c[0]], tris.positions[c[2]] - tris.positions[c[0]]);
    EXPECT_GT(n.z, 0.0);
  }
  // Each triangle's corners appear in the quad's cyclic order.
  const std::vector<uint32_t> cyclic = {0, 1, 2, 3, 0, 1, 2, 3};
  for (size_t f = 0; f < 2; ++f) {
    const auto c = tris.face(f);
    const auto at = [&](uint32_t x) { return (x - c[0] + 4) % 4; };
    EXPECT_LT(at(c[1]), at(c[2])) << "face " << f;
  }
}

TEST(Triangulate, CollinearCornerMakesNoEmptyTriangle) {
  // A square with an extra corner halfway along its bottom edge.
  const std::vector<glm::dvec3> square = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  expect_exact_cover(square, 4.0);
}

TEST(Triangulate, TrianglesAndShortFacesAreKeptAsTheyAre) {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({0, 2});
  const PolygonMesh t = triangulate(p);
  EXPECT_EQ(t.indices, p.indices);
  EXPECT_EQ(t.face_offsets, p.face_offsets);
}

TEST(Triangulate, CubeOfQuadsBecomesTwelveTrianglesThatBuildAndSubdivide) {
  const PolygonMesh quads = make_cube_quads();
  const PolygonMesh tris = triangulate(quads);
  ASSERT_EQ(tris.num_faces(), 12u);
  EXPECT_EQ(tris.positions, quads.positions);
  for (size_t f = 0; f < 6; ++f) {
    // Quad f became triangles 2f and 2f+1, using only its corners, with the quad's normal.
    const auto q = quads.face(f);
    const std::set<uint32_t> corners(q.begin(), q.end());
    const std::vector<glm::dvec3> qp = {quads.positions[q[0]], quads.positions[q[1]], quads.positions[q[2]],
                                        quads.positions[q[3]]};
    const glm::dvec3 normal = glm::normalize(newell_normal(qp));
    double area = 0;
    for (size_t t = 2 * f; t < 2 * f + 2; ++t) {
      const auto c = tris.face(t);
      for (uint32_t i : c) EXPECT_TRUE(corners.count(i)) << "triangle " << t;
      area += signed_area(tris.positions[c[0]], tris.positions[c[1]], tris.positions[c[2]], normal);
    }
    EXPECT_NEAR(area, 1.0, 1e-12);
  }
  HalfedgeMesh mesh = build_halfedge_mesh(tris);
  EXPECT_TRUE(validate(mesh).ok());
  const Check subdivided = loop_subdivide(mesh);
  EXPECT_TRUE(subdivided.ok) << subdivided.reason;
  EXPECT_EQ(mesh.num_faces(), 48u);
}

// A closed quad torus with jittered, non-planar quads and one hexagon cap-like band: a stand-in for Suzanne.
PolygonMesh bumpy_quad_torus(uint32_t rings, uint32_t sides) {
  PolygonMesh p;
  for (uint32_t i = 0; i < rings; ++i) {
    for (uint32_t j = 0; j < sides; ++j) {
      const double a = 2 * M_PI * i / rings, b = 2 * M_PI * j / sides;
      const double r = 0.35 + 0.04 * std::sin(7.0 * i + 3.0 * j);
      p.add_vertex({(1 + r * std::cos(b)) * std::cos(a), (1 + r * std::cos(b)) * std::sin(a), r * std::sin(b)});
    }
  }
  for (uint32_t i = 0; i < rings; ++i) {
    for (uint32_t j = 0; j < sides; ++j) {
      const uint32_t i1 = (i + 1) % rings, j1 = (j + 1) % sides;
      p.add_face({i * sides + j, i1 * sides + j, i1 * sides + j1, i * sides + j1});
    }
  }
  return p;
}

TEST(Triangulate, BumpyQuadTorusBuildsValidatesAndKeepsNormals) {
  const PolygonMesh quads = bumpy_quad_torus(24, 12);
  TriangulationReport report;
  const PolygonMesh tris = triangulate(quads, &report);
  EXPECT_EQ(report.polygons_split, quads.num_faces());
  ASSERT_EQ(tris.num_faces(), 2 * quads.num_faces());
  for (size_t f = 0; f < quads.num_faces(); ++f) {
    const auto q = quads.face(f);
    std::vector<glm::dvec3> qp;
    for (uint32_t i : q) qp.push_back(quads.positions[i]);
    const glm::dvec3 normal = glm::normalize(newell_normal(qp));
    for (size_t t = 2 * f; t < 2 * f + 2; ++t) {
      const auto c = tris.face(t);
      EXPECT_GT(signed_area(tris.positions[c[0]], tris.positions[c[1]], tris.positions[c[2]], normal), 0.0);
    }
  }
  HalfedgeMesh mesh = build_halfedge_mesh(tris);
  EXPECT_TRUE(validate(mesh).ok());
  EXPECT_EQ(mesh.num_vertices(), quads.num_vertices());
  EXPECT_TRUE(loop_subdivide(mesh).ok);
}

// Two quads that share three corners (Suzanne, as Blender exports her, has such pairs): each may only be cut along a
// diagonal the other has not used, or the triangle of the three shared corners would be made twice.
TEST(Triangulate, QuadsSharingThreeCornersAreCutAlongDifferentDiagonals) {
  PolygonMesh polygons;
  // A fold along the path 0-1-2: two kites, one tilted up and one down, each able to take the diagonal 0-2.
  polygons.positions = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {1, -1, 1}, {1, -1, -1}};
  polygons.add_face({0, 1, 2, 3});
  polygons.add_face({2, 1, 0, 4});
  const PolygonMesh triangles = triangulate(polygons);
  ASSERT_EQ(triangles.num_faces(), 4u);
  std::set<std::set<uint32_t>> seen;
  for (size_t f = 0; f < triangles.num_faces(); ++f) {
    const std::span<const uint32_t> t = triangles.face(f);
    EXPECT_TRUE(seen.insert({t[0], t[1], t[2]}).second) << "triangle " << f << " repeats another";
  }
  const HalfedgeMesh mesh = build_halfedge_mesh(triangles);
  EXPECT_TRUE(validate(mesh).ok());
}

TEST(Triangulate, HalfedgeMeshOfQuadsIsReplacedByTriangles) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  const Check refused = can_loop_subdivide(mesh);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(refused.reason.find("mesh:triangulate()"), std::string::npos) << refused.reason;
  EXPECT_NE(refused.reason.find("Edit > Triangulate"), std::string::npos) << refused.reason;
  EXPECT_NE(refused.reason.find("meshedit triangulate IN -o OUT"), std::string::npos) << refused.reason;
  const OpResult<TriangulationReport> done = triangulate_mesh(mesh);
  ASSERT_TRUE(done.ok()) << done.check.reason;
  EXPECT_EQ(done.value.polygons_split, 6u);
  EXPECT_EQ(mesh.num_faces(), 12u);
  EXPECT_TRUE(validate(mesh).ok());
  const PolygonMesh back = to_polygon_mesh(mesh);
  EXPECT_EQ(back.positions, make_cube_quads().positions);
  for (FaceId f : mesh.faces()) EXPECT_EQ(mesh.degree(f), 3u);
}

TEST(Triangulate, BrokenHalfedgeMeshIsRefusedUnchanged) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  mesh.set_next(HalfedgeId(0), HalfedgeId(0));
  const HalfedgeMesh before = mesh;
  const OpResult<TriangulationReport> done = triangulate_mesh(mesh);
  EXPECT_FALSE(done.ok());
  EXPECT_EQ(done.check.reason.rfind("cannot triangulate: ", 0), 0u) << done.check.reason;
  EXPECT_TRUE(mesh.same_as(before));
}

TEST(Triangulate, TriangleMeshIsLeftUntouched) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  const HalfedgeMesh before = mesh;
  const uint64_t version = mesh.version();
  const OpResult<TriangulationReport> done = triangulate_mesh(mesh);
  ASSERT_TRUE(done.ok());
  EXPECT_EQ(done.value.polygons_split, 0u);
  EXPECT_TRUE(mesh.same_as(before));
  EXPECT_EQ(mesh.version(), version);
}

}  // namespace
}  // namespace meshedit
