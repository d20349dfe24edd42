// HalfedgeMesh storage: allocation, tombstones, liveness past the end, iteration, setters, the bounded
// walks (on valid and deliberately broken cycles), equality and version bookkeeping.
// Tetrahedron ids (mesh_build.h): f0 = h0 0->1, h1 1->2, h2 2->0; f1 = h3 0->3, h4 3->1, h5 1->0;
// f2 = h6 0->2, h7 2->3, h8 3->0; f3 = h9 1->3, h10 3->2, h11 2->1; twins h0-h5 h1-h11 h2-h6 h3-h8 h4-h9 h7-h10.
#include <gtest/gtest.h>

#include <vector>

#include "core/halfedge_mesh.h"
#include "core/mesh_build.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

HalfedgeMesh tetrahedron() { return build_halfedge_mesh(make_tetrahedron()); }

template <class Range>
auto collect(const Range& range) {
  std::vector<decltype(*range.begin())> out;
  for (auto id : range) out.push_back(id);
  return out;
}

TEST(HalfedgeMesh, EmptyMesh) {
  const HalfedgeMesh m;
  EXPECT_EQ(m.num_vertices(), 0u);
  EXPECT_EQ(m.num_halfedges(), 0u);
  EXPECT_EQ(m.num_edges(), 0u);
  EXPECT_EQ(m.num_faces(), 0u);
  EXPECT_EQ(m.num_boundaries(), 0u);
  EXPECT_EQ(m.halfedge_capacity(), 0u);
  EXPECT_EQ(m.version(), 0u);
  EXPECT_FALSE(m.alive(VertexId(0)));
  EXPECT_FALSE(m.alive(FaceId::boundary(0)));
  EXPECT_TRUE(collect(m.vertices()).empty());
}

TEST(HalfedgeMesh, AllocationAppendsLiveElementsWithInvalidPointers) {
  HalfedgeMesh m;
  EXPECT_EQ(m.new_vertex({1, 2, 3}), VertexId(0));
  const VertexId v1 = m.new_vertex();
  EXPECT_EQ(v1, VertexId(1));
  EXPECT_EQ(m.position(VertexId(0)), glm::dvec3(1, 2, 3));
  EXPECT_EQ(m.position(v1), glm::dvec3(0, 0, 0));
  EXPECT_FALSE(m.halfedge(v1).valid());

  const HalfedgeId h = m.new_halfedge();
  EXPECT_EQ(h, HalfedgeId(0));
  EXPECT_FALSE(m.next(h).valid());
  EXPECT_FALSE(m.twin(h).valid());
  EXPECT_FALSE(m.vertex(h).valid());
  EXPECT_FALSE(m.edge(h).valid());
  EXPECT_FALSE(m.face(h).valid());

  EXPECT_EQ(m.new_edge(), EdgeId(0));
  EXPECT_EQ(m.new_edge(), EdgeId(1));
  const FaceId f = m.new_face();
  const FaceId b = m.new_boundary();
  EXPECT_EQ(f, FaceId::face(0));
  EXPECT_FALSE(f.is_boundary());
  EXPECT_EQ(b, FaceId::boundary(0));
  EXPECT_TRUE(b.is_boundary());
  EXPECT_EQ(b.slot(), 0u);
  EXPECT_FALSE(m.halfedge(f).valid());
  EXPECT_FALSE(m.halfedge(b).valid());

  EXPECT_EQ(m.num_vertices(), 2u);
  EXPECT_EQ(m.num_halfedges(), 1u);
  EXPECT_EQ(m.num_edges(), 2u);
  EXPECT_EQ(m.num_faces(), 1u);
  EXPECT_EQ(m.num_boundaries(), 1u);
  EXPECT_EQ(m.capacity(ElementKind::Vertex), 2u);
  EXPECT_EQ(m.capacity(ElementKind::Halfedge), 1u);
  EXPECT_EQ(m.capacity(ElementKind::Edge), 2u);
  EXPECT_EQ(m.capacity(ElementKind::Face), 1u);
  EXPECT_EQ(m.capacity(ElementKind::Boundary), 1u);
  // Faces and boundary loops are separate arrays: f0 and b0 are different elements.
  m.delete_element(f);
  EXPECT_FALSE(m.alive(f));
  EXPECT_TRUE(m.alive(b));
}

