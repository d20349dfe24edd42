// What the renderer draws of a mesh, built on the CPU (render/mesh_geometry.h): exact positions and
// ids on the cube and the grid, arrows inside their faces, and broken meshes that draw what they can.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/primitives.h"
#include "render/mesh_geometry.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::near;

glm::dvec3 d(const glm::vec3& v) { return glm::dvec3(v); }

// Barycentric coordinates of p in triangle (a, b, c), and p's distance from the triangle's plane.
struct Barycentric {
  double u, v, w, off_plane;
};
Barycentric barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double area2 = glm::dot(n, n);
  Barycentric out;
  out.u = glm::dot(glm::cross(c - b, p - b), n) / area2;
  out.v = glm::dot(glm::cross(a - c, p - c), n) / area2;
  out.w = glm::dot(glm::cross(b - a, p - a), n) / area2;
  out.off_plane = std::abs(glm::dot(p - a, n)) / std::sqrt(area2);
  return out;
}

TEST(MeshGeometry, CubeTrianglesAreTheFacesCornersWithTheirIds) {
  const PolygonMesh cube = make_cube();
  const HalfedgeMesh mesh = build_halfedge_mesh(cube);
  const MeshGeometry g = build_mesh_geometry(mesh);
  ASSERT_EQ(g.triangle_count(), 12u);
  ASSERT_EQ(g.triangle_corners.size(), 36u);
  for (uint32_t f = 0; f < 12; ++f) {
    EXPECT_EQ(g.triangle_faces[f], f);
    const auto corners = cube.face(f);
    for (uint32_t j = 0; j < 3; ++j) EXPECT_EQ(g.triangle_corners[3 * f + j], corners[j]) << "f" << f;
  }
  ASSERT_EQ(g.positions.size(), 8u);
  ASSERT_EQ(g.points.size(), 8u);
  for (uint32_t v = 0; v < 8; ++v) {
    const glm::dvec3 expected((v & 1) - 0.5, ((v >> 1) & 1) - 0.5, ((v >> 2) & 1) - 0.5);
    EXPECT_TRUE(near(d(g.positions[v]), expected, 0.0)) << "v" << v;
    EXPECT_EQ(g.points[v].vertex, v);
    EXPECT_TRUE(near(d(g.points[v].position), expected, 0.0));
    // Smooth normals are core's area-weighted ones, rounded to float.
    EXPECT_TRUE(near(d(g.smooth_normals[v]), vertex_normal(mesh, VertexId(v)), 1e-7));
  }
  ASSERT_EQ(g.face_normals.size(), 12u);
  for (uint32_t f = 0; f < 12; ++f) {
    EXPECT_TRUE(near(d(g.face_normals[f]), face_normal(mesh, FaceId::face(f)), 1e-7));
  }
  EXPECT_TRUE(near(g.bounds.min, {-0.5, -0.5, -0.5}, 0.0));
  EXPECT_TRUE(near(g.bounds.max, {0.5, 0.5, 0.5}, 0.0));
  EXPECT_TRUE(g.skipped_faces.empty());
  EXPECT_TRUE(g.skipped_edges.empty());
}

TEST(MeshGeometry, CubeEdgesRunBetweenTheirHalfedgesVerticesInIdOrder) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  const MeshGeometry g = build_mesh_geometry(mesh);
  ASSERT_EQ(g.edges.size(), 18u);
  for (uint32_t e = 0; e < 18; ++e) {
    const EdgeSegment& s = g.edges[e];
    EXPECT_EQ(s.edge, e);
    EXPECT_EQ(s.flags, 0u);  // a closed surface has no boundary
    const HalfedgeId h = mesh.halfedge(EdgeId(e));
    EXPECT_TRUE(near(d(s.start), mesh.position(mesh.vertex(h)), 0.0));
    EXPECT_TRUE(near(d(s.end), mesh.position(mesh.vertex(mesh.twin(h))), 0.0));
  }
  // Edge e0 is face 0's first side: from the face's corner 0 to corner 1.
  const PolygonMesh cube = make_cube();
  EXPECT_TRUE(near(d(g.edges[0].start), cube.positions[cube.face(0)[0]], 0.0));
  EXPECT_TRUE(near(d(g.edges[0].end), cube.positions[cube.face(0)[1]], 0.0));
}

TEST(MeshGeometry, QuadsAreFannedFromTheFirstCorner) {
  const PolygonMesh quads = make_cube_quads();
  const MeshGeometry g = build_mesh_geometry(build_halfedge_mesh(quads));
  ASSERT_EQ(g.triangle_count(), 12u);
  for (uint32_t f = 0; f < 6; ++f) {
    const auto c = quads.face(f);
    const uint32_t expected[6] = {c[0], c[1], c[2], c[0], c[2], c[3]};
    for (uint32_t j = 0; j < 6; ++j) EXPECT_EQ(g.triangle_corners[6 * f + j], expected[j]) << "f" << f;
    EXPECT_EQ(g.triangle_faces[2 * f], f);
    EXPECT_EQ(g.triangle_faces[2 * f + 1], f);
  }
  EXPECT_EQ(g.edges.size(), 12u);
}

