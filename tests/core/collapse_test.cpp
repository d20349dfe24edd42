// collapse(): every field of every touched element for an interior edge reaching the boundary, a boundary
// edge and an edge of a closed mesh; each refusal of the link condition and the degenerate cases, with its
// reason; refusals leave the mesh and its version untouched.
//
// fan(4) ids (mesh_build.h): v0 centre (0,0), v1 (1,0), v2 at 90 degrees, v3 at 180, v4 at 270;
//   f0: h0 0->1, h1 1->2, h2 2->0   f1: h3 0->2, h4 2->3, h5 3->0   f2: h6 0->3, h7 3->4, h8 4->0
//   f3: h9 0->4, h10 4->1, h11 1->0   b0: h12 2->1, h13 1->4, h14 4->3, h15 3->2 (next in that order)
//   Twins/edges: h0-h11 e0, h1-h12 e1, h2-h3 e2, h4-h15 e3, h5-h6 e4, h7-h14 e5, h8-h9 e6, h10-h13 e7.
//   v0.halfedge h0, v1 h13, v2 h12, v3 h15, v4 h14; f_i.halfedge h(3i); b0.halfedge h12.
// cube ids: f0 (0,2,3) h0-h2, f1 (0,3,1) h3-h5, ..., f6 (2,6,7) h18-h20, f7 (2,7,3) h21-h23, f8 (0,4,6)
//   h24-h26, f9 (0,6,2) h27-h29. Edges used: e0 = h0/h29 (0-2), e1 = h1/h23 (2-3), e2 = h2/h3 (3-0),
//   e13 = h18/h28 (2-6), e14 = h20/h21 (7-2), e16 = h26/h27 (6-0). v0.halfedge h0, v3 h2, v6 h11.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "ops_test_support.h"

