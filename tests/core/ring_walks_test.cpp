// walk_rings (ring_walks.h), the interleaved one-ring walks of whole-mesh passes: every live vertex in a range is
// visited once, in increasing order, with its neighbours in the plain walk's order (h -> h.twin.next from
// v.halfedge) and the rim flag of each edge; begin, neighbours and end of one vertex come on one lane; dead vertices
// are skipped. Checked against the element API's walk on a closed mesh, a grid with a boundary, a mesh with dead
// vertices after collapses, and ranges shorter than the lanes.
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_storage.h"
#include "core/primitives.h"
#include "core/ring_walks.h"

namespace meshedit {
namespace {

struct Visit {
  uint32_t vertex = 0, start = 0;
  std::vector<uint32_t> neighbours;
  std::vector<bool> rim;
};

// Records each vertex's walk as the visitor sees it, checking that a lane is used by one vertex at a time.
class Recorder {
 public:
  Recorder() { std::fill(std::begin(open_), std::end(open_), int64_t(-1)); }

  void begin(unsigned lane, uint32_t v) {
    ASSERT_LT(lane, ring_walks::kLanes);
    ASSERT_EQ(open_[lane], -1) << "lane " << lane << " began v" << v << " before ending v" << open_[lane];
    open_[lane] = int64_t(v);
    visits.push_back(Visit{v, 0, {}, {}});
    slot_[lane] = visits.size() - 1;
  }
  void neighbour(unsigned lane, uint32_t q, bool rim) {
    ASSERT_NE(open_[lane], -1);
    visits[slot_[lane]].neighbours.push_back(q);
    visits[slot_[lane]].rim.push_back(rim);
  }
  void end(unsigned lane, uint32_t v, uint32_t start) {
    ASSERT_EQ(open_[lane], int64_t(v));
    visits[slot_[lane]].start = start;
    open_[lane] = -1;
  }

  std::vector<Visit> visits;  // in begin order

 private:
  int64_t open_[ring_walks::kLanes];  // the vertex a lane is walking, or -1
  size_t slot_[ring_walks::kLanes] = {};
};

// The plain walk through the element API.
Visit plain_walk(const HalfedgeMesh& mesh, VertexId v) {
  Visit visit{v.index, mesh.halfedge(v).index, {}, {}};
  mesh.for_each_outgoing(v, [&](HalfedgeId h) {
    const HalfedgeId t = mesh.twin(h);
    visit.neighbours.push_back(mesh.vertex(t).index);
    visit.rim.push_back(mesh.is_boundary(h) || mesh.is_boundary(t));
  });
  return visit;
}

void expect_walks_match(HalfedgeMesh& mesh, size_t begin, size_t end) {
  Recorder recorder;
  ring_walks::walk_rings(MeshStorage::view(mesh), begin, end, recorder);
  std::vector<Visit> expected;
  for (size_t v = begin; v < end; ++v) {
    if (mesh.alive(VertexId(uint32_t(v)))) expected.push_back(plain_walk(mesh, VertexId(uint32_t(v))));
  }
  ASSERT_EQ(recorder.visits.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    const Visit& got = recorder.visits[i];
    const Visit& want = expected[i];
    ASSERT_EQ(got.vertex, want.vertex) << "visit " << i;
    EXPECT_EQ(got.start, want.start) << "v" << want.vertex;
    EXPECT_EQ(got.neighbours, want.neighbours) << "v" << want.vertex;
    EXPECT_EQ(got.rim, want.rim) << "v" << want.vertex;
  }
}

TEST(RingWalks, ClosedMeshEveryVertexInOrderWithItsNeighboursInWalkOrder) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(12, 9));
  expect_walks_match(mesh, 0, mesh.vertex_capacity());
}

TEST(RingWalks, BoundaryEdgesAreRimAndBoundaryVerticesWalkTheirWholeFan) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_grid(7, 5));
  Recorder recorder;
  ring_walks::walk_rings(MeshStorage::view(mesh), 0, mesh.vertex_capacity(), recorder);
  size_t vertices_with_rim = 0;
  for (const Visit& visit : recorder.visits) {
    size_t rims = 0;
    for (bool r : visit.rim) rims += r ? 1 : 0;
    EXPECT_TRUE(rims == 0 || rims == 2) << "v" << visit.vertex;
    EXPECT_EQ(rims == 2, mesh.is_boundary(VertexId(visit.vertex))) << "v" << visit.vertex;
    vertices_with_rim += rims == 2 ? 1 : 0;
  }
  EXPECT_EQ(vertices_with_rim, size_t(2 * (7 + 5)));  // the grid's outline: 8 x 6 vertices, 24 on the rim
  expect_walks_match(mesh, 0, mesh.vertex_capacity());
}

TEST(RingWalks, DeadVerticesAreSkipped) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(10, 8));
  for (uint32_t e : {3u, 40u, 77u}) {
    ASSERT_TRUE(mesh.alive(EdgeId(e)));
    ASSERT_TRUE(collapse(mesh, EdgeId(e)).ok()) << "e" << e;
  }
  ASSERT_LT(mesh.num_vertices(), mesh.vertex_capacity());
  expect_walks_match(mesh, 0, mesh.vertex_capacity());
}

TEST(RingWalks, RangesShorterThanTheLanesAndEmptyRanges) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_icosahedron());
  expect_walks_match(mesh, 0, 0);
  expect_walks_match(mesh, 5, 5);
  expect_walks_match(mesh, 2, 5);
  expect_walks_match(mesh, 7, mesh.vertex_capacity());
}

}  // namespace
}  // namespace meshedit