TEST(HalfedgeMesh, DeletionLeavesATombstone) {
  HalfedgeMesh m = tetrahedron();
  m.delete_element(HalfedgeId(4));
  EXPECT_FALSE(m.alive(HalfedgeId(4)));
  EXPECT_EQ(m.num_halfedges(), 11u);
  EXPECT_EQ(m.halfedge_capacity(), 12u);
  // Stored pointers stay readable for the tables.
  EXPECT_EQ(m.next(HalfedgeId(4)), HalfedgeId(5));
  EXPECT_EQ(m.twin(HalfedgeId(4)), HalfedgeId(9));
  // The id is not reused.
  EXPECT_EQ(m.new_halfedge(), HalfedgeId(12));
  // Deleting a dead element changes nothing, not even the version.
  const uint64_t version = m.version();
  m.delete_element(HalfedgeId(4));
  m.delete_element(HalfedgeId(99));
  EXPECT_EQ(m.num_halfedges(), 12u);
  EXPECT_EQ(m.version(), version);

  m.delete_element(VertexId(2));
  m.delete_element(EdgeId(5));
  m.delete_element(FaceId::face(3));
  EXPECT_EQ(m.num_vertices(), 3u);
  EXPECT_EQ(m.num_edges(), 5u);
  EXPECT_EQ(m.num_faces(), 3u);
  EXPECT_FALSE(m.alive(ElementRef(VertexId(2))));
  EXPECT_FALSE(m.alive(ElementRef(ElementKind::Face, 3)));
  EXPECT_TRUE(m.alive(ElementRef(ElementKind::Face, 2)));
}

TEST(HalfedgeMesh, AlivePastTheEndIsFalse) {
  const HalfedgeMesh m = tetrahedron();
  EXPECT_TRUE(m.alive(VertexId(3)));
  EXPECT_FALSE(m.alive(VertexId(4)));
  EXPECT_TRUE(m.alive(HalfedgeId(11)));
  EXPECT_FALSE(m.alive(HalfedgeId(12)));
  EXPECT_FALSE(m.alive(HalfedgeId(kInvalidIndex)));
  EXPECT_FALSE(m.alive(EdgeId(6)));
  EXPECT_FALSE(m.alive(FaceId::face(4)));
  EXPECT_FALSE(m.alive(FaceId::boundary(0)));  // a closed mesh has no boundary loops
  EXPECT_FALSE(m.alive(FaceId()));
  EXPECT_FALSE(m.alive(ElementRef(ElementKind::Boundary, 0)));
  EXPECT_FALSE(m.alive(ElementRef(ElementKind::Edge, kInvalidIndex)));
  EXPECT_FALSE(m.alive(ElementRef(ElementKind::Face, kInvalidIndex)));
}

TEST(HalfedgeMesh, IterationSkipsDeadIds) {
  HalfedgeMesh m = tetrahedron();
  m.delete_element(VertexId(0));
  m.delete_element(VertexId(2));
  EXPECT_EQ(collect(m.vertices()), (std::vector<VertexId>{VertexId(1), VertexId(3)}));
  m.delete_element(HalfedgeId(11));
  const auto halfedges = collect(m.halfedges());
  ASSERT_EQ(halfedges.size(), 11u);
  EXPECT_EQ(halfedges.front(), HalfedgeId(0));
  EXPECT_EQ(halfedges.back(), HalfedgeId(10));
  m.delete_element(FaceId::face(1));
  EXPECT_EQ(collect(m.faces()), (std::vector<FaceId>{FaceId::face(0), FaceId::face(2), FaceId::face(3)}));

  const HalfedgeMesh grid = build_halfedge_mesh(make_grid(2, 1));
  EXPECT_EQ(collect(grid.boundaries()), (std::vector<FaceId>{FaceId::boundary(0)}));
}

TEST(HalfedgeMesh, IterationEndIsFixedWhenTheRangeIsMade) {
  HalfedgeMesh m = tetrahedron();
  std::vector<EdgeId> visited;
  for (EdgeId e : m.edges()) {
    visited.push_back(e);
    m.new_edge();  // appended while iterating (and may reallocate): must not be visited
    m.new_edge();
  }
  EXPECT_EQ(visited.size(), 6u);
  EXPECT_EQ(visited.back(), EdgeId(5));
  EXPECT_EQ(m.num_edges(), 18u);
  EXPECT_EQ(collect(m.edges()).size(), 18u);
}

TEST(HalfedgeMesh, SettersAndSetNeighbors) {
  HalfedgeMesh m = tetrahedron();
  const HalfedgeId h(0);
  m.set_neighbors(h, HalfedgeId(7), HalfedgeId(8), VertexId(3), EdgeId(4), FaceId::face(2));
  EXPECT_EQ(m.next(h), HalfedgeId(7));
  EXPECT_EQ(m.twin(h), HalfedgeId(8));
  EXPECT_EQ(m.vertex(h), VertexId(3));
  EXPECT_EQ(m.edge(h), EdgeId(4));
  EXPECT_EQ(m.face(h), FaceId::face(2));
  m.set_face(h, FaceId::boundary(0));
  EXPECT_TRUE(m.is_boundary(h));
  m.set_halfedge(VertexId(1), HalfedgeId(5));
  m.set_halfedge(EdgeId(1), HalfedgeId(11));
  m.set_halfedge(FaceId::face(1), HalfedgeId(4));
  m.set_position(VertexId(2), {0.5, 0, 1});
  EXPECT_EQ(m.halfedge(VertexId(1)), HalfedgeId(5));
  EXPECT_EQ(m.halfedge(EdgeId(1)), HalfedgeId(11));
  EXPECT_EQ(m.halfedge(FaceId::face(1)), HalfedgeId(4));
  EXPECT_EQ(m.position(VertexId(2)), glm::dvec3(0.5, 0, 1));
}

