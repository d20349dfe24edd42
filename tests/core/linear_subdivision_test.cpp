// Linear subdivision: original vertices keep their positions bit for bit, new ones sit exactly at edge midpoints
// and face centroids, triangles become 4 triangles and other faces quads, with the counts and validity that follow.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

#include "core/linear_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/validate.h"

namespace meshedit {
namespace {

VertexId V(uint32_t i) { return VertexId(i); }

// Every original vertex where it was; every edge's new vertex (refined id V + edge id on these fixtures) at
// (a + b) * 0.5 exactly.
void expect_old_kept_and_midpoints(const HalfedgeMesh& original, const HalfedgeMesh& refined) {
  for (VertexId v : original.vertices()) EXPECT_EQ(refined.position(v), original.position(v)) << "v" << v.index;
  for (EdgeId e : original.edges()) {
    const HalfedgeId h = original.halfedge(e);
    const glm::dvec3 a = original.position(original.vertex(h));
    const glm::dvec3 b = original.position(original.vertex(original.twin(h)));
    EXPECT_EQ(refined.position(V(original.vertex_capacity() + e.index)), (a + b) * 0.5) << "e" << e.index;
  }
}

size_t faces_with_sides(const HalfedgeMesh& mesh, uint32_t sides) {
  size_t count = 0;
  for (FaceId f : mesh.faces()) count += mesh.degree(f) == sides;
  return count;
}

TEST(LinearSubdivision, TrianglesBecomeFourAtMidpoints) {
  const HalfedgeMesh original = build_halfedge_mesh(make_icosahedron());
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(linear_subdivide(mesh));
  expect_old_kept_and_midpoints(original, mesh);
  EXPECT_EQ(mesh.num_vertices(), 12u + 30u);
  EXPECT_EQ(mesh.num_faces(), 80u);
  EXPECT_EQ(faces_with_sides(mesh, 3), 80u);
  EXPECT_EQ(mesh.num_edges(), 2u * 30u + 3u * 20u);
  EXPECT_TRUE(validate(mesh).ok());
}

TEST(LinearSubdivision, GridWithBoundaryKeepsItsShape) {
  const HalfedgeMesh original = build_halfedge_mesh(make_grid(3, 2));
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(linear_subdivide(mesh));
  expect_old_kept_and_midpoints(original, mesh);
  EXPECT_EQ(mesh.num_faces(), 4u * 12u);
  EXPECT_EQ(mesh.num_boundaries(), 1u);
  EXPECT_TRUE(validate(mesh).ok());
}

// The cube [-0.5, 0.5]^3 as quads: each face becomes 4 quads around its centre, which sits at the centroid.
TEST(LinearSubdivision, QuadsBecomeQuadsAroundTheirCentroid) {
  const HalfedgeMesh original = build_halfedge_mesh(make_cube_quads());
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(linear_subdivide(mesh));
  expect_old_kept_and_midpoints(original, mesh);
  EXPECT_EQ(mesh.num_vertices(), 8u + 12u + 6u);
  EXPECT_EQ(faces_with_sides(mesh, 4), 24u);
  EXPECT_EQ(mesh.num_faces(), 24u);
  for (FaceId f : original.faces()) {
    glm::dvec3 centre(0.0);
    // Every face of the cube has one coordinate fixed at +-0.5 and the others spanning [-0.5, 0.5].
    glm::dvec3 lo(1.0), hi(-1.0);
    original.for_each_face_halfedge(f, [&](HalfedgeId h) {
      const glm::dvec3& p = original.position(original.vertex(h));
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    });
    for (int k = 0; k < 3; ++k) centre[k] = lo[k] == hi[k] ? lo[k] : 0.0;
    EXPECT_EQ(mesh.position(V(8 + 12 + f.slot())), centre) << "f" << f.slot();
  }
  EXPECT_TRUE(validate(mesh).ok());
}

// A square pyramid: one quad base and four triangles. The base becomes 4 quads, each side 4 triangles, and the
// triangles and quads share the base edges' midpoints.
TEST(LinearSubdivision, MixedTrianglesAndQuads) {
  PolygonMesh pyramid;
  pyramid.add_vertex({-1, -1, 0});
  pyramid.add_vertex({1, -1, 0});
  pyramid.add_vertex({1, 1, 0});
  pyramid.add_vertex({-1, 1, 0});
  pyramid.add_vertex({0, 0, 2});
  pyramid.add_face({0, 3, 2, 1});
  pyramid.add_face({0, 1, 4});
  pyramid.add_face({1, 2, 4});
  pyramid.add_face({2, 3, 4});
  pyramid.add_face({3, 0, 4});
  const HalfedgeMesh original = build_halfedge_mesh(pyramid);
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(linear_subdivide(mesh));
  expect_old_kept_and_midpoints(original, mesh);
  EXPECT_EQ(mesh.num_vertices(), 5u + 8u + 1u);
  EXPECT_EQ(faces_with_sides(mesh, 3), 16u);
  EXPECT_EQ(faces_with_sides(mesh, 4), 4u);
  EXPECT_EQ(mesh.position(V(5 + 8)), glm::dvec3(0.0));  // the base's centroid
  EXPECT_TRUE(validate(mesh).ok());
}

TEST(LinearSubdivision, TwoLevelsKeepTheOriginalVertices) {
  const HalfedgeMesh original = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh mesh = original;
  ASSERT_TRUE(linear_subdivide(mesh, 2));
  for (VertexId v : original.vertices()) EXPECT_EQ(mesh.position(v), original.position(v));
  EXPECT_EQ(mesh.num_faces(), 64u);
  EXPECT_TRUE(validate(mesh).ok());
}

TEST(LinearSubdivision, BrokenMeshIsRefusedAndUnchanged) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_tetrahedron());
  mesh.set_twin(HalfedgeId(0), HalfedgeId(0));
  const HalfedgeMesh before = mesh;
  const Check done = linear_subdivide(mesh);
  EXPECT_FALSE(done);
  EXPECT_NE(done.reason.find("linear subdivision needs a valid mesh"), std::string::npos) << done.reason;
  EXPECT_TRUE(mesh.same_as(before));
}

}  // namespace
}  // namespace meshedit
