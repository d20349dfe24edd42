// flip(): every field of every touched element on small fixtures, the rotation direction, what two and
// four flips give under our convention, and refusals (boundary, non-triangle, duplicate edge, dead or
// broken input) that leave the mesh and its version untouched.
//
// Ids below follow mesh_build.h.
// grid(1,1): v0 (0,0) v1 (1,0) v2 (0,1) v3 (1,1); f0 = (0,1,3): h0 0->1, h1 1->3, h2 3->0;
//   f1 = (0,3,2): h3 0->3, h4 3->2, h5 2->0; b0: h6 1->0, h7 0->2, h8 2->3, h9 3->1 (next in that order).
//   Twins/edges: h0-h6 e0, h1-h9 e1, h2-h3 e2, h4-h8 e3, h5-h7 e4 (e.halfedge the first of each pair).
//   v0.halfedge h7, v1 h6, v2 h8, v3 h9; f0.halfedge h0, f1 h3, b0 h6.
// fan(4): v0 centre, v1..v4 at angles 0, 90, 180, 270 degrees; f_i = (0, i+1, (i+1)%4+1):
//   f0: h0 0->1, h1 1->2, h2 2->0   f1: h3 0->2, h4 2->3, h5 3->0   f2: h6 0->3, h7 3->4, h8 4->0
//   f3: h9 0->4, h10 4->1, h11 1->0   b0: h12 2->1, h13 1->4, h14 4->3, h15 3->2
//   Twins/edges: h0-h11 e0, h1-h12 e1, h2-h3 e2, h4-h15 e3, h5-h6 e4, h7-h14 e5, h8-h9 e6, h10-h13 e7.
//   v0.halfedge h0 (interior: lowest outgoing), v1 h13, v2 h12, v3 h15, v4 h14.
#include <gtest/gtest.h>

#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "ops_test_support.h"