TEST(HalfedgeMesh, NavigationOnValidMeshes) {
  const HalfedgeMesh t = tetrahedron();
  EXPECT_EQ(t.prev(HalfedgeId(0)), HalfedgeId(2));
  EXPECT_EQ(t.prev(HalfedgeId(4)), HalfedgeId(3));
  EXPECT_EQ(t.degree(FaceId::face(0)), 3u);
  EXPECT_EQ(t.degree(VertexId(0)), 3u);
  EXPECT_FALSE(t.is_boundary(VertexId(0)));
  EXPECT_FALSE(t.is_boundary(EdgeId(0)));
  std::vector<HalfedgeId> cycle, fan;
  EXPECT_TRUE(t.for_each_face_halfedge(FaceId::face(1), [&](HalfedgeId h) { cycle.push_back(h); }));
  EXPECT_EQ(cycle, (std::vector<HalfedgeId>{HalfedgeId(3), HalfedgeId(4), HalfedgeId(5)}));
  EXPECT_TRUE(t.for_each_outgoing(VertexId(0), [&](HalfedgeId h) { fan.push_back(h); }));
  EXPECT_EQ(fan, (std::vector<HalfedgeId>{HalfedgeId(0), HalfedgeId(3), HalfedgeId(6)}));

  EXPECT_EQ(build_halfedge_mesh(make_cube_quads()).degree(FaceId::face(0)), 4u);

  // Fan of 5: v0 is the centre (valence 5), the rim is b0 with 5 halfedges h15..h19.
  const HalfedgeMesh fan5 = build_halfedge_mesh(make_fan(5));
  EXPECT_EQ(fan5.degree(VertexId(0)), 5u);
  EXPECT_EQ(fan5.degree(VertexId(1)), 3u);
  EXPECT_EQ(fan5.degree(FaceId::boundary(0)), 5u);
  EXPECT_FALSE(fan5.is_boundary(VertexId(0)));
  EXPECT_TRUE(fan5.is_boundary(VertexId(1)));
  // h1 (1->2) is on the rim, h0 (0->1) is a spoke.
  EXPECT_TRUE(fan5.is_boundary(fan5.edge(HalfedgeId(1))));
  EXPECT_FALSE(fan5.is_boundary(fan5.edge(HalfedgeId(0))));
  EXPECT_FALSE(fan5.is_boundary(HalfedgeId(1)));
  EXPECT_TRUE(fan5.is_boundary(fan5.twin(HalfedgeId(1))));
  EXPECT_EQ(fan5.halfedge(FaceId::boundary(0)), HalfedgeId(15));
}

TEST(HalfedgeMesh, WalksStopOnARho) {
  // f0: h0 -> h1 -> h2 -> h1 -> ... never returns to h0.
  HalfedgeMesh m = tetrahedron();
  m.set_next(HalfedgeId(2), HalfedgeId(1));
  EXPECT_FALSE(m.prev(HalfedgeId(0)).valid());
  EXPECT_EQ(m.prev(HalfedgeId(1)), HalfedgeId(2));  // the walk from h1 stays on the loop
  EXPECT_EQ(m.degree(FaceId::face(0)), 0u);
  size_t calls = 0;
  EXPECT_FALSE(m.for_each_face_halfedge(FaceId::face(0), [&](HalfedgeId) { ++calls; }));
  EXPECT_LE(calls, size_t(m.halfedge_capacity()) + 1);
  EXPECT_GE(calls, 3u);
}

TEST(HalfedgeMesh, FanWalkStopsWhenItNeverReturns) {
  // next(h5) = h4: from v0 the twin->next walk goes h0 h4 h10 h8 h4 ... and never returns to h0.
  HalfedgeMesh m = tetrahedron();
  m.set_next(HalfedgeId(5), HalfedgeId(4));
  EXPECT_EQ(m.degree(VertexId(0)), 0u);
  size_t calls = 0;
  EXPECT_FALSE(m.for_each_outgoing(VertexId(0), [&](HalfedgeId) { ++calls; }));
  EXPECT_LE(calls, size_t(m.halfedge_capacity()) + 1);
}