TEST(MeshGeometry, GridFlagsExactlyTheBoundaryEdges) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_grid(3, 2));
  const MeshGeometry g = build_mesh_geometry(mesh);
  EXPECT_EQ(g.triangle_count(), 12u);
  EXPECT_EQ(g.points.size(), 12u);
  ASSERT_EQ(g.edges.size(), mesh.num_edges());
  size_t boundary = 0;
  for (const EdgeSegment& s : g.edges) {
    const bool on_boundary = (s.flags & kEdgeBoundaryFlag) != 0;
    EXPECT_EQ(on_boundary, mesh.is_boundary(EdgeId(s.edge))) << "e" << s.edge;
    if (!on_boundary) continue;
    ++boundary;
    // Both ends on the grid's outline, and the segment along it.
    auto on_outline = [](glm::vec3 p) { return p.x == 0 || p.x == 3 || p.y == 0 || p.y == 2; };
    EXPECT_TRUE(on_outline(s.start) && on_outline(s.end));
    EXPECT_TRUE(s.start.x == s.end.x || s.start.y == s.end.y);
  }
  EXPECT_EQ(boundary, 10u);  // 3 + 2 + 3 + 2 unit sides
  // Vertex 4 of a 3x2 grid is (0, 1, 0): row-major from the origin.
  EXPECT_TRUE(near(d(g.positions[4]), {0, 1, 0}, 0.0));
}

TEST(MeshGeometry, ArrowsLieInsideTheirFacesAndPointAlongTheirHalfedges) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  const std::vector<HalfedgeArrow> arrows = build_halfedge_arrows(mesh);
  ASSERT_EQ(arrows.size(), 36u);
  for (uint32_t i = 0; i < 36; ++i) {
    const HalfedgeArrow& arrow = arrows[i];
    EXPECT_EQ(arrow.halfedge, i);  // face by face, each cycle from the face's halfedge: h0, h1, h2, h3...
    const HalfedgeId h(arrow.halfedge);
    const FaceId f = mesh.face(h);
    const glm::dvec3 a = mesh.position(mesh.vertex(h));
    const glm::dvec3 b = mesh.position(mesh.vertex(mesh.next(h)));
    const glm::dvec3 c = mesh.position(mesh.vertex(mesh.next(mesh.next(h))));
    for (const glm::vec3& p : {arrow.tail, arrow.tip, arrow.barb_inner, arrow.barb_outer}) {
      const Barycentric bc = barycentric(d(p), a, b, c);
      SCOPED_TRACE(format_id(h) + " in " + format_id(f));
      EXPECT_GT(bc.u, 0.01);
      EXPECT_GT(bc.v, 0.01);
      EXPECT_GT(bc.w, 0.01);
      EXPECT_LT(bc.off_plane, 1e-6);
    }
    // From near h.vertex towards h.next.vertex.
    EXPECT_GT(glm::dot(d(arrow.tip - arrow.tail), b - a), 0.0);
    EXPECT_LT(glm::length(d(arrow.tail) - a), glm::length(d(arrow.tail) - b));
    EXPECT_LT(glm::length(d(arrow.tip) - b), glm::length(d(arrow.tip) - a));
    // The barbs sit behind the tip, one on each side of the shaft.
    const glm::dvec3 shaft = d(arrow.tip - arrow.tail);
    EXPECT_LT(glm::dot(d(arrow.barb_inner - arrow.tip), shaft), 0.0);
    EXPECT_LT(glm::dot(d(arrow.barb_outer - arrow.tip), shaft), 0.0);
    // The one-at-a-time version agrees exactly.
    const auto single = halfedge_arrow(mesh, h);
    ASSERT_TRUE(single.has_value());
    EXPECT_EQ(single->tail, arrow.tail);
    EXPECT_EQ(single->tip, arrow.tip);
    EXPECT_EQ(single->barb_inner, arrow.barb_inner);
    EXPECT_EQ(single->barb_outer, arrow.barb_outer);
  }
}

TEST(MeshGeometry, BoundaryHalfedgesHaveNoArrow) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_grid(1, 1));
  EXPECT_EQ(build_halfedge_arrows(mesh).size(), 6u);
  for (HalfedgeId h : mesh.halfedges()) {
    EXPECT_EQ(halfedge_arrow(mesh, h).has_value(), !mesh.is_boundary(h)) << format_id(h);
  }
}