namespace meshedit {
namespace {

using namespace ops_testing;

TEST(Collapse, InteriorEdgeToTheRimEveryField) {
  // e0: h0 (a = v0 -> b = v1) in f0, c = v2; h1 = h11 in f3, d = v4. t2 = h12, t3 = h3, t4 = h8, t5 = h13.
  HalfedgeMesh m = build_halfedge_mesh(make_fan(4));
  const OpResult<VertexId> r = collapse(m, E(0));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_TRUE(valid_mesh(m));
  EXPECT_ID(r.value, V(0));
  EXPECT_EQ(m.position(V(0)), glm::dvec3(0.5, 0.0, 0.0));

  // Deleted: b = v1, e0, e2 = h1.edge = e1, e5 = h10.edge = e7, f0, f3, h0, h1, h2, h9, h10, h11.
  EXPECT_FALSE(m.alive(V(1)));
  for (uint32_t e : {0u, 1u, 7u}) EXPECT_FALSE(m.alive(E(e))) << "e" << e;
  for (uint32_t f : {0u, 3u}) EXPECT_FALSE(m.alive(F(f))) << "f" << f;
  for (uint32_t h : {0u, 1u, 2u, 9u, 10u, 11u}) EXPECT_FALSE(m.alive(H(h))) << "h" << h;

  // f1 = (0, 2, 3): h3 -> h4 -> h5;  f2 = (0, 3, 4): h6 -> h7 -> h8;  b0: h12 (2->0) -> h13 (0->4) -> h14 -> h15.
  expect_halfedge(m, H(3), H(4), H(12), V(0), E(2), F(1));
  expect_halfedge(m, H(4), H(5), H(15), V(2), E(3), F(1));
  expect_halfedge(m, H(5), H(3), H(6), V(3), E(4), F(1));
  expect_halfedge(m, H(6), H(7), H(5), V(0), E(4), F(2));
  expect_halfedge(m, H(7), H(8), H(14), V(3), E(5), F(2));
  expect_halfedge(m, H(8), H(6), H(13), V(4), E(6), F(2));
  expect_halfedge(m, H(12), H(13), H(3), V(2), E(2), B(0));
  expect_halfedge(m, H(13), H(14), H(8), V(0), E(6), B(0));
  expect_halfedge(m, H(14), H(15), H(7), V(4), E(5), B(0));
  expect_halfedge(m, H(15), H(12), H(4), V(3), E(3), B(0));
  // e3 = h2.edge = e2 was held by h2 (dead): it moves to t2 = h12. e4 = h9.edge = e6 holds h8 and keeps it.
  EXPECT_ID(m.halfedge(E(2)), H(12));
  EXPECT_ID(m.halfedge(E(3)), H(4));
  EXPECT_ID(m.halfedge(E(4)), H(5));
  EXPECT_ID(m.halfedge(E(5)), H(7));
  EXPECT_ID(m.halfedge(E(6)), H(8));
  EXPECT_ID(m.halfedge(F(1)), H(3));
  EXPECT_ID(m.halfedge(F(2)), H(6));
  EXPECT_ID(m.halfedge(B(0)), H(12));
  // v0 took b's place on the rim: its halfedge is now its boundary halfedge h13 (was h0, dead).
  EXPECT_ID(m.halfedge(V(0)), H(13));
  EXPECT_ID(m.halfedge(V(2)), H(12));
  EXPECT_ID(m.halfedge(V(3)), H(15));
  EXPECT_ID(m.halfedge(V(4)), H(14));

  EXPECT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.num_edges(), 5u);
  EXPECT_EQ(m.num_faces(), 2u);
  EXPECT_EQ(m.num_halfedges(), 10u);
  EXPECT_EQ(m.num_boundaries(), 1u);
}

TEST(Collapse, BoundaryEdgeEveryField) {
  // e1: h1 (a = v1 -> b = v2) in f0, c = v0; h12 on b0 between h15 and h13. t2 = h3 (0->2), t3 = h11 (1->0).
  HalfedgeMesh m = build_halfedge_mesh(make_fan(4));
  const glm::dvec3 midpoint = (m.position(V(1)) + m.position(V(2))) * 0.5;
  const OpResult<VertexId> r = collapse(m, E(1));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_TRUE(valid_mesh(m));
  EXPECT_ID(r.value, V(1));
  EXPECT_EQ(m.position(V(1)), midpoint);

  // Deleted: v2, e1, e2 (= h2.edge), f0, h0, h1, h2, h12.
  EXPECT_FALSE(m.alive(V(2)));
  for (uint32_t e : {1u, 2u}) EXPECT_FALSE(m.alive(E(e))) << "e" << e;
  EXPECT_FALSE(m.alive(F(0)));
  for (uint32_t h : {0u, 1u, 2u, 12u}) EXPECT_FALSE(m.alive(H(h))) << "h" << h;

  // f1 = (0, 1, 3): h3 -> h4 -> h5;  f3 = (0, 4, 1): h9 -> h10 -> h11;  b0: h13 (1->4) -> h14 -> h15 (3->1).
  expect_halfedge(m, H(3), H(4), H(11), V(0), E(0), F(1));
  expect_halfedge(m, H(4), H(5), H(15), V(1), E(3), F(1));
  expect_halfedge(m, H(11), H(9), H(3), V(1), E(0), F(3));
  expect_halfedge(m, H(15), H(13), H(4), V(3), E(3), B(0));
  expect_halfedge(m, H(13), H(14), H(10), V(1), E(7), B(0));
  expect_halfedge(m, H(10), H(11), H(13), V(4), E(7), F(3));
  // e3 = h0.edge = e0 was held by h0 (dead): it moves to t2 = h3; so does c = v0's halfedge.
  EXPECT_ID(m.halfedge(E(0)), H(3));
  EXPECT_ID(m.halfedge(V(0)), H(3));
  EXPECT_ID(m.halfedge(V(1)), H(13));
  EXPECT_ID(m.halfedge(B(0)), H(13));  // was h12
  EXPECT_EQ(m.degree(B(0)), 3u);

  EXPECT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.num_edges(), 6u);
  EXPECT_EQ(m.num_faces(), 3u);
  EXPECT_EQ(m.num_halfedges(), 12u);
}

