// split(): every field of every touched and created element for an interior and a boundary split of the
// unit square, the documented id order, the midpoint, and refusals that leave the mesh untouched.
//
// grid(1,1) ids (mesh_build.h): v0 (0,0) v1 (1,0) v2 (0,1) v3 (1,1); f0 = (0,1,3): h0 0->1, h1 1->3, h2 3->0;
//   f1 = (0,3,2): h3 0->3, h4 3->2, h5 2->0; b0: h6 1->0, h7 0->2, h8 2->3, h9 3->1 (next in that order).
//   Twins/edges: h0-h6 e0, h1-h9 e1, h2-h3 e2, h4-h8 e3, h5-h7 e4 (e.halfedge the first of each pair).
//   v0.halfedge h7, v1 h6, v2 h8, v3 h9; f0.halfedge h0, f1 h3, b0 h6.
#include <gtest/gtest.h>

#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "ops_test_support.h"

namespace meshedit {
namespace {

using namespace ops_testing;

TEST(Split, InteriorEdgeEveryField) {
  HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  // e2: h0 of the operation is h2 (a = v3 -> b = v0) in f0, c = v1; h1 = h3 in f1, d = v2.
  const OpResult<VertexId> r = split(m, E(2));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_TRUE(valid_mesh(m));
  // New ids: m = v4; ea = e5 (3-4), ec = e6 (4-1), ed = e7 (4-2); g0 = f2, g1 = f3;
  // n0 = h10 3->4, n1 = h11 4->3, n2 = h12 4->1, n3 = h13 1->4, n4 = h14 4->2, n5 = h15 2->4.
  EXPECT_ID(r.value, V(4));
  EXPECT_EQ(m.position(V(4)), glm::dvec3(0.5, 0.5, 0.0));
  EXPECT_ID(m.halfedge(V(4)), H(11));

  // f0 = (4, 0, 1): h2 -> h0 -> h13      g0 = f2 = (3, 4, 1): h10 -> h12 -> h1
  // f1 = (0, 4, 2): h3 -> h14 -> h5      g1 = f3 = (4, 3, 2): h11 -> h4 -> h15
  expect_halfedge(m, H(0), H(13), H(6), V(0), E(0), F(0));
  expect_halfedge(m, H(1), H(10), H(9), V(1), E(1), F(2));
  expect_halfedge(m, H(2), H(0), H(3), V(4), E(2), F(0));
  expect_halfedge(m, H(3), H(14), H(2), V(0), E(2), F(1));
  expect_halfedge(m, H(4), H(15), H(8), V(3), E(3), F(3));
  expect_halfedge(m, H(5), H(3), H(7), V(2), E(4), F(1));
  expect_halfedge(m, H(10), H(12), H(11), V(3), E(5), F(2));
  expect_halfedge(m, H(11), H(4), H(10), V(4), E(5), F(3));
  expect_halfedge(m, H(12), H(1), H(13), V(4), E(6), F(2));
  expect_halfedge(m, H(13), H(2), H(12), V(1), E(6), F(0));
  expect_halfedge(m, H(14), H(5), H(15), V(4), E(7), F(1));
  expect_halfedge(m, H(15), H(11), H(14), V(2), E(7), F(3));
  // The boundary loop is untouched.
  expect_halfedge(m, H(6), H(7), H(0), V(1), E(0), B(0));
  expect_halfedge(m, H(7), H(8), H(5), V(0), E(4), B(0));
  expect_halfedge(m, H(8), H(9), H(4), V(2), E(3), B(0));
  expect_halfedge(m, H(9), H(6), H(1), V(3), E(1), B(0));

  EXPECT_ID(m.halfedge(F(0)), H(2));
  EXPECT_ID(m.halfedge(F(1)), H(3));
  EXPECT_ID(m.halfedge(F(2)), H(10));
  EXPECT_ID(m.halfedge(F(3)), H(11));
  EXPECT_ID(m.halfedge(B(0)), H(6));
  const HalfedgeId edge_halfedge[] = {H(0), H(1), H(2), H(4), H(5), H(10), H(12), H(14)};
  for (uint32_t e = 0; e < 8; ++e) EXPECT_ID(m.halfedge(E(e)), edge_halfedge[e]);
  const HalfedgeId vertex_halfedge[] = {H(7), H(6), H(8), H(9), H(11)};
  for (uint32_t v = 0; v < 5; ++v) EXPECT_ID(m.halfedge(V(v)), vertex_halfedge[v]);
  EXPECT_EQ(m.position(V(3)), glm::dvec3(1, 1, 0));
  EXPECT_EQ(m.position(V(0)), glm::dvec3(0, 0, 0));

  EXPECT_EQ(m.num_vertices(), 5u);
  EXPECT_EQ(m.num_edges(), 8u);
  EXPECT_EQ(m.num_faces(), 4u);
  EXPECT_EQ(m.num_halfedges(), 16u);
  EXPECT_EQ(m.halfedge_capacity(), 16u);
}

TEST(Split, BoundaryEdgeEveryField) {
  HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  // e0: h0 = h0 (a = v0 -> b = v1) in f0, c = v3; h1 = h6 on b0, followed by h7.
  const OpResult<VertexId> r = split(m, E(0));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_TRUE(valid_mesh(m));
  // New ids: m = v4; ea = e5 (0-4), ec = e6 (4-3); g0 = f2; n0 = h10 0->4, n1 = h11 4->0, n2 = h12 4->3, n3 = h13 3->4.
  EXPECT_ID(r.value, V(4));
  EXPECT_EQ(m.position(V(4)), glm::dvec3(0.5, 0.0, 0.0));
  EXPECT_ID(m.halfedge(V(4)), H(11));  // on the boundary loop, as the convention requires

  // f0 = (4, 1, 3): h0 -> h1 -> h13    g0 = f2 = (0, 4, 3): h10 -> h12 -> h2
  // b0: h6 (1->4) -> h11 (4->0) -> h7 -> h8 -> h9
  expect_halfedge(m, H(0), H(1), H(6), V(4), E(0), F(0));
  expect_halfedge(m, H(1), H(13), H(9), V(1), E(1), F(0));
  expect_halfedge(m, H(2), H(10), H(3), V(3), E(2), F(2));
  expect_halfedge(m, H(6), H(11), H(0), V(1), E(0), B(0));
  expect_halfedge(m, H(10), H(12), H(11), V(0), E(5), F(2));
  expect_halfedge(m, H(11), H(7), H(10), V(4), E(5), B(0));
  expect_halfedge(m, H(12), H(2), H(13), V(4), E(6), F(2));
  expect_halfedge(m, H(13), H(0), H(12), V(3), E(6), F(0));
  // Untouched: f1 and the rest of the loop.
  expect_halfedge(m, H(3), H(4), H(2), V(0), E(2), F(1));
  expect_halfedge(m, H(4), H(5), H(8), V(3), E(3), F(1));
  expect_halfedge(m, H(5), H(3), H(7), V(2), E(4), F(1));
  expect_halfedge(m, H(7), H(8), H(5), V(0), E(4), B(0));
  expect_halfedge(m, H(8), H(9), H(4), V(2), E(3), B(0));
  expect_halfedge(m, H(9), H(6), H(1), V(3), E(1), B(0));

  EXPECT_ID(m.halfedge(F(0)), H(0));
  EXPECT_ID(m.halfedge(F(1)), H(3));
  EXPECT_ID(m.halfedge(F(2)), H(10));
  EXPECT_ID(m.halfedge(B(0)), H(6));
  const HalfedgeId edge_halfedge[] = {H(0), H(1), H(2), H(4), H(5), H(10), H(12)};
  for (uint32_t e = 0; e < 7; ++e) EXPECT_ID(m.halfedge(E(e)), edge_halfedge[e]);
  const HalfedgeId vertex_halfedge[] = {H(7), H(6), H(8), H(9), H(11)};
  for (uint32_t v = 0; v < 5; ++v) EXPECT_ID(m.halfedge(V(v)), vertex_halfedge[v]);

  EXPECT_EQ(m.num_vertices(), 5u);
  EXPECT_EQ(m.num_edges(), 7u);
  EXPECT_EQ(m.num_faces(), 3u);
  EXPECT_EQ(m.num_halfedges(), 14u);
  EXPECT_EQ(m.num_boundaries(), 1u);
  EXPECT_EQ(m.degree(B(0)), 5u);
}

TEST(Split, BoundaryEdgeWorksFromTheFaceSideWhicheverHalfedgeTheEdgeHolds) {
  // Pointing e0 at its boundary halfedge h6 must give the same result, except e0.halfedge itself stays h6.
  HalfedgeMesh from_face = build_halfedge_mesh(make_grid(1, 1));
  HalfedgeMesh from_loop = from_face;
  from_loop.set_halfedge(E(0), H(6));
  ASSERT_TRUE(valid_mesh(from_loop));
  ASSERT_TRUE(split(from_face, E(0)).ok());
  ASSERT_TRUE(split(from_loop, E(0)).ok());
  EXPECT_TRUE(valid_mesh(from_loop));
  EXPECT_ID(from_loop.halfedge(E(0)), H(6));
  from_loop.set_halfedge(E(0), H(0));
  EXPECT_TRUE(from_loop.same_as(from_face));
}

TEST(Split, InteriorEndpointHalfedgeMovesToN0) {
  // fan(4), e0 = v0-v1 with v0.halfedge = h0 (0->1): after the split h0 leaves m = v5, so v0 takes n0 = h16 (0->5).
  HalfedgeMesh m = build_halfedge_mesh(make_fan(4));
  const OpResult<VertexId> r = split(m, E(0));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_TRUE(valid_mesh(m));
  EXPECT_ID(r.value, V(5));
  EXPECT_ID(m.halfedge(V(0)), H(16));
  expect_halfedge(m, H(16), H(18), H(17), V(0), E(8), F(4));
  expect_halfedge(m, H(0), H(1), H(11), V(5), E(0), F(0));
  EXPECT_EQ(m.position(V(5)), glm::dvec3(0.5, 0.0, 0.0));
  EXPECT_EQ(m.degree(V(0)), 4u);
  EXPECT_EQ(m.degree(V(5)), 4u);
}

TEST(Split, RefusalsChangeNothing) {
  struct Case {
    const char* what;
    HalfedgeMesh mesh;
    EdgeId edge;
    const char* reason;
  };
  HalfedgeMesh dead = build_halfedge_mesh(make_tetrahedron());
  dead.delete_element(E(3));
  // A lone edge with a boundary loop on each side is not buildable from polygons; make one from a triangle by
  // turning f0 into a second boundary loop.
  HalfedgeMesh two_loops = build_halfedge_mesh(make_grid(1, 1));
  const FaceId loop = two_loops.new_boundary();
  for (uint32_t h : {0u, 1u, 2u}) two_loops.set_face(H(h), loop);
  two_loops.set_halfedge(loop, H(0));
  two_loops.delete_element(F(0));
  const Case cases[] = {
      {"quad", build_halfedge_mesh(make_cube_quads()), E(0),
       "f0 is not a triangle (4 sides); only edges of triangles can be split"},
      {"dead edge", dead, E(3), "e3 is dead"},
      {"past the end", build_halfedge_mesh(make_cube()), E(18), "e18 does not exist"},
      {"boundary on both sides", two_loops, E(0),
       "e0 has boundary loops on both sides (b1 and b0); there is no face to split"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    HalfedgeMesh m = c.mesh;
    const uint64_t version = m.version();
    EXPECT_EQ(can_split(m, c.edge).reason, c.reason);
    const OpResult<VertexId> r = split(m, c.edge);
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.value.valid());
    EXPECT_EQ(r.check.reason, c.reason);
    EXPECT_TRUE(m.same_as(c.mesh));
    EXPECT_EQ(m.version(), version);
  }
}

TEST(Split, BoundaryLoopBrokenAfterH1IsRefused) {
  HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  m.set_next(H(6), H(99));
  const HalfedgeMesh broken = m;
  EXPECT_EQ(split(m, E(0)).check.reason, "h6.next is h99, which does not exist");
  EXPECT_TRUE(m.same_as(broken));
  m.set_next(H(6), H(8));
  const HalfedgeMesh broken2 = m;
  EXPECT_EQ(split(m, E(0)).check.reason, "h6 reaches v0, but its next h8 leaves v2");
  EXPECT_TRUE(m.same_as(broken2));
}

}  // namespace
}  // namespace meshedit