TEST(MeshGeometry, ARhoShapedFaceCycleIsSkippedAndTheRestIsDrawn) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  // f0 is h0 -> h1 -> h2 -> h0; make it h0 -> h1 -> h2 -> h1 -> ..., a cycle that never comes back.
  mesh.set_next(HalfedgeId(2), HalfedgeId(1));
  const MeshGeometry g = build_mesh_geometry(mesh);
  ASSERT_EQ(g.skipped_faces.size(), 1u);
  EXPECT_EQ(g.skipped_faces[0], FaceId::face(0));
  ASSERT_EQ(g.triangle_count(), 11u);
  for (uint32_t t = 0; t < 11; ++t) EXPECT_EQ(g.triangle_faces[t], t + 1);
  EXPECT_EQ(g.edges.size(), 18u);  // edges do not depend on next pointers
  EXPECT_EQ(build_halfedge_arrows(mesh).size(), 33u);
  EXPECT_FALSE(halfedge_arrow(mesh, HalfedgeId(0)).has_value());
  EXPECT_FALSE(face_corners(mesh, FaceId::face(0)).has_value());
  EXPECT_TRUE(face_corners(mesh, FaceId::face(1)).has_value());
}

TEST(MeshGeometry, PointersToNowhereOrToOtherFacesSkipOnlyTheirFace) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  mesh.set_next(HalfedgeId(4), HalfedgeId(999999));                               // f1's cycle leaves the arrays
  mesh.set_face(HalfedgeId(7), FaceId::face(5));                                  // f2's cycle holds a halfedge of "f5"
  mesh.set_twin(HalfedgeId(mesh.halfedge(EdgeId(0)).index), HalfedgeId(123456));  // e0's twin is gone
  const MeshGeometry g = build_mesh_geometry(mesh);
  ASSERT_EQ(g.skipped_faces.size(), 2u);
  EXPECT_EQ(g.skipped_faces[0], FaceId::face(1));
  EXPECT_EQ(g.skipped_faces[1], FaceId::face(2));
  EXPECT_EQ(g.triangle_count(), 10u);
  ASSERT_EQ(g.skipped_edges.size(), 1u);
  EXPECT_EQ(g.skipped_edges[0], EdgeId(0));
  EXPECT_EQ(g.edges.size(), 17u);
  EXPECT_EQ(g.edges[0].edge, 1u);
}

TEST(MeshGeometry, DeadOrNonFiniteVerticesSkipTheFacesAroundThem) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  mesh.delete_element(VertexId(7));
  mesh.set_position(VertexId(0), {std::nan(""), 0.0, 0.0});
  const MeshGeometry g = build_mesh_geometry(mesh);
  size_t expected = 0;
  const PolygonMesh cube = make_cube();
  for (size_t f = 0; f < cube.num_faces(); ++f) {
    const auto c = cube.face(f);
    if (std::find(c.begin(), c.end(), 7u) == c.end() && std::find(c.begin(), c.end(), 0u) == c.end()) ++expected;
  }
  EXPECT_EQ(g.triangle_count(), expected);
  EXPECT_EQ(g.skipped_faces.size(), 12u - expected);
  EXPECT_EQ(g.points.size(), 6u);  // v0 (not finite) and v7 (dead) have no dot
  EXPECT_EQ(g.positions[7], glm::vec3(0.0f));
  EXPECT_TRUE(near(g.bounds.min, {-0.5, -0.5, -0.5}, 0.0));  // v0's NaN does not poison the box
  for (const EdgeSegment& s : g.edges) {
    EXPECT_TRUE(std::isfinite(s.start.x) && std::isfinite(s.end.x)) << "e" << s.edge;
  }
}

TEST(MeshGeometry, EmptyMeshGivesNothing) {
  const HalfedgeMesh mesh;
  const MeshGeometry g = build_mesh_geometry(mesh);
  EXPECT_EQ(g.triangle_count(), 0u);
  EXPECT_TRUE(g.edges.empty());
  EXPECT_TRUE(g.points.empty());
  EXPECT_TRUE(g.bounds.empty());
  EXPECT_TRUE(mesh_bounds(mesh).empty());
}

TEST(MeshGeometry, BoundsMatchTheGeometrysBox) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_torus(12, 4));
  const BoundingBox b = mesh_bounds(mesh);
  const MeshGeometry g = build_mesh_geometry(mesh);
  EXPECT_TRUE(near(b.min, g.bounds.min, 0.0));
  EXPECT_TRUE(near(b.max, g.bounds.max, 0.0));
  EXPECT_NEAR(b.max.x, 1.35, 1e-12);
  EXPECT_NEAR(b.max.z, 0.35, 1e-12);
}

}  // namespace
}  // namespace meshedit