TEST(Collapse, ClosedMeshEdgeEveryTouchedField) {
  // cube e0: h0 (a = v0 -> b = v2) in f0 = (0,2,3), c = v3; h1 = h29 in f9 = (0,6,2), d = v6.
  // t2 = h23 (3->2), t3 = h3 (0->3), t4 = h26 (6->0), t5 = h18 (2->6); e2 = e1 and e5 = e13 die, e3 = e2 and
  // e4 = e16 stay.
  HalfedgeMesh m = build_halfedge_mesh(make_cube());
  const OpResult<VertexId> r = collapse(m, E(0));
  ASSERT_TRUE(r.ok()) << r.check.reason;
  EXPECT_TRUE(valid_mesh(m));
  EXPECT_ID(r.value, V(0));
  EXPECT_EQ(m.position(V(0)), glm::dvec3(-0.5, 0.0, -0.5));

  EXPECT_FALSE(m.alive(V(2)));
  for (uint32_t e : {0u, 1u, 13u}) EXPECT_FALSE(m.alive(E(e))) << "e" << e;
  for (uint32_t f : {0u, 9u}) EXPECT_FALSE(m.alive(F(f))) << "f" << f;
  for (uint32_t h : {0u, 1u, 2u, 27u, 28u, 29u}) EXPECT_FALSE(m.alive(H(h))) << "h" << h;

  expect_halfedge(m, H(23), H(21), H(3), V(3), E(2), F(7));
  expect_halfedge(m, H(3), H(4), H(23), V(0), E(2), F(1));
  expect_halfedge(m, H(26), H(24), H(18), V(6), E(16), F(8));
  expect_halfedge(m, H(18), H(19), H(26), V(0), E(16), F(6));
  // b's other outgoing halfedges now leave v0.
  expect_halfedge(m, H(21), H(22), H(20), V(0), E(14), F(7));
  expect_halfedge(m, H(20), H(18), H(21), V(7), E(14), F(6));
  EXPECT_EQ(corners(m, F(7)), (std::vector<uint32_t>{0, 7, 3}));
  EXPECT_EQ(corners(m, F(6)), (std::vector<uint32_t>{0, 6, 7}));
  // Pointers into the dead: e2.halfedge h2 -> t2 = h23, v3.halfedge h2 -> h23, v0.halfedge h0 -> t3 = h3;
  // e16.halfedge was h26 and v6.halfedge h11, both alive, so they stay.
  EXPECT_ID(m.halfedge(E(2)), H(23));
  EXPECT_ID(m.halfedge(E(16)), H(26));
  EXPECT_ID(m.halfedge(V(0)), H(3));
  EXPECT_ID(m.halfedge(V(3)), H(23));
  EXPECT_ID(m.halfedge(V(6)), H(11));

  EXPECT_EQ(m.num_vertices(), 7u);
  EXPECT_EQ(m.num_edges(), 15u);
  EXPECT_EQ(m.num_faces(), 10u);
  EXPECT_EQ(m.num_halfedges(), 30u);
  EXPECT_EQ(m.degree(V(0)), 6u);  // v0's 6 neighbours and v2's 4, less v0, v2, and v3, v6 counted twice
}

// A square pyramid: base v0 (0,0,0) v1 (1,0,0) v2 (1,1,0) v3 (0,1,0), apex v4; the base is split by the
// diagonal v0-v2, which is e8 (h12 0->2 in f4 = (0,2,1), h17 2->0 in f5 = (0,3,2)).
HalfedgeMesh pyramid() {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  for (auto f : {std::vector<uint32_t>{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 2, 1}, {0, 3, 2}}) {
    p.add_face(f);
  }
  return build_halfedge_mesh(p);
}

// A closed sphere of a quad f0 = (0,2,1,3) and two triangles f1 = (0,3,1), f2 = (1,2,0) on the other side,
// sharing the edge e4 = v1-v0 (e4.halfedge = h6, 1->0, in f1).
HalfedgeMesh quad_and_two_triangles() {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, -1, 0}, {0.5, 1, 0}};
  p.add_face({0, 2, 1, 3});
  p.add_face({0, 3, 1});
  p.add_face({1, 2, 0});
  return build_halfedge_mesh(p);
}

HalfedgeMesh lone_triangle() {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.add_face({0, 1, 2});
  return build_halfedge_mesh(p);
}

