// flip, split and collapse on every edge of every shared fixture, long random mixes of all three on the torus
// and the grid, and every operation on every edge of randomly corrupted meshes. After each accepted operation
// the mesh validates, counts change by the documented amounts, the Euler characteristic holds, and new or
// merged vertices sit at midpoints; after each refusal the mesh is identical to its copy, version included.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "ops_test_support.h"

namespace meshedit {
namespace {

using namespace ops_testing;

enum class Op { Flip, Split, Collapse };
const char* op_name(Op op) { return op == Op::Flip ? "flip" : op == Op::Split ? "split" : "collapse"; }

struct Counts {
  long v, e, f, h;
};
Counts counts(const HalfedgeMesh& m) {
  return {long(m.num_vertices()), long(m.num_edges()), long(m.num_faces()), long(m.num_halfedges())};
}

// Runs `op` on `e` of `m` and checks everything the contract promises, whether it is accepted or refused.
// Returns whether it was accepted.
bool apply_and_check(HalfedgeMesh& m, Op op, EdgeId e) {
  const HalfedgeMesh before = m;
  const uint64_t version = m.version();
  const Counts c0 = counts(m);
  const bool boundary_edge = m.is_boundary(e);
  const HalfedgeId h = m.alive(e) ? m.halfedge(e) : HalfedgeId();
  const VertexId end0 = h.valid() ? m.vertex(h) : VertexId(), end1 = h.valid() ? m.vertex(m.twin(h)) : VertexId();
  const glm::dvec3 midpoint = h.valid() ? (m.position(end0) + m.position(end1)) * 0.5 : glm::dvec3(0.0);

  Check check;
  VertexId vertex;
  switch (op) {
    case Op::Flip: {
      const Check predicted = can_flip(m, e);
      const OpResult<EdgeId> r = flip(m, e);
      check = r.check;
      EXPECT_EQ(predicted.ok, check.ok);
      if (r.ok()) {
        EXPECT_ID(r.value, e);
      }
      break;
    }
    case Op::Split: {
      const Check predicted = can_split(m, e);
      const OpResult<VertexId> r = split(m, e);
      check = r.check;
      vertex = r.value;
      EXPECT_EQ(predicted.ok, check.ok);
      break;
    }
    case Op::Collapse: {
      const Check predicted = can_collapse(m, e);
      const OpResult<VertexId> r = collapse(m, e);
      check = r.check;
      vertex = r.value;
      EXPECT_EQ(predicted.ok, check.ok);
      break;
    }
  }
  SCOPED_TRACE(std::string(op_name(op)) + " " + format_id(e) + (check.ok ? "" : ": " + check.reason));

  if (!check.ok) {
    EXPECT_TRUE(names_an_element(check.reason)) << check.reason;
    EXPECT_TRUE(m.same_as(before));
    EXPECT_EQ(m.version(), version);
    return false;
  }
  EXPECT_TRUE(valid_mesh(m));
  EXPECT_TRUE(simplicial_mesh(m));
  EXPECT_EQ(euler_characteristic(m), euler_characteristic(before));
  const Counts c1 = counts(m);
  const int b = boundary_edge ? 1 : 0;
  switch (op) {
    case Op::Flip:
      EXPECT_EQ(c1.v, c0.v);
      EXPECT_EQ(c1.e, c0.e);
      EXPECT_EQ(c1.f, c0.f);
      EXPECT_EQ(c1.h, c0.h);
      EXPECT_TRUE(m.alive(e));
      break;
    case Op::Split:
      EXPECT_EQ(c1.v - c0.v, 1);
      EXPECT_EQ(c1.e - c0.e, 3 - b);
      EXPECT_EQ(c1.f - c0.f, 2 - b);
      EXPECT_EQ(c1.h - c0.h, 6 - 2 * b);
      EXPECT_EQ(vertex.index, before.vertex_capacity());
      EXPECT_EQ(m.position(vertex), midpoint);
      // m.halfedge leaves m along the split edge: toward one of the old endpoints.
      EXPECT_TRUE(m.vertex(m.twin(m.halfedge(vertex))) == end0 || m.vertex(m.twin(m.halfedge(vertex))) == end1);
      break;
    case Op::Collapse:
      EXPECT_EQ(c1.v - c0.v, -1);
      EXPECT_EQ(c1.e - c0.e, -3 + b);
      EXPECT_EQ(c1.f - c0.f, -2 + b);
      EXPECT_EQ(c1.h - c0.h, -6 + 2 * b);
      EXPECT_TRUE(vertex == end0 || vertex == end1);
      EXPECT_TRUE(m.alive(vertex));
      EXPECT_FALSE(m.alive(vertex == end0 ? end1 : end0));
      EXPECT_FALSE(m.alive(e));
      EXPECT_EQ(m.position(vertex), midpoint);
      break;
  }
  return true;
}

struct Fixture {
  const char* name;
  PolygonMesh polygons;
};

std::vector<Fixture> fixtures() {
  return {{"tetrahedron", make_tetrahedron()}, {"cube", make_cube()},     {"icosahedron", make_icosahedron()},
          {"grid(3,2)", make_grid(3, 2)},      {"fan(50)", make_fan(50)}, {"torus(8,4)", make_torus(8, 4)},
          {"cube_quads", make_cube_quads()}};
}

TEST(OpsStress, EveryOperationOnEveryEdgeOfAFreshCopy) {
  for (const Fixture& fixture : fixtures()) {
    SCOPED_TRACE(fixture.name);
    const HalfedgeMesh start = build_halfedge_mesh(fixture.polygons);
    for (Op op : {Op::Flip, Op::Split, Op::Collapse}) {
      size_t accepted = 0;
      for (EdgeId e : start.edges()) {
        HalfedgeMesh m = start;
        accepted += apply_and_check(m, op, e) ? 1 : 0;
      }
      const std::string name = fixture.name;
      SCOPED_TRACE(op_name(op));
      if (name == "tetrahedron") {
        EXPECT_EQ(accepted, op == Op::Split ? 6u : 0u);
      }
      // Every icosahedron edge: c and d are never adjacent, and a, b share exactly c and d.
      if (name == "icosahedron") {
        EXPECT_EQ(accepted, 30u);
      }
      if (name == "cube_quads") {
        EXPECT_EQ(accepted, 0u);
      }
      // fan(50): 50 spokes flip (the rim vertices beside one are not joined), 100 edges split, and all 100
      // collapse (a spoke joins an interior and a boundary vertex; a rim edge's ends share only the centre).
      if (name == "fan(50)") {
        EXPECT_EQ(accepted, op == Op::Flip ? 50u : 100u);
      }
    }
  }
}

TEST(OpsStress, QuadRefusalsSayNotATriangle) {
  HalfedgeMesh m = build_halfedge_mesh(make_cube_quads());
  for (EdgeId e : m.edges()) {
    for (const Check& check : {can_flip(m, e), can_split(m, e), can_collapse(m, e)}) {
      EXPECT_NE(check.reason.find("is not a triangle (4 sides)"), std::string::npos) << check.reason;
    }
  }
}

TEST(OpsStress, EveryOperationOnEveryOriginalEdgeInTurn) {
  // One mesh per fixture and operation, operated on edge after edge, so later operations meet earlier results.
  for (const Fixture& fixture : fixtures()) {
    SCOPED_TRACE(fixture.name);
    for (Op op : {Op::Flip, Op::Split, Op::Collapse}) {
      SCOPED_TRACE(op_name(op));
      HalfedgeMesh m = build_halfedge_mesh(fixture.polygons);
      for (EdgeId e : m.edges()) {  // the range's end is fixed: only original edges
        if (!m.alive(e)) continue;
        apply_and_check(m, op, e);
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
}

// Random mixes of the three operations on random live edges. Uses only mt19937's raw output (fully specified
// by the standard), so the sequence is the same on every platform.
void random_mix(const PolygonMesh& polygons, uint32_t seed, int steps, long* accepted_out) {
  HalfedgeMesh m = build_halfedge_mesh(polygons);
  const long euler = euler_characteristic(m);
  std::mt19937 rng(seed);
  long accepted[3] = {0, 0, 0};
  for (int step = 0; step < steps; ++step) {
    // Keep the size wandering around its start: collapse more often when the mesh has grown.
    const uint32_t roll = rng() % 100;
    const bool grown = m.num_vertices() > 2 * polygons.num_vertices();
    const Op op = roll < 40 ? Op::Flip : roll < (grown ? 55u : 70u) ? Op::Split : Op::Collapse;
    EdgeId e;
    while (!m.alive(e)) e = EdgeId(rng() % m.edge_capacity());
    SCOPED_TRACE("seed " + std::to_string(seed) + " step " + std::to_string(step));
    if (apply_and_check(m, op, e)) ++accepted[static_cast<int>(op)];
    ASSERT_EQ(euler_characteristic(m), euler);
    if (::testing::Test::HasFailure()) return;
  }
  for (int i = 0; i < 3; ++i) accepted_out[i] += accepted[i];
}

TEST(OpsStress, RandomMixesOnTheTorusAndTheGrid) {
  long torus[3] = {0, 0, 0}, grid[3] = {0, 0, 0};
  for (uint32_t seed : {1u, 2u, 3u}) {
    random_mix(make_torus(8, 4), seed, 1500, torus);
    if (HasFatalFailure() || HasFailure()) return;
    random_mix(make_grid(6, 5), seed + 100, 1500, grid);
    if (HasFatalFailure() || HasFailure()) return;
  }
  // Each kind of operation must really have happened many times, or the loop proved little.
  for (int i = 0; i < 3; ++i) {
    EXPECT_GT(torus[i], 800) << op_name(Op(i)) << " on the torus";
    EXPECT_GT(grid[i], 800) << op_name(Op(i)) << " on the grid";
  }
}

// Random corruption: one field of one element set to a random id (often dead, invalid or out of range).
void corrupt(HalfedgeMesh& m, std::mt19937& rng) {
  const uint32_t range = m.halfedge_capacity() + 4;
  auto any_halfedge = [&] { return rng() % 8 == 0 ? HalfedgeId() : HalfedgeId(rng() % range); };
  const HalfedgeId h(rng() % m.halfedge_capacity());
  switch (rng() % 8) {
    case 0: m.set_next(h, any_halfedge()); break;
    case 1: m.set_twin(h, any_halfedge()); break;
    case 2: m.set_vertex(h, VertexId(rng() % (m.vertex_capacity() + 2))); break;
    case 3: m.set_edge(h, EdgeId(rng() % (m.edge_capacity() + 2))); break;
    case 4: {
      const bool loop = rng() % 4 == 0;
      m.set_face(h, loop ? FaceId::boundary(rng() % 3) : FaceId::face(rng() % (m.face_capacity() + 2)));
      break;
    }
    case 5: m.set_halfedge(VertexId(rng() % m.vertex_capacity()), any_halfedge()); break;
    case 6: m.set_halfedge(EdgeId(rng() % m.edge_capacity()), any_halfedge()); break;
    case 7: m.delete_element(HalfedgeId(rng() % m.halfedge_capacity())); break;
  }
}

TEST(OpsStress, CorruptedMeshesNeverCrashOrHang) {
  // Whatever a script did to the mesh, every check ends and every refusal leaves the mesh as it was. Accepted
  // operations may run too (the damage can lie outside what they touch); they must only stay in bounds, which
  // a build with -D_GLIBCXX_ASSERTIONS or AddressSanitizer checks.
  std::mt19937 rng(2024);
  const PolygonMesh shapes[] = {make_torus(6, 3), make_grid(3, 3), make_fan(6), make_icosahedron()};
  size_t refused = 0, accepted = 0;
  auto run = [&](HalfedgeMesh& m, Op op, EdgeId e) {
    const HalfedgeMesh before = m;
    const Check check = op == Op::Flip ? flip(m, e).check : op == Op::Split ? split(m, e).check : collapse(m, e).check;
    if (check.ok) {
      ++accepted;
      return;
    }
    ++refused;
    EXPECT_TRUE(m.same_as(before)) << op_name(op) << " " << format_id(e) << ": " << check.reason;
    EXPECT_EQ(m.version(), before.version());
    EXPECT_FALSE(check.reason.empty());
  };
  for (int trial = 0; trial < 120; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    HalfedgeMesh start = build_halfedge_mesh(shapes[trial % 4]);
    const int breaks = 1 + static_cast<int>(rng() % 3);
    for (int i = 0; i < breaks; ++i) corrupt(start, rng);
    // Every operation on every edge id (and one past the end) of a fresh copy...
    for (uint32_t index = 0; index < start.edge_capacity() + 1; ++index) {
      for (Op op : {Op::Flip, Op::Split, Op::Collapse}) {
        HalfedgeMesh m = start;
        run(m, op, EdgeId(index));
      }
    }
    // ...and a sequence on one copy, so operations meet what earlier ones did to the broken mesh.
    HalfedgeMesh m = start;
    for (int i = 0; i < 60; ++i) run(m, Op(rng() % 3), EdgeId(rng() % (m.edge_capacity() + 1)));
    if (HasFailure()) return;
  }
  EXPECT_GT(refused, 1000u);
  EXPECT_GT(accepted, 1000u);
}

}  // namespace
}  // namespace meshedit