TEST(HalfedgeMesh, WalksStopOnDeadAndInvalidPointers) {
  HalfedgeMesh m = tetrahedron();
  m.delete_element(HalfedgeId(1));
  EXPECT_FALSE(m.prev(HalfedgeId(0)).valid());
  EXPECT_FALSE(m.prev(HalfedgeId(1)).valid());  // a dead halfedge has no prev
  EXPECT_EQ(m.degree(FaceId::face(0)), 0u);
  m = tetrahedron();
  m.set_twin(HalfedgeId(5), HalfedgeId(500));
  EXPECT_EQ(m.degree(VertexId(1)), 0u);  // v1's fan h1 h9 h5 meets h5.twin past the end
  EXPECT_FALSE(m.for_each_outgoing(VertexId(1), [](HalfedgeId) {}));
  m.set_halfedge(FaceId::face(2), HalfedgeId());
  EXPECT_EQ(m.degree(FaceId::face(2)), 0u);
  EXPECT_EQ(m.degree(FaceId::face(9)), 0u);  // past the end
  EXPECT_EQ(m.degree(VertexId(9)), 0u);
  EXPECT_FALSE(m.is_boundary(EdgeId(9)));
}

TEST(HalfedgeMesh, SameAsComparesEverythingButTheVersion) {
  const HalfedgeMesh a = tetrahedron();
  HalfedgeMesh b = a;
  EXPECT_TRUE(a.same_as(b));
  b.set_position(VertexId(0), a.position(VertexId(0)));  // same value, new version
  EXPECT_NE(a.version(), b.version());
  EXPECT_TRUE(a.same_as(b));
  b.set_next(HalfedgeId(0), HalfedgeId(0));
  EXPECT_FALSE(a.same_as(b));
  b = a;
  b.delete_element(EdgeId(3));
  EXPECT_FALSE(a.same_as(b));
  b = a;
  b.new_boundary();
  EXPECT_FALSE(a.same_as(b));
  b = a;
  b.set_position(VertexId(3), {0, 0, 0});
  EXPECT_FALSE(a.same_as(b));
}

TEST(HalfedgeMesh, EveryMutationBumpsTheVersion) {
  HalfedgeMesh m = tetrahedron();
  uint64_t last = m.version();
  auto bumped = [&] {
    const bool up = m.version() > last;
    last = m.version();
    return up;
  };
  m.set_next(HalfedgeId(0), HalfedgeId(1));
  EXPECT_TRUE(bumped());
  m.set_twin(HalfedgeId(0), HalfedgeId(5));
  EXPECT_TRUE(bumped());
  m.set_vertex(HalfedgeId(0), VertexId(0));
  EXPECT_TRUE(bumped());
  m.set_edge(HalfedgeId(0), EdgeId(0));
  EXPECT_TRUE(bumped());
  m.set_face(HalfedgeId(0), FaceId::face(0));
  EXPECT_TRUE(bumped());
  m.set_neighbors(HalfedgeId(0), HalfedgeId(1), HalfedgeId(5), VertexId(0), EdgeId(0), FaceId::face(0));
  EXPECT_TRUE(bumped());
  m.set_halfedge(VertexId(0), HalfedgeId(0));
  EXPECT_TRUE(bumped());
  m.set_halfedge(EdgeId(0), HalfedgeId(0));
  EXPECT_TRUE(bumped());
  m.set_halfedge(FaceId::face(0), HalfedgeId(0));
  EXPECT_TRUE(bumped());
  m.set_position(VertexId(0), {0, 0, 0});
  EXPECT_TRUE(bumped());
  m.new_vertex();
  EXPECT_TRUE(bumped());
  m.new_halfedge();
  EXPECT_TRUE(bumped());
  m.new_edge();
  EXPECT_TRUE(bumped());
  m.new_face();
  EXPECT_TRUE(bumped());
  m.new_boundary();
  EXPECT_TRUE(bumped());
  m.delete_element(VertexId(4));
  EXPECT_TRUE(bumped());
  m.delete_element(FaceId::boundary(0));
  EXPECT_TRUE(bumped());

  m.bump_version_above(last + 100);
  EXPECT_EQ(m.version(), last + 101);
  m.bump_version_above(3);  // below the current version: still goes up
  EXPECT_EQ(m.version(), last + 102);
}

TEST(HalfedgeMesh, ReserveKeepsIdsAndGrowsMemory) {
  HalfedgeMesh m = tetrahedron();
  const size_t before = m.memory_bytes();
  EXPECT_GT(before, 0u);
  m.reserve(100, 600, 300, 200);
  EXPECT_GT(m.memory_bytes(), before);
  EXPECT_TRUE(m.same_as(tetrahedron()));
  EXPECT_EQ(m.new_vertex(), VertexId(4));
}

}  // namespace
}  // namespace meshedit
