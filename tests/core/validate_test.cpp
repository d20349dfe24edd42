// validate(): every fixture is valid; each invariant, broken by hand, gives exactly the expected
// violations (element, invariant, message); hostile meshes end with a report; random corruption of a
// torus is always caught unless it only re-chose an equally valid representative pointer.
//
// Ids used below follow mesh_build.h. Tetrahedron (faces {0,1,2} {0,3,1} {0,2,3} {1,3,2}):
//   f0: h0 0->1, h1 1->2, h2 2->0     f1: h3 0->3, h4 3->1, h5 1->0
//   f2: h6 0->2, h7 2->3, h8 3->0     f3: h9 1->3, h10 3->2, h11 2->1
//   twins h0-h5 (e0), h1-h11 (e1), h2-h6 (e2), h3-h8 (e3), h4-h9 (e4), h7-h10 (e5)
//   v0.halfedge h0, v1 h1, v2 h2, v3 h4; fans: v0 h0 h3 h6, v1 h1 h9 h5, v2 h2 h7 h11, v3 h4 h8 h10
// Single triangle {0,1,2}: f0 = h0 0->1, h1 1->2, h2 2->0; b0 = h3 1->0, h4 0->2, h5 2->1 (next h3 h4 h5);
//   twins h0-h3 (e0), h1-h5 (e1), h2-h4 (e2); v0.halfedge h4, v1 h3, v2 h5.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   fixtures                                       listing, tetrahedron, triangle, two_triangles_sharing_v0; every
//                                                  fixture valid; invariant_name
//   DeadReference                                  dead, past-the-end and missing references in every field
//   TwinOfTwin and TwinEdge                        twins that do not pair up or lie on different edges; an edge of four
//                                                  halfedges
//   FaceCycle                                      next-cycles that do not close, halfedges in the wrong face, faces
//                                                  and loops of two halfedges
//   NextNotPermutation, VertexHalfedge, VertexFan  a shared next, vertex halfedges leaving another vertex, fans that do
//                                                  not close, hourglasses, a vertex on the boundary twice
//   Orphan and NonFinitePosition                   elements no halfedge uses, a triangle turned into a boundary loop;
//                                                  NaN and infinite positions
//   report order, cap and summary                  the cap keeps the first in order and counts all; summary()
//   hostile meshes                                 expect_well_formed; every twin itself, one huge rho, random
//                                                  corruptions (many at once, 10k single ones of the torus)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/validate.h"