namespace meshedit {
namespace {

using namespace ops_testing;

TEST(Flip, DiagonalOfTheUnitSquareEveryField) {
  HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  const HalfedgeMesh before = m;
  // e2: h0 of the operation is h2 (a = v3 -> b = v0) in f0 = (3, 0, 1), c = v1; h1 = h3 in f1 = (0, 3, 2), d = v2.
  const OpResult<EdgeId> r = flip(m, E(2));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_ID(r.value, E(2));
  EXPECT_TRUE(valid_mesh(m));

  // f0 = (d, c, a) = (2, 1, 3): h2 2->1, h1 1->3, h4 3->2.   f1 = (c, d, b) = (1, 2, 0): h3 1->2, h5 2->0, h0 0->1.
  expect_halfedge(m, H(2), H(1), H(3), V(2), E(2), F(0));
  expect_halfedge(m, H(1), H(4), H(9), V(1), E(1), F(0));
  expect_halfedge(m, H(4), H(2), H(8), V(3), E(3), F(0));
  expect_halfedge(m, H(3), H(5), H(2), V(1), E(2), F(1));
  expect_halfedge(m, H(5), H(0), H(7), V(2), E(4), F(1));
  expect_halfedge(m, H(0), H(3), H(6), V(0), E(0), F(1));
  // The boundary loop is untouched.
  expect_halfedge(m, H(6), H(7), H(0), V(1), E(0), B(0));
  expect_halfedge(m, H(7), H(8), H(5), V(0), E(4), B(0));
  expect_halfedge(m, H(8), H(9), H(4), V(2), E(3), B(0));
  expect_halfedge(m, H(9), H(6), H(1), V(3), E(1), B(0));
  EXPECT_ID(m.halfedge(F(0)), H(2));
  EXPECT_ID(m.halfedge(F(1)), H(3));
  EXPECT_ID(m.halfedge(B(0)), H(6));
  const EdgeId edge_halfedges[] = {E(0), E(1), E(2), E(3), E(4)};
  const HalfedgeId expected_edge_halfedge[] = {H(0), H(1), H(2), H(4), H(5)};
  for (int i = 0; i < 5; ++i) EXPECT_ID(m.halfedge(edge_halfedges[i]), expected_edge_halfedge[i]);
  // Boundary vertices keep their boundary halfedges; positions do not move.
  const HalfedgeId vertex_halfedge[] = {H(7), H(6), H(8), H(9)};
  for (uint32_t v = 0; v < 4; ++v) {
    EXPECT_ID(m.halfedge(V(v)), vertex_halfedge[v]);
    EXPECT_EQ(m.position(V(v)), before.position(V(v)));
  }
  EXPECT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.num_edges(), 5u);
  EXPECT_EQ(m.num_faces(), 2u);
  EXPECT_EQ(m.num_halfedges(), 10u);
  EXPECT_EQ(m.halfedge_capacity(), before.halfedge_capacity());
}

TEST(Flip, TurnsCounterClockwiseSeenFromTheNormals) {
  // In the square (normals +z), e2 runs from a = v3 (1,1) to b = v0 (0,0). A quarter turn counter-clockwise
  // about the centre takes (1,1) to (0,1) = v2 and (0,0) to (1,0) = v1, so h2 must run v2 -> v1.
  HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  ASSERT_TRUE(flip(m, E(2)).ok());
  const glm::dvec3 centre(0.5, 0.5, 0.0);
  auto turned = [&](const glm::dvec3& p) {
    const glm::dvec3 r = p - centre;
    return centre + glm::dvec3(-r.y, r.x, 0.0);
  };
  EXPECT_EQ(m.position(m.vertex(H(2))), turned(glm::dvec3(1, 1, 0)));
  EXPECT_EQ(m.position(m.vertex(H(3))), turned(glm::dvec3(0, 0, 0)));
}

TEST(Flip, InteriorEndpointHalfedgeMovesToH4) {
  // fan(4), e0 = v0-v1: h0 = h0 (0->1) in f0 = (0,1,2), c = v2; h1 = h11 (1->0) in f3, h4 = h9 (0->4), h5 = h10
  // (4->1), d = v4. v0.halfedge was h0, which now leaves v4, so it becomes h9; v1 is on the boundary and keeps h13.
  HalfedgeMesh m = build_halfedge_mesh(make_fan(4));
  const OpResult<EdgeId> r = flip(m, E(0));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_TRUE(valid_mesh(m));
  // f0 = (4, 2, 0): h0 4->2, h2 2->0, h9 0->4.   f3 = (2, 4, 1): h11 2->4, h10 4->1, h1 1->2.
  expect_halfedge(m, H(0), H(2), H(11), V(4), E(0), F(0));
  expect_halfedge(m, H(2), H(9), H(3), V(2), E(2), F(0));
  expect_halfedge(m, H(9), H(0), H(8), V(0), E(6), F(0));
  expect_halfedge(m, H(11), H(10), H(0), V(2), E(0), F(3));
  expect_halfedge(m, H(10), H(1), H(13), V(4), E(7), F(3));
  expect_halfedge(m, H(1), H(11), H(12), V(1), E(1), F(3));
  EXPECT_ID(m.halfedge(F(0)), H(0));
  EXPECT_ID(m.halfedge(F(3)), H(11));
  EXPECT_ID(m.halfedge(V(0)), H(9));
  EXPECT_ID(m.halfedge(V(1)), H(13));
  EXPECT_ID(m.halfedge(V(2)), H(12));
  EXPECT_ID(m.halfedge(V(4)), H(14));
  EXPECT_ID(m.halfedge(E(0)), H(0));
  EXPECT_EQ(m.degree(V(0)), 3u);
  EXPECT_EQ(m.degree(V(2)), 4u);
}

TEST(Flip, TwiceSwapsTheTrianglesBetweenTheTwoFaces) {
  HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  ASSERT_TRUE(flip(m, E(2)).ok());
  ASSERT_TRUE(flip(m, E(2)).ok());
  EXPECT_TRUE(valid_mesh(m));
  // Before: f0 = (3,0,1) read from h2, f1 = (0,3,2) read from h3. After two flips h2 runs 0->3 (reversed)
  // and the faces have swapped triangles: f0 holds (b, a, d) = (0, 3, 2) as h2, h4, h5; f1 holds (a, b, c) =
  // (3, 0, 1) as h3, h0, h1.
  EXPECT_EQ(corners(m, F(0)), (std::vector<uint32_t>{0, 3, 2}));
  EXPECT_EQ(corners(m, F(1)), (std::vector<uint32_t>{3, 0, 1}));
  expect_halfedge(m, H(2), H(4), H(3), V(0), E(2), F(0));
  expect_halfedge(m, H(4), H(5), H(8), V(3), E(3), F(0));
  expect_halfedge(m, H(5), H(2), H(7), V(2), E(4), F(0));
  expect_halfedge(m, H(3), H(0), H(2), V(3), E(2), F(1));
  expect_halfedge(m, H(0), H(1), H(6), V(0), E(0), F(1));
  expect_halfedge(m, H(1), H(3), H(9), V(1), E(1), F(1));
}

TEST(Flip, FourTimesRestoresEveryHalfedgePointer) {
  // fan(4), e0: the only differences from the start are the documented ones: f0.halfedge = h0 (already),
  // f3.halfedge = h11 (was h9), v0.halfedge = h9 (was h0, moved by the first flip).
  const HalfedgeMesh start = build_halfedge_mesh(make_fan(4));
  HalfedgeMesh m = start;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(flip(m, E(0)).ok()) << "flip " << i;
    ASSERT_TRUE(valid_mesh(m)) << "flip " << i;
  }
  HalfedgeMesh expected = start;
  expected.set_halfedge(F(3), H(11));
  expected.set_halfedge(V(0), H(9));
  EXPECT_FALSE(m.same_as(start));
  EXPECT_TRUE(m.same_as(expected));
}