TEST(Collapse, RefusalsNameTheReasonAndChangeNothing) {
  struct Case {
    const char* what;
    HalfedgeMesh mesh;
    EdgeId edge;
    const char* reason;
  };
  const Case cases[] = {
      {"tetrahedron", build_halfedge_mesh(make_tetrahedron()), E(0),
       "collapsing e0 would fold f2 onto f3 (both would join the merged vertex, v2 and v3): a closed surface needs "
       "at least 4 vertices"},
      {"interior edge between boundary vertices", build_halfedge_mesh(make_grid(1, 1)), E(2),
       "v3 and v0 are both on the boundary but e2 is not; collapsing it would pinch the surface at the merged "
       "vertex"},
      {"lone triangle", lone_triangle(), E(0),
       "f0 is a lone triangle (all its edges are on the boundary); collapsing e0 would leave no face"},
      {"boundary loop of three", build_halfedge_mesh(make_fan(3)), E(1),
       "v1 and v2 are both joined to v3 (besides v0); collapsing e1 would join the merged vertex to v3 twice"},
      {"link condition inside", pyramid(), E(8),
       "v0 and v2 are both joined to v4 (besides v1 and v3); collapsing e8 would join the merged vertex to v4 "
       "twice"},
      {"face with both ends", quad_and_two_triangles(), E(4),
       "f0 has both v1 and v0 as corners; collapsing e4 would make it use the merged vertex twice"},
      {"quads", build_halfedge_mesh(make_cube_quads()), E(0),
       "f0 is not a triangle (4 sides); only edges between triangles can be collapsed"},
      {"past the end", build_halfedge_mesh(make_icosahedron()), E(30), "e30 does not exist"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    ASSERT_TRUE(valid_mesh(c.mesh));
    HalfedgeMesh m = c.mesh;
    const uint64_t version = m.version();
    EXPECT_EQ(can_collapse(m, c.edge).reason, c.reason);
    const OpResult<VertexId> r = collapse(m, c.edge);
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.value.valid());
    EXPECT_EQ(r.check.reason, c.reason);
    EXPECT_TRUE(m.same_as(c.mesh));
    EXPECT_EQ(m.version(), version);
  }
}

TEST(Collapse, EveryTetrahedronEdgeIsRefused) {
  const HalfedgeMesh start = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh m = start;
  for (uint32_t e = 0; e < 6; ++e) {
    const Check check = can_collapse(m, E(e));
    EXPECT_FALSE(check.ok) << "e" << e;
    EXPECT_NE(check.reason.find("at least 4 vertices"), std::string::npos) << check.reason;
    EXPECT_FALSE(collapse(m, E(e)).ok());
  }
  EXPECT_TRUE(m.same_as(start));
}

TEST(Collapse, BrokenFanAroundAnEndpointIsRefused) {
  // Break the twin of b's third outgoing halfedge (the first one no triangle check looks at).
  HalfedgeMesh m = build_halfedge_mesh(make_icosahedron());
  const HalfedgeId h0 = m.halfedge(E(0)), h1 = m.twin(h0);
  const HalfedgeId third = m.next(m.twin(m.next(h0)));  // leaves b after h1 and h0.next
  ASSERT_EQ(m.vertex(third), m.vertex(h1));
  const HalfedgeId victim = m.twin(third);
  m.set_twin(victim, m.next(victim));
  const HalfedgeMesh broken = m;
  const uint64_t version = m.version();
  const OpResult<VertexId> r = collapse(m, E(0));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.check.reason, "the halfedges around " + format_id(m.vertex(h1)) +
                                " do not form a closed fan (walking twin.next from " + format_id(h1) +
                                "); collapsing e0 needs the faces around it");
  EXPECT_TRUE(m.same_as(broken));
  EXPECT_EQ(m.version(), version);
}

TEST(Collapse, BrokenFaceBesideAnEndpointIsRefused) {
  // fan(4), e0: f1 = (0,2,3) lies in v0's fan but is neither f0 nor f3; cut its cycle after h4.
  HalfedgeMesh m = build_halfedge_mesh(make_fan(4));
  m.set_next(H(4), H(99));
  const HalfedgeMesh broken = m;
  const OpResult<VertexId> r = collapse(m, E(0));
  EXPECT_EQ(r.check.reason, "the next-cycle of f1 (beside v0) does not close; collapsing e0 needs the faces around it");
  EXPECT_TRUE(m.same_as(broken));
}

TEST(Collapse, CollapseThenSplitRestoresTheCounts) {
  // Not an undo (ids differ), but a split of a surviving spoke puts the vertex count back and stays valid.
  HalfedgeMesh m = build_halfedge_mesh(make_icosahedron());
  ASSERT_TRUE(collapse(m, E(0)).ok());
  EXPECT_TRUE(valid_mesh(m));
  EXPECT_EQ(m.num_vertices(), 11u);
  EXPECT_EQ(m.num_faces(), 18u);
  EdgeId live;
  for (EdgeId e : m.edges()) {
    live = e;
    break;
  }
  ASSERT_TRUE(split(m, live).ok());
  EXPECT_TRUE(valid_mesh(m));
  EXPECT_EQ(m.num_vertices(), 12u);
  EXPECT_EQ(m.num_faces(), 20u);
  EXPECT_EQ(m.num_edges(), 30u);
}

}  // namespace
}  // namespace meshedit