namespace meshedit {
namespace {

// ---- fixtures --------------------------------------------------------------------------------------

// One line per violation: "<invariant> <element>: <message>".
std::string listing(const ValidationReport& report) {
  std::string s;
  for (const Violation& v : report.violations) {
    s += std::string(invariant_name(v.invariant)) + " " + format_id(v.element) + ": " + v.message + "\n";
  }
  return s;
}

HalfedgeMesh tetrahedron() { return build_halfedge_mesh(make_tetrahedron()); }

HalfedgeMesh triangle() {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.add_face({0, 1, 2});
  return build_halfedge_mesh(p);
}

// Two triangles {0,1,2} and {3,4,5}: f0 = h0 h1 h2, f1 = h3 h4 h5; b0 = h6 1->0, h7 0->2, h8 2->1;
// b1 = h9 4->3, h10 3->5, h11 5->4. Then v3 is merged into v0 (h3 and h10 now leave v0; v3 deleted).
HalfedgeMesh two_triangles_sharing_v0() {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {-1, 0, 0}, {0, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({3, 4, 5});
  HalfedgeMesh m = build_halfedge_mesh(p);
  m.set_vertex(HalfedgeId(3), VertexId(0));
  m.set_vertex(HalfedgeId(10), VertexId(0));
  m.delete_element(VertexId(3));
  return m;
}

TEST(Validate, EveryFixtureIsValid) {
  const PolygonMesh fixtures[] = {make_tetrahedron(), make_cube(),  make_cube_quads(), make_icosahedron(),
                                  make_grid(3, 2),    make_fan(50), make_torus(8, 6)};
  for (const PolygonMesh& p : fixtures) {
    const ValidationReport report = validate(build_halfedge_mesh(p));
    EXPECT_TRUE(report.ok()) << listing(report);
    EXPECT_EQ(report.total, 0u);
    EXPECT_TRUE(report.violations.empty());
    EXPECT_EQ(report.summary(), "valid");
  }
}

TEST(Validate, EmptyMeshIsValid) { EXPECT_TRUE(validate(HalfedgeMesh()).ok()); }

TEST(Validate, InvariantNames) {
  EXPECT_STREQ(invariant_name(Invariant::DeadReference), "dead reference");
  EXPECT_STREQ(invariant_name(Invariant::TwinOfTwin), "twin of twin");
  EXPECT_STREQ(invariant_name(Invariant::TwinEdge), "twin edge");
  EXPECT_STREQ(invariant_name(Invariant::FaceCycle), "face cycle");
  EXPECT_STREQ(invariant_name(Invariant::NextNotPermutation), "next not permutation");
  EXPECT_STREQ(invariant_name(Invariant::VertexHalfedge), "vertex halfedge");
  EXPECT_STREQ(invariant_name(Invariant::VertexFan), "vertex fan");
  EXPECT_STREQ(invariant_name(Invariant::Orphan), "orphan");
  EXPECT_STREQ(invariant_name(Invariant::NonFinitePosition), "non-finite position");
}

// ---- DeadReference ---------------------------------------------------------------------------------

TEST(Validate, FaceHalfedgeDead) {
  HalfedgeMesh m = tetrahedron();
  const HalfedgeId dead = m.new_halfedge();
  m.delete_element(dead);
  m.set_halfedge(FaceId::face(0), dead);
  EXPECT_EQ(listing(validate(m)), "dead reference f0: f0.halfedge is h12, which is dead\n");
}

TEST(Validate, VertexHalfedgePastTheEnd) {
  HalfedgeMesh m = tetrahedron();
  m.set_halfedge(VertexId(0), HalfedgeId(999));
  const ValidationReport report = validate(m);
  ASSERT_EQ(report.total, 1u);
  EXPECT_EQ(report.violations[0].element, ElementRef(VertexId(0)));
  EXPECT_EQ(report.violations[0].invariant, Invariant::DeadReference);
  EXPECT_EQ(report.violations[0].message, "v0.halfedge is h999, past the end (12 halfedge slots)");
}

TEST(Validate, TwinPastTheEnd) {
  HalfedgeMesh m = tetrahedron();
  m.set_twin(HalfedgeId(0), HalfedgeId(12));
  EXPECT_EQ(listing(validate(m)),
            "dead reference h0: h0.twin is h12, past the end (12 halfedge slots)\n"
            "twin of twin h5: h5.twin is h0, but h0.twin is h12 (should be h5)\n");
}

TEST(Validate, NextInvalid) {
  HalfedgeMesh m = tetrahedron();
  m.set_next(HalfedgeId(0), HalfedgeId());
  EXPECT_EQ(listing(validate(m)),
            "dead reference h0: h0.next is - (none)\n"
            "next not permutation h1: no live halfedge has h1 as its next\n");
}

TEST(Validate, FaceOutOfRangeBoundary) {
  HalfedgeMesh m = tetrahedron();
  m.set_face(HalfedgeId(0), FaceId::boundary(3));
  EXPECT_EQ(listing(validate(m)),
            "dead reference h0: h0.face is b3, past the end (0 boundary slots)\n"
            "face cycle f0: f0.halfedge is h0, but h0.face is b3\n");
  m = tetrahedron();
  m.set_face(HalfedgeId(1), FaceId(0x7FFFFFFEu));
  EXPECT_EQ(listing(validate(m)), "dead reference h1: h1.face is f2147483646, past the end (4 face slots)\n");
}

TEST(Validate, DeletedVertexEdgeFace) {
  HalfedgeMesh m = tetrahedron();
  m.delete_element(VertexId(0));
  EXPECT_EQ(listing(validate(m)),
            "dead reference h0: h0.vertex is v0, which is dead\n"
            "dead reference h3: h3.vertex is v0, which is dead\n"
            "dead reference h6: h6.vertex is v0, which is dead\n");
  m = tetrahedron();
  m.delete_element(EdgeId(0));
  EXPECT_EQ(listing(validate(m)),
            "dead reference h0: h0.edge is e0, which is dead\n"
            "dead reference h5: h5.edge is e0, which is dead\n");
  m = tetrahedron();
  m.delete_element(FaceId::face(0));
  EXPECT_EQ(listing(validate(m)),
            "dead reference h0: h0.face is f0, which is dead\n"
            "dead reference h1: h1.face is f0, which is dead\n"
            "dead reference h2: h2.face is f0, which is dead\n");
}

TEST(Validate, DeletedHalfedge) {
  HalfedgeMesh m = tetrahedron();
  m.delete_element(HalfedgeId(0));
  EXPECT_EQ(listing(validate(m)),
            "dead reference v0: v0.halfedge is h0, which is dead\n"
            "dead reference h2: h2.next is h0, which is dead\n"
            "dead reference h5: h5.twin is h0, which is dead\n"
            "dead reference e0: e0.halfedge is h0, which is dead\n"
            "dead reference f0: f0.halfedge is h0, which is dead\n"
            "next not permutation h1: no live halfedge has h1 as its next\n");
}

// ---- TwinOfTwin and TwinEdge -----------------------------------------------------------------------

TEST(Validate, TwinOfTwin) {
  HalfedgeMesh m = tetrahedron();
  m.set_twin(HalfedgeId(0), HalfedgeId(1));
  EXPECT_EQ(listing(validate(m)),
            "twin of twin h0: h0.twin is h1, but h1.twin is h11 (should be h0)\n"
            "twin of twin h5: h5.twin is h0, but h0.twin is h1 (should be h5)\n"
            "vertex fan v0: v0's fan does not close: h0.twin is h1, whose next h2 leaves v2, not v0\n");
}

TEST(Validate, TwinIsItself) {
  HalfedgeMesh m = tetrahedron();
  m.set_twin(HalfedgeId(0), HalfedgeId(0));
  const ValidationReport report = validate(m);
  ASSERT_GE(report.violations.size(), 1u);
  EXPECT_EQ(report.violations[0].invariant, Invariant::TwinOfTwin);
  EXPECT_EQ(report.violations[0].element, ElementRef(HalfedgeId(0)));
  EXPECT_EQ(report.violations[0].message, "h0.twin is h0 itself");
  EXPECT_EQ(listing(report),
            "twin of twin h0: h0.twin is h0 itself\n"
            "twin of twin h5: h5.twin is h0, but h0.twin is h0 (should be h5)\n"
            "vertex fan v0: v0's fan does not close: h0.twin is h0, whose next h1 leaves v1, not v0\n");
}

TEST(Validate, TwinsOnDifferentEdges) {
  HalfedgeMesh m = tetrahedron();
  m.set_edge(HalfedgeId(0), EdgeId(1));
  EXPECT_EQ(listing(validate(m)),
            "twin edge h0: h0 and its twin h5 lie on different edges (e1 and e0)\n"
            "twin edge e0: e0.halfedge is h0, but h0.edge is e1\n"
            "twin edge e1: e1 has 3 halfedges (h0 h1 h11); an edge has exactly two\n");
}

TEST(Validate, EdgeHalfedgeOnAnotherEdge) {
  HalfedgeMesh m = tetrahedron();
  m.set_halfedge(EdgeId(0), HalfedgeId(1));
  EXPECT_EQ(listing(validate(m)), "twin edge e0: e0.halfedge is h1, but h1.edge is e1\n");
}

TEST(Validate, EdgeWithFourHalfedges) {
  // h4/h9 (e4) moved onto e0, and e4 deleted: only the count shows it.
  HalfedgeMesh m = tetrahedron();
  m.set_edge(HalfedgeId(4), EdgeId(0));
  m.set_edge(HalfedgeId(9), EdgeId(0));
  m.delete_element(EdgeId(4));
  EXPECT_EQ(listing(validate(m)), "twin edge e0: e0 has 4 halfedges (h0 h4 h5 h9); an edge has exactly two\n");
}

// ---- FaceCycle -------------------------------------------------------------------------------------

TEST(Validate, NextFormsRho) {
  // f1: h3 -> h4 -> h5 -> h4 never returns to h3.
  HalfedgeMesh m = tetrahedron();
  m.set_next(HalfedgeId(5), HalfedgeId(4));
  EXPECT_EQ(listing(validate(m)),
            "face cycle f1: f1's next-cycle does not close: h3 h4 h5 then comes back to h4, never to f1.halfedge h3\n"
            "next not permutation h3: no live halfedge has h3 as its next\n"
            "next not permutation h4: h4 is the next of 2 halfedges (h3 h5)\n"
            "vertex fan v0: v0's fan does not close: h0.twin is h5, whose next h4 leaves v3, not v0\n");
}

TEST(Validate, NextRunsIntoAnotherFace) {
  // h2.next = h3: f0's walk runs into f1's cycle and loops there; f1's walk then meets f0's claim.
  HalfedgeMesh m = tetrahedron();
  m.set_next(HalfedgeId(2), HalfedgeId(3));
  EXPECT_EQ(listing(validate(m)),
            "face cycle f0: f0's next-cycle does not close: h0 h1 h2 h3 h4 h5 then comes back to h3, never to "
            "f0.halfedge h0\n"
            "face cycle f1: f1's next-cycle does not close: it reaches h3, which is in f0's next-cycle\n"
            "next not permutation h0: no live halfedge has h0 as its next\n"
            "next not permutation h3: h3 is the next of 2 halfedges (h2 h5)\n"
            "vertex fan v0: v0's fan does not close: h0 h3 h6 then comes back to h3, never to v0.halfedge h0\n");
}

TEST(Validate, HalfedgeInTheWrongFace) {
  HalfedgeMesh m = tetrahedron();
  m.set_face(HalfedgeId(1), FaceId::face(1));
  EXPECT_EQ(listing(validate(m)), "face cycle h1: h1.face is f1, but h1 is in f0's next-cycle\n");
}

TEST(Validate, FaceHalfedgeInAnotherFace) {
  HalfedgeMesh m = tetrahedron();
  m.set_halfedge(FaceId::face(0), HalfedgeId(3));
  EXPECT_EQ(listing(validate(m)), "face cycle f0: f0.halfedge is h3, but h3.face is f1\n");
}

TEST(Validate, FaceOfTwoHalfedges) {
  // f0: h0 -> h1 -> h0; h2 still says f0, and nobody's next is h2.
  HalfedgeMesh m = tetrahedron();
  m.set_next(HalfedgeId(1), HalfedgeId(0));
  EXPECT_EQ(listing(validate(m)),
            "face cycle h2: h2.face is f0, but h2 is not in f0's next-cycle\n"
            "face cycle f0: f0's next-cycle has only 2 halfedges (h0 h1); a face needs at least 3\n"
            "next not permutation h0: h0 is the next of 2 halfedges (h1 h2)\n"
            "next not permutation h2: no live halfedge has h2 as its next\n"
            "vertex fan v2: v2's fan does not close: h11.twin is h1, whose next h0 leaves v0, not v2\n");
}

TEST(Validate, BoundaryLoopOfTwoHalfedges) {
  HalfedgeMesh m = triangle();
  ASSERT_TRUE(validate(m).ok());
  m.set_next(HalfedgeId(4), HalfedgeId(3));
  EXPECT_EQ(listing(validate(m)),
            "face cycle h5: h5.face is b0, but h5 is not in b0's next-cycle\n"
            "face cycle b0: b0's next-cycle has only 2 halfedges (h3 h4); a boundary loop needs at least 3\n"
            "next not permutation h3: h3 is the next of 2 halfedges (h4 h5)\n"
            "next not permutation h5: no live halfedge has h5 as its next\n"
            "vertex fan v2: v2's fan does not close: h2.twin is h4, whose next h3 leaves v1, not v2\n");
}

// ---- NextNotPermutation, VertexHalfedge, VertexFan -------------------------------------------------

TEST(Validate, NextSharedByTwo) {
  HalfedgeMesh m = tetrahedron();
  m.set_next(HalfedgeId(0), HalfedgeId(2));
  const ValidationReport report = validate(m);
  const auto it = std::find_if(report.violations.begin(), report.violations.end(),
                               [](const Violation& v) { return v.invariant == Invariant::NextNotPermutation; });
  ASSERT_NE(it, report.violations.end());
  EXPECT_EQ(it->element, ElementRef(HalfedgeId(1)));
  EXPECT_EQ(it->message, "no live halfedge has h1 as its next");
  EXPECT_EQ(listing(report),
            "face cycle h1: h1.face is f0, but h1 is not in f0's next-cycle\n"
            "face cycle f0: f0's next-cycle has only 2 halfedges (h0 h2); a face needs at least 3\n"
            "next not permutation h1: no live halfedge has h1 as its next\n"
            "next not permutation h2: h2 is the next of 2 halfedges (h0 h1)\n"
            "vertex fan v1: v1's fan does not close: h5.twin is h0, whose next h2 leaves v2, not v1\n");
}

TEST(Validate, VertexHalfedgeLeavesAnotherVertex) {
  HalfedgeMesh m = tetrahedron();
  m.set_halfedge(VertexId(0), HalfedgeId(1));
  EXPECT_EQ(listing(validate(m)), "vertex halfedge v0: v0.halfedge is h1, but h1 leaves v1\n");
}

TEST(Validate, HalfedgeLeavesTheWrongVertex) {
  HalfedgeMesh m = tetrahedron();
  m.set_vertex(HalfedgeId(0), VertexId(2));
  EXPECT_EQ(listing(validate(m)),
            "vertex halfedge v0: v0.halfedge is h0, but h0 leaves v2\n"
            "vertex fan v2: v2 has two separate fans (hourglass): h2 h7 h11 | h0\n");
}

TEST(Validate, FanFormsRho) {
  // h6.twin = h5, so from v0: h0 -> h3 -> h6 -> next(h5) = h3 again.
  HalfedgeMesh m = tetrahedron();
  m.set_twin(HalfedgeId(6), HalfedgeId(5));
  EXPECT_EQ(listing(validate(m)),
            "twin of twin h2: h2.twin is h6, but h6.twin is h5 (should be h2)\n"
            "twin of twin h6: h6.twin is h5, but h5.twin is h0 (should be h6)\n"
            "vertex fan v0: v0's fan does not close: h0 h3 h6 then comes back to h3, never to v0.halfedge h0\n");
}

TEST(Validate, HourglassOfTwoTetrahedra) {
  // Two tetrahedra (v0..v3 and v4..v7) with v4 merged into v0: v0 has two closed fans.
  PolygonMesh p = make_tetrahedron();
  PolygonMesh second = make_tetrahedron();
  for (auto& q : second.positions) q.x += 3;
  p.append(second);
  HalfedgeMesh m = build_halfedge_mesh(p);
  ASSERT_TRUE(validate(m).ok());
  for (HalfedgeId h : {HalfedgeId(12), HalfedgeId(15), HalfedgeId(18)}) {
    ASSERT_EQ(m.vertex(h), VertexId(4));
    m.set_vertex(h, VertexId(0));
  }
  m.delete_element(VertexId(4));
  EXPECT_EQ(listing(validate(m)), "vertex fan v0: v0 has two separate fans (hourglass): h0 h3 h6 | h12 h15 h18\n");
}

TEST(Validate, VertexOnTwoBoundaryLoops) {
  // v0 is on b0 and on b1 (two holes meeting at a vertex): the fan from v0.halfedge misses f1's side.
  const HalfedgeMesh m = two_triangles_sharing_v0();
  EXPECT_EQ(listing(validate(m)), "vertex fan v0: v0 has two separate fans (hourglass): h7 h0 | h3 h10\n");
}

TEST(Validate, VertexOnOneBoundaryLoopTwice) {
  // The two loops joined into one that passes v0 twice (a pinched hole): one fan, two boundary halfedges.
  HalfedgeMesh m = two_triangles_sharing_v0();
  m.set_next(HalfedgeId(6), HalfedgeId(10));
  m.set_next(HalfedgeId(9), HalfedgeId(7));
  for (HalfedgeId h : {HalfedgeId(9), HalfedgeId(10), HalfedgeId(11)}) m.set_face(h, FaceId::boundary(0));
  m.delete_element(FaceId::boundary(1));
  EXPECT_EQ(listing(validate(m)),
            "vertex fan v0: v0 is on the boundary more than once: h7 (b0) h10 (b0); at most one boundary halfedge "
            "may leave a vertex\n");
}

// ---- Orphan and NonFinitePosition ------------------------------------------------------------------

TEST(Validate, NewElementsWithNoConnections) {
  HalfedgeMesh m = tetrahedron();
  m.new_vertex();
  m.new_edge();
  m.new_face();
  m.new_boundary();
  EXPECT_EQ(listing(validate(m)),
            "dead reference v4: v4.halfedge is - (none)\n"
            "dead reference e6: e6.halfedge is - (none)\n"
            "dead reference f4: f4.halfedge is - (none)\n"
            "dead reference b0: b0.halfedge is - (none)\n"
            "orphan v4: v4 is orphaned: no live halfedge leaves it\n"
            "orphan e6: e6 is orphaned: no live halfedge lies on it\n"
            "orphan f4: f4 is orphaned: no live halfedge lies in it\n"
            "orphan b0: b0 is orphaned: no live halfedge lies in it\n");
}

TEST(Validate, EdgeWithNoHalfedgesPointingAtALiveHalfedge) {
  // e6.halfedge is h0, but h0 lies on e0, and no halfedge lies on e6.
  HalfedgeMesh m = tetrahedron();
  const EdgeId e = m.new_edge();
  m.set_halfedge(e, HalfedgeId(0));
  EXPECT_EQ(listing(validate(m)),
            "twin edge e6: e6.halfedge is h0, but h0.edge is e0\n"
            "orphan e6: e6 is orphaned: no live halfedge lies on it\n");
}

TEST(Validate, TriangleTurnedIntoABoundaryLoop) {
  // Nothing but boundary: every edge has boundary on both sides, every vertex is only on boundary loops.
  HalfedgeMesh m = triangle();
  const FaceId b1 = m.new_boundary();
  for (uint32_t h = 0; h < 3; ++h) m.set_face(HalfedgeId(h), b1);
  m.set_halfedge(b1, HalfedgeId(0));
  m.delete_element(FaceId::face(0));
  EXPECT_EQ(listing(validate(m)),
            "vertex fan v0: v0 is on the boundary more than once: h4 (b0) h0 (b1); at most one boundary halfedge "
            "may leave a vertex\n"
            "vertex fan v1: v1 is on the boundary more than once: h3 (b0) h1 (b1); at most one boundary halfedge "
            "may leave a vertex\n"
            "vertex fan v2: v2 is on the boundary more than once: h5 (b0) h2 (b1); at most one boundary halfedge "
            "may leave a vertex\n"
            "orphan v0: v0 is orphaned: every face around it is a boundary loop\n"
            "orphan v1: v1 is orphaned: every face around it is a boundary loop\n"
            "orphan v2: v2 is orphaned: every face around it is a boundary loop\n"
            "orphan e0: e0 is orphaned: both its sides are boundary loops (b1 and b0)\n"
            "orphan e1: e1 is orphaned: both its sides are boundary loops (b1 and b0)\n"
            "orphan e2: e2 is orphaned: both its sides are boundary loops (b1 and b0)\n");
}

TEST(Validate, NonFinitePositions) {
  HalfedgeMesh m = tetrahedron();
  m.set_position(VertexId(1), {0, std::numeric_limits<double>::quiet_NaN(), 1});
  m.set_position(VertexId(3), {-std::numeric_limits<double>::infinity(), 0.5, 2});
  EXPECT_EQ(listing(validate(m)),
            "non-finite position v1: v1.position is (0, nan, 1)\n"
            "non-finite position v3: v3.position is (-inf, 0.5, 2)\n");
}

// ---- report order, cap and summary -----------------------------------------------------------------

TEST(Validate, CapKeepsTheFirstInOrderAndCountsAll) {
  HalfedgeMesh m = tetrahedron();
  m.set_position(VertexId(0), {std::numeric_limits<double>::quiet_NaN(), 0, 0});  // found first, reported last
  m.set_twin(HalfedgeId(0), HalfedgeId(1));
  const ValidationReport full = validate(m);
  ASSERT_EQ(full.total, 4u);
  const ValidationReport capped = validate(m, 2);
  EXPECT_EQ(capped.total, 4u);
  EXPECT_FALSE(capped.ok());
  EXPECT_EQ(listing(capped),
            "twin of twin h0: h0.twin is h1, but h1.twin is h11 (should be h0)\n"
            "twin of twin h5: h5.twin is h0, but h0.twin is h1 (should be h5)\n");
  EXPECT_EQ(full.violations.back().invariant, Invariant::NonFinitePosition);
  EXPECT_EQ(capped.summary(), "4 problems; first: h0.twin is h1, but h1.twin is h11 (should be h0)");
  const ValidationReport none = validate(m, 0);
  EXPECT_EQ(none.total, 4u);
  EXPECT_TRUE(none.violations.empty());
  EXPECT_EQ(none.summary(), "4 problems");
  m = tetrahedron();
  m.set_halfedge(VertexId(0), HalfedgeId(1));
  EXPECT_EQ(validate(m).summary(), "1 problem; first: v0.halfedge is h1, but h1 leaves v1");
}

// ---- hostile meshes --------------------------------------------------------------------------------

// Sorted by (invariant, element) and capped: what every report must look like.
void expect_well_formed(const ValidationReport& report, size_t cap) {
  EXPECT_EQ(report.violations.size(), std::min(report.total, cap));
  for (size_t i = 1; i < report.violations.size(); ++i) {
    const Violation& a = report.violations[i - 1];
    const Violation& b = report.violations[i];
    EXPECT_TRUE(a.invariant < b.invariant || (a.invariant == b.invariant && !(b.element < a.element)));
  }
  for (const Violation& v : report.violations) EXPECT_FALSE(v.message.empty());
}

TEST(Validate, EveryTwinIsItselfOnABigMesh) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(40, 20));
  for (HalfedgeId h : m.halfedges()) m.set_twin(h, h);
  const ValidationReport report = validate(m);
  expect_well_formed(report, 100);
  // Per halfedge: twin is itself (TwinOfTwin); per vertex: the fan walk leaves the vertex at once.
  EXPECT_EQ(report.total, m.num_halfedges() + m.num_vertices());
  EXPECT_EQ(report.violations[0].message, "h0.twin is h0 itself");
}

TEST(Validate, OneHugeRhoAndSharedCycles) {
  // Every next points to h1, every face's halfedge is h0: walks must stop early, not loop.
  HalfedgeMesh m = build_halfedge_mesh(make_torus(8, 6));
  for (HalfedgeId h : m.halfedges()) m.set_next(h, HalfedgeId(1));
  for (FaceId f : m.faces()) m.set_halfedge(f, HalfedgeId(0));
  const ValidationReport report = validate(m, 1000);
  expect_well_formed(report, 1000);
  EXPECT_GT(report.total, 0u);
  EXPECT_NE(listing(report).find("f0's next-cycle does not close: h0 h1 then comes back to h1, never to "
                                 "f0.halfedge h0"),
            std::string::npos);
  EXPECT_NE(listing(report).find("h1 is the next of 288 halfedges (h0 h1 h2 h3 h4 h5 h6 h7 ... (280 more))"),
            std::string::npos);
}

// Random values for any field, many at once: validate must end with a well-formed report.
TEST(Validate, ManyRandomCorruptionsAtOnceNeverCrash) {
  std::mt19937 rng(7);
  const HalfedgeMesh original = build_halfedge_mesh(make_grid(4, 3));
  auto any_value = [&](uint32_t capacity) -> uint32_t {
    switch (rng() % 4) {
      case 0: return kInvalidIndex;
      case 1: return capacity + rng() % 4;
      case 2: return rng();
      default: return rng() % capacity;
    }
  };
  for (int round = 0; round < 300; ++round) {
    HalfedgeMesh m = original;
    for (int k = 0; k < 40; ++k) {
      const HalfedgeId h(rng() % m.halfedge_capacity());
      switch (rng() % 10) {
        case 0: m.set_next(h, HalfedgeId(any_value(m.halfedge_capacity()))); break;
        case 1: m.set_twin(h, HalfedgeId(any_value(m.halfedge_capacity()))); break;
        case 2: m.set_vertex(h, VertexId(any_value(m.vertex_capacity()))); break;
        case 3: m.set_edge(h, EdgeId(any_value(m.edge_capacity()))); break;
        case 4: m.set_face(h, FaceId(any_value(m.face_capacity()) | (rng() % 2 ? FaceId::kBoundaryBit : 0))); break;
        case 5:
          m.set_halfedge(VertexId(rng() % m.vertex_capacity()), HalfedgeId(any_value(m.halfedge_capacity())));
          break;
        case 6: m.set_halfedge(EdgeId(rng() % m.edge_capacity()), HalfedgeId(any_value(m.halfedge_capacity()))); break;
        case 7:
          m.set_halfedge(FaceId::face(rng() % m.face_capacity()), HalfedgeId(any_value(m.halfedge_capacity())));
          break;
        case 8: m.set_halfedge(FaceId::boundary(0), HalfedgeId(any_value(m.halfedge_capacity()))); break;
        default: m.delete_element(h); break;
      }
    }
    const ValidationReport report = validate(m, 50);
    expect_well_formed(report, 50);
  }
}

// 10k single-field corruptions of the torus: each is reported, unless it only picked another valid
// representative (v.halfedge another outgoing halfedge, e.halfedge the twin, f.halfedge another of f's).
TEST(Validate, RandomSingleCorruptionsOfTheTorusAreAllCaught) {
  const HalfedgeMesh torus = build_halfedge_mesh(make_torus(8, 6));
  ASSERT_TRUE(validate(torus).ok());
  std::mt19937 rng(20240611);
  const uint32_t H = torus.halfedge_capacity(), V = torus.vertex_capacity(), E = torus.edge_capacity(),
                 F = torus.face_capacity();
  auto value = [&](uint32_t capacity) -> uint32_t {
    const uint32_t r = rng() % 10;
    if (r == 0) return kInvalidIndex;
    if (r == 1) return capacity + rng() % 100;
    return rng() % capacity;
  };
  int corruptions = 0, rechosen = 0, unchanged = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    HalfedgeMesh m = torus;
    bool changed = true, harmless = false;
    const uint32_t kind = rng() % 9;
    std::string what;
    if (kind < 5) {
      const HalfedgeId h(rng() % H);
      what = format_id(h);
      switch (kind) {
        case 0: {
          const HalfedgeId x(value(H));
          changed = x != m.next(h);
          m.set_next(h, x);
          what += ".next";
          break;
        }
        case 1: {
          const HalfedgeId x(value(H));
          changed = x != m.twin(h);
          m.set_twin(h, x);
          what += ".twin";
          break;
        }
        case 2: {
          const VertexId x(value(V));
          changed = x != m.vertex(h);
          m.set_vertex(h, x);
          what += ".vertex";
          break;
        }
        case 3: {
          const EdgeId x(value(E));
          changed = x != m.edge(h);
          m.set_edge(h, x);
          what += ".edge";
          break;
        }
        default: {
          const FaceId x = rng() % 10 == 0 ? FaceId::boundary(rng() % 3) : FaceId(value(F));
          changed = x != m.face(h);
          m.set_face(h, x);
          what += ".face";
        }
      }
    } else if (kind == 5) {
      const VertexId v(rng() % V);
      const HalfedgeId x(value(H));
      changed = x != m.halfedge(v);
      harmless = m.alive(x) && m.vertex(x) == v;
      m.set_halfedge(v, x);
      what = format_id(v) + ".halfedge";
    } else if (kind == 6) {
      const EdgeId e(rng() % E);
      const HalfedgeId x = rng() % 4 == 0 ? m.twin(m.halfedge(e)) : HalfedgeId(value(H));
      changed = x != m.halfedge(e);
      harmless = x == m.twin(m.halfedge(e));
      m.set_halfedge(e, x);
      what = format_id(e) + ".halfedge";
    } else if (kind == 7) {
      const FaceId f = FaceId::face(rng() % F);
      const HalfedgeId x(value(H));
      changed = x != m.halfedge(f);
      harmless = m.alive(x) && m.face(x) == f;
      m.set_halfedge(f, x);
      what = format_id(f) + ".halfedge";
    } else {
      switch (rng() % 4) {
        case 0: {
          const VertexId v(rng() % V);
          m.delete_element(v);
          what = "delete " + format_id(v);
          break;
        }
        case 1: {
          const HalfedgeId h(rng() % H);
          m.delete_element(h);
          what = "delete " + format_id(h);
          break;
        }
        case 2: {
          const EdgeId e(rng() % E);
          m.delete_element(e);
          what = "delete " + format_id(e);
          break;
        }
        default: {
          const FaceId f = FaceId::face(rng() % F);
          m.delete_element(f);
          what = "delete " + format_id(f);
        }
      }
    }
    const ValidationReport report = validate(m);
    expect_well_formed(report, 100);
    if (!changed) {
      ++unchanged;
      EXPECT_TRUE(report.ok()) << what;
    } else if (harmless) {
      ++rechosen;
      EXPECT_TRUE(report.ok()) << what << "\n" << listing(report);
    } else {
      ++corruptions;
      EXPECT_FALSE(report.ok()) << what;
    }
  }
  // The trial mix really exercised all three outcomes.
  EXPECT_GT(corruptions, 8000);
  EXPECT_GT(rechosen, 100);
  EXPECT_GT(unchanged, 10);
}

}  // namespace
}  // namespace meshedit