TEST(Flip, BoundaryEdgeIsRefusedAndNothingChanges) {
  HalfedgeMesh m = build_halfedge_mesh(make_grid(1, 1));
  const HalfedgeMesh before = m;
  const uint64_t version = m.version();
  const OpResult<EdgeId> r = flip(m, E(0));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.check.reason, "e0 is on the boundary (b0); only interior edges can be flipped");
  EXPECT_EQ(can_flip(m, E(0)).reason, r.check.reason);
  EXPECT_TRUE(m.same_as(before));
  EXPECT_EQ(m.version(), version);
}

TEST(Flip, EveryTetrahedronFlipWouldDuplicateAnEdge) {
  HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  const HalfedgeMesh before = m;
  const uint64_t version = m.version();
  // e0 = v0-v1 between f0 (0,1,2) and f1 (0,3,1): the flip would join v2 and v3, already joined by e5.
  EXPECT_EQ(can_flip(m, E(0)).reason, "flipping e0 would join v2 and v3, which are already joined by e5");
  for (uint32_t e = 0; e < 6; ++e) {
    const OpResult<EdgeId> r = flip(m, E(e));
    EXPECT_FALSE(r.ok()) << "e" << e;
    EXPECT_NE(r.check.reason.find("already joined"), std::string::npos) << r.check.reason;
  }
  EXPECT_TRUE(m.same_as(before));
  EXPECT_EQ(m.version(), version);
}

TEST(Flip, QuadsAreRefusedWithTheirSideCount) {
  HalfedgeMesh m = build_halfedge_mesh(make_cube_quads());
  const HalfedgeMesh before = m;
  // e0 = h0 (0->2) lies in f0 = (0, 2, 3, 1).
  EXPECT_EQ(can_flip(m, E(0)).reason,
            "f0 is not a triangle (4 sides); only edges between two triangles can be flipped");
  EXPECT_FALSE(flip(m, E(0)).ok());
  EXPECT_TRUE(m.same_as(before));
}

TEST(Flip, DeadMissingAndUnsetEdgesAreRefused) {
  HalfedgeMesh m = build_halfedge_mesh(make_icosahedron());
  EXPECT_EQ(can_flip(m, E(30)).reason, "e30 does not exist");
  EXPECT_EQ(can_flip(m, EdgeId()).reason, "no edge was given");
  m.delete_element(E(4));
  const HalfedgeMesh before = m;
  const uint64_t version = m.version();
  EXPECT_EQ(flip(m, E(4)).check.reason, "e4 is dead");
  EXPECT_TRUE(m.same_as(before));
  EXPECT_EQ(m.version(), version);
}

TEST(Flip, BrokenPointersAreRefusedWithAReason) {
  const HalfedgeMesh start = build_halfedge_mesh(make_grid(1, 1));
  struct Case {
    const char* what;
    void (*do_break)(HalfedgeMesh&);
    const char* reason;
  };
  const Case cases[] = {
      {"twin points elsewhere", [](HalfedgeMesh& m) { m.set_twin(H(3), H(4)); }, "h2.twin is h3, but h3.twin is h4"},
      {"twin out of range", [](HalfedgeMesh& m) { m.set_twin(H(2), H(99)); }, "h2.twin is h99, which does not exist"},
      {"edge halfedge on another edge", [](HalfedgeMesh& m) { m.set_halfedge(E(2), H(0)); },
       "e2.halfedge is h0, but h0.edge is e0"},
      {"f0 made a quad through h6",
       [](HalfedgeMesh& m) {
         m.set_next(H(1), H(6));
         m.set_next(H(6), H(2));
         m.set_face(H(6), F(0));
       },
       "f0 is not a triangle (4 sides); only edges between two triangles can be flipped"},
      {"next out of range", [](HalfedgeMesh& m) { m.set_next(H(0), H(99)); }, "h0.next is h99, which does not exist"},
      {"next never returns", [](HalfedgeMesh& m) { m.set_next(H(1), H(0)); },
       "the next-cycle of f0 from h2 does not come back to h2"},
      {"dead vertex", [](HalfedgeMesh& m) { m.delete_element(V(1)); }, "h1.vertex is v1, which is dead"},
      {"dead face", [](HalfedgeMesh& m) { m.delete_element(F(1)); }, "h3.face is f1, which is dead"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    HalfedgeMesh m = start;
    c.do_break(m);
    const HalfedgeMesh broken = m;
    const uint64_t version = m.version();
    const OpResult<EdgeId> r = flip(m, E(2));
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.check.reason, c.reason);
    EXPECT_TRUE(m.same_as(broken));
    EXPECT_EQ(m.version(), version);
  }
}

}  // namespace
}  // namespace meshedit
