// Loop subdivision: counts and validity after every phase, exact positions worked out by hand (cube,
// tetrahedron, icosahedron, grids with a boundary) for both weight sets, the phased path against the
// one call, refusals that change nothing, and repeated levels.
//
// Expected positions are written from the rules themselves with each vertex's neighbourhood spelled out
// (never by calling the code under test):
//   interior vertex of valence n: (1 - n u) p + u * sum(neighbours)
//     Course u = 3/16 (n = 3) else 3/(8n);  Loop u = beta / n, beta = 5/8 - (3/8 + cos(2 pi / n) / 4)^2
//   interior edge point: 3/8 (a + b) + 1/8 (c + d);  boundary edge point: (a + b) / 2
//   boundary vertex: 3/4 p + 1/8 (left + right boundary neighbours)
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers                     near, valid, the two weight sets (course_u, loop_u), interior_rule, edge_rule,
//                               neighbours, find_edge, vertex_on_edge, counts
//   phases and counts           run_phases_and_check (what each phase promises) on closed meshes; exact counts
//   positions on closed meshes  the tetrahedron, the cube and the icosahedron worked by hand for both weight sets
//   positions with a boundary   the flat grid, boundary rules that ignore the interior, a fan with a valence-50 centre
//   phases against one call     the four phases give the mesh loop_subdivide gives
//   refusals                    quads, a broken mesh, a valid mesh split cannot handle: refused, nothing changed; the
//                               empty mesh
//   repeated levels             three levels of the torus with their counts
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/triangulate.h"
#include "core/validate.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

constexpr double kTol = 1e-12;

::testing::AssertionResult near(const glm::dvec3& actual, const glm::dvec3& expected, double tol = kTol) {
  return testing::near(actual, expected, tol);
}

::testing::AssertionResult valid(const HalfedgeMesh& mesh) {
  const ValidationReport report = validate(mesh);
  if (report.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << report.summary();
}

VertexId V(uint32_t i) { return VertexId(i); }

// The course's u for valence n, as the assignment states it.
double course_u(uint32_t n) { return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n); }
// Loop's original u for valence n.
double loop_u(uint32_t n) {
  const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
  return (5.0 / 8.0 - c * c) / n;
}
double u_for(LoopWeights w, uint32_t n) { return w == LoopWeights::Course ? course_u(n) : loop_u(n); }

// (1 - n u) p + u * sum over the listed neighbours, with positions taken from the ORIGINAL mesh.
glm::dvec3 interior_rule(const HalfedgeMesh& original, uint32_t v, const std::vector<uint32_t>& neighbours,
                         LoopWeights w) {
  const auto n = static_cast<uint32_t>(neighbours.size());
  const double u = u_for(w, n);
  glm::dvec3 sum(0.0);
  for (uint32_t q : neighbours) sum += original.position(V(q));
  return (1.0 - n * u) * original.position(V(v)) + u * sum;
}

glm::dvec3 edge_rule(const HalfedgeMesh& original, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return 3.0 / 8.0 * (original.position(V(a)) + original.position(V(b))) +
         1.0 / 8.0 * (original.position(V(c)) + original.position(V(d)));
}

std::vector<uint32_t> neighbours(const HalfedgeMesh& mesh, VertexId v) {
  std::vector<uint32_t> out;
  mesh.for_each_outgoing(v, [&](HalfedgeId h) { out.push_back(mesh.vertex(mesh.twin(h)).index); });
  std::sort(out.begin(), out.end());
  return out;
}

EdgeId find_edge(const HalfedgeMesh& mesh, uint32_t a, uint32_t b) {
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    const uint32_t x = mesh.vertex(h).index, y = mesh.vertex(mesh.twin(h)).index;
    if ((x == a && y == b) || (x == b && y == a)) return e;
  }
  return EdgeId();
}

// After subdivision, the vertex that replaced edge a-b: the only vertex created by subdivision (id at
// or past `first_new`) adjacent to both a and b.
VertexId vertex_on_edge(const HalfedgeMesh& mesh, uint32_t a, uint32_t b, uint32_t first_new) {
  VertexId found;
  int count = 0;
  for (VertexId v : mesh.vertices()) {
    if (v.index < first_new) continue;
    const std::vector<uint32_t> n = neighbours(mesh, v);
    if (std::binary_search(n.begin(), n.end(), a) && std::binary_search(n.begin(), n.end(), b)) {
      found = v;
      ++count;
    }
  }
  return count == 1 ? found : VertexId();
}

size_t count_flags(const std::vector<uint8_t>& flags) { return size_t(std::count(flags.begin(), flags.end(), 1)); }

struct Counts {
  size_t v, e, f;
};
Counts counts(const HalfedgeMesh& m) { return {m.num_vertices(), m.num_edges(), m.num_faces()}; }

// ---- phases and counts -----------------------------------------------------------------------------

// Runs the four phases one by one on a closed or bounded triangle mesh, checking what each promises.
void run_phases_and_check(HalfedgeMesh& m, LoopWeights weights) {
  const Counts before = counts(m);
  const uint32_t old_vertices = m.vertex_capacity();
  const HalfedgeMesh original = m;

  OpResult<LoopState> computed = loop_compute_positions(m, weights);
  ASSERT_TRUE(computed.ok()) << computed.check.reason;
  EXPECT_TRUE(m.same_as(original));  // phase 1 reads only
  LoopState& s = computed.value;
  ASSERT_EQ(s.original_edges.size(), before.e);
  EXPECT_TRUE(std::is_sorted(s.original_edges.begin(), s.original_edges.end()));

  loop_split_edges(m, s);
  EXPECT_TRUE(valid(m));
  EXPECT_EQ(m.num_vertices(), before.v + before.e);
  EXPECT_EQ(m.num_faces(), 4 * before.f);
  EXPECT_EQ(m.num_edges(), 2 * before.e + 3 * before.f);
  EXPECT_EQ(count_flags(s.is_new_vertex), before.e);
  EXPECT_EQ(count_flags(s.is_new_edge), 3 * before.f);
  ASSERT_EQ(s.is_new_vertex.size(), m.vertex_capacity());
  ASSERT_EQ(s.is_new_edge.size(), m.edge_capacity());
  ASSERT_EQ(s.new_position.size(), m.vertex_capacity());
  for (VertexId v : m.vertices()) {
    // Old vertices keep their ids and stay put until phase 4; every new one is past the old ids.
    EXPECT_EQ(s.is_new_vertex[v.index] != 0, v.index >= old_vertices) << format_id(v);
    if (v.index < old_vertices) {
      EXPECT_EQ(m.position(v), original.position(v)) << format_id(v);
      EXPECT_EQ(s.new_position[v.index], s.vertex_position[v.index]) << format_id(v);
    }
  }
  size_t halves = 0;
  for (VertexId v : m.vertices()) {
    if (v.index < old_vertices) continue;
    // A new vertex sits on exactly one original edge a-b, at its midpoint; its two edges that are not
    // flagged new are the halves, going to a and b; the flagged ones go anywhere else.
    std::vector<uint32_t> half_ends, cross_ends;
    m.for_each_outgoing(v, [&](HalfedgeId h) {
      const uint32_t other = m.vertex(m.twin(h)).index;
      (s.is_new_edge[m.edge(h).index] ? cross_ends : half_ends).push_back(other);
    });
    ASSERT_EQ(half_ends.size(), 2u) << format_id(v);
    const uint32_t a = half_ends[0], b = half_ends[1];
    EXPECT_LT(a, old_vertices) << format_id(v);
    EXPECT_LT(b, old_vertices) << format_id(v);
    EXPECT_TRUE(find_edge(original, a, b).valid()) << format_id(v) << " halves end at v" << a << " and v" << b;
    EXPECT_EQ(m.position(v), 0.5 * (original.position(V(a)) + original.position(V(b)))) << format_id(v);
    EXPECT_EQ(s.new_position[v.index], s.edge_position[find_edge(original, a, b).index]) << format_id(v);
    EXPECT_GE(cross_ends.size(), 1u) << format_id(v);
    for (uint32_t c : cross_ends) EXPECT_TRUE(c != a && c != b) << format_id(v);
    halves += 2;
  }
  EXPECT_EQ(halves, 2 * before.e);

  loop_flip_edges(m, s);
  EXPECT_TRUE(valid(m));
  EXPECT_EQ(m.num_vertices(), before.v + before.e);
  EXPECT_EQ(m.num_faces(), 4 * before.f);
  EXPECT_EQ(m.num_edges(), 2 * before.e + 3 * before.f);
  for (EdgeId e : m.edges()) {
    // Every edge across an old face now joins two new vertices (the inner triangles).
    const HalfedgeId h = m.halfedge(e);
    const bool a_new = s.is_new_vertex[m.vertex(h).index], b_new = s.is_new_vertex[m.vertex(m.twin(h)).index];
    if (s.is_new_edge[e.index]) {
      EXPECT_TRUE(a_new && b_new) << format_id(e);
    }
  }
  for (VertexId v : m.vertices()) {
    if (v.index >= old_vertices) continue;
    // An old vertex keeps its valence and now sees only new vertices.
    EXPECT_EQ(m.degree(v), original.degree(v)) << format_id(v);
    for (uint32_t q : neighbours(m, v)) EXPECT_TRUE(s.is_new_vertex[q]) << format_id(v) << " - v" << q;
  }

  loop_commit_positions(m, s);
  EXPECT_TRUE(valid(m));
  for (VertexId v : m.vertices()) EXPECT_EQ(m.position(v), s.new_position[v.index]) << format_id(v);
}

TEST(LoopSubdivision, PhasesKeepClosedMeshesValidWithExpectedCounts) {
  const struct {
    const char* name;
    PolygonMesh polygons;
  } shapes[] = {{"tetrahedron", make_tetrahedron()},
                {"cube", make_cube()},
                {"icosahedron", make_icosahedron()},
                {"torus", make_torus(8, 6)}};
  for (const auto& shape : shapes) {
    for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
      SCOPED_TRACE(shape.name);
      HalfedgeMesh m = build_halfedge_mesh(shape.polygons);
      ASSERT_NO_FATAL_FAILURE(run_phases_and_check(m, w));
    }
  }
}

TEST(LoopSubdivision, ClosedMeshCountsAreExact) {
  // V' = V + E, E' = 2E + 3F, F' = 4F, written out per shape.
  HalfedgeMesh tet = build_halfedge_mesh(make_tetrahedron());  // 4, 6, 4
  ASSERT_TRUE(loop_subdivide(tet));
  EXPECT_EQ(tet.num_vertices(), 10u);
  EXPECT_EQ(tet.num_edges(), 24u);
  EXPECT_EQ(tet.num_faces(), 16u);
  HalfedgeMesh cube = build_halfedge_mesh(make_cube());  // 8, 18, 12
  ASSERT_TRUE(loop_subdivide(cube));
  EXPECT_EQ(cube.num_vertices(), 26u);
  EXPECT_EQ(cube.num_edges(), 72u);
  EXPECT_EQ(cube.num_faces(), 48u);
  HalfedgeMesh ico = build_halfedge_mesh(make_icosahedron());  // 12, 30, 20
  ASSERT_TRUE(loop_subdivide(ico));
  EXPECT_EQ(ico.num_vertices(), 42u);
  EXPECT_EQ(ico.num_edges(), 120u);
  EXPECT_EQ(ico.num_faces(), 80u);
  for (const HalfedgeMesh* m : {&tet, &cube, &ico}) {
    EXPECT_TRUE(valid(*m));
    EXPECT_EQ(m->num_boundaries(), 0u);
  }
}

// ---- positions on closed meshes --------------------------------------------------------------------

TEST(LoopSubdivision, TetrahedronShrinksToAQuarter) {
  // Valence 3 everywhere, u = 3/16 for both weight sets; the other three vertices sum to -p, so
  // p' = (1 - 9/16) p - 3/16 p = p / 4. Edge a-b: c + d = -(a + b), so the point is (a + b) / 4.
  for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
    HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
    const HalfedgeMesh original = m;
    ASSERT_TRUE(loop_subdivide(m, w));
    for (uint32_t v = 0; v < 4; ++v) EXPECT_TRUE(near(m.position(V(v)), original.position(V(v)) / 4.0)) << v;
    const VertexId m01 = vertex_on_edge(m, 0, 1, 4);
    ASSERT_TRUE(m01.valid());
    EXPECT_TRUE(near(m.position(m01), {0.5, 0, 0}));  // ((1,1,1) + (1,-1,-1)) / 4
  }
}

TEST(LoopSubdivision, CubePositionsMatchTheRulesForBothWeightSets) {
  // make_cube's triangles (each side quad q split along q0-q2):
  //   z-: (0,2,3) (0,3,1)   z+: (4,5,7) (4,7,6)   y-: (0,1,5) (0,5,4)
  //   y+: (2,6,7) (2,7,3)   x-: (0,4,6) (0,6,2)   x+: (1,3,7) (1,7,5)
  // so v0 and v7 have valence 6 and the others valence 4:
  const std::vector<uint32_t> ring0 = {1, 2, 3, 4, 5, 6};
  const std::vector<uint32_t> ring7 = {1, 2, 3, 4, 5, 6};
  const std::vector<uint32_t> ring1 = {0, 3, 5, 7};
  const std::vector<uint32_t> ring6 = {0, 2, 4, 7};
  const HalfedgeMesh original = build_halfedge_mesh(make_cube());
  // The hand-derived rings are the mesh's.
  ASSERT_EQ(neighbours(original, V(0)), ring0);
  ASSERT_EQ(neighbours(original, V(7)), ring7);
  ASSERT_EQ(neighbours(original, V(1)), ring1);
  ASSERT_EQ(neighbours(original, V(6)), ring6);

  for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
    SCOPED_TRACE(w == LoopWeights::Course ? "course" : "loop");
    const glm::dvec3 p0 = interior_rule(original, 0, ring0, w);
    const glm::dvec3 p7 = interior_rule(original, 7, ring7, w);
    const glm::dvec3 p1 = interior_rule(original, 1, ring1, w);
    const glm::dvec3 p6 = interior_rule(original, 6, ring6, w);
    // Edge 0-1 lies in (0,3,1) and (0,1,5); the diagonal 0-3 in (0,2,3) and (0,3,1).
    const glm::dvec3 e01 = edge_rule(original, 0, 1, 3, 5);
    const glm::dvec3 e03 = edge_rule(original, 0, 3, 2, 1);

    // The same numbers as fractions: the six neighbours of v0 sum to -(p0 + p7) = 0, so v0 -> 5/8 p0
    // for u = 1/16 (both sets agree at valence 6). v1's ring sums to (1,0,0):
    // Course u = 3/32 -> 5/8 p1 + (3/32,0,0); Loop u = 31/256 -> 132/256 p1 + (31/256,0,0).
    EXPECT_TRUE(near(p0, glm::dvec3(-5.0 / 16.0)));
    EXPECT_TRUE(
        near(p1, w == LoopWeights::Course ? glm::dvec3(13, -10, -10) / 32.0 : glm::dvec3(97, -66, -66) / 256.0));
    EXPECT_TRUE(near(e01, {1.0 / 8.0, -3.0 / 8.0, -3.0 / 8.0}));
    EXPECT_TRUE(near(e03, {0, 0, -0.5}));

    // Phase 1 state.
    OpResult<LoopState> computed = loop_compute_positions(original, w);
    ASSERT_TRUE(computed.ok());
    const LoopState& s = computed.value;
    EXPECT_EQ(s.weights, w);
    EXPECT_TRUE(near(s.vertex_position[0], p0));
    EXPECT_TRUE(near(s.vertex_position[7], p7));
    EXPECT_TRUE(near(s.vertex_position[1], p1));
    EXPECT_TRUE(near(s.vertex_position[6], p6));
    EXPECT_TRUE(near(s.edge_position[find_edge(original, 0, 1).index], e01));
    EXPECT_TRUE(near(s.edge_position[find_edge(original, 0, 3).index], e03));

    // The subdivided mesh.
    HalfedgeMesh m = original;
    ASSERT_TRUE(loop_subdivide(m, w));
    EXPECT_TRUE(near(m.position(V(0)), p0));
    EXPECT_TRUE(near(m.position(V(7)), p7));
    EXPECT_TRUE(near(m.position(V(1)), p1));
    EXPECT_TRUE(near(m.position(V(6)), p6));
    const VertexId m01 = vertex_on_edge(m, 0, 1, 8), m03 = vertex_on_edge(m, 0, 3, 8);
    ASSERT_TRUE(m01.valid());
    ASSERT_TRUE(m03.valid());
    EXPECT_TRUE(near(m.position(m01), e01));
    EXPECT_TRUE(near(m.position(m03), e03));
  }
  // The two weight sets really differ at valence 4.
  EXPECT_GT(std::abs(course_u(4) - loop_u(4)), 0.02);
}

TEST(LoopSubdivision, IcosahedronVerticesLandOnTwoSpheres) {
  // On the unit icosahedron adjacent vertices have dot product 1/sqrt(5), vertices two steps apart
  // -1/sqrt(5). Old vertex (valence 5): the ring sums to sqrt(5) p, so its radius is 1 - 5u + sqrt(5) u.
  // Edge point: a + b and c + d lie on the same axis, |a + b|^2 = 2 + 2/sqrt(5), |c + d|^2 = 2 - 2/sqrt(5).
  const double s5 = std::sqrt(5.0);
  const double edge_radius = 3.0 / 8.0 * std::sqrt(2.0 + 2.0 / s5) + 1.0 / 8.0 * std::sqrt(2.0 - 2.0 / s5);
  for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
    SCOPED_TRACE(w == LoopWeights::Course ? "course" : "loop");
    const double u = u_for(w, 5);
    const double vertex_radius = 1.0 - 5.0 * u + s5 * u;
    HalfedgeMesh m = build_halfedge_mesh(make_icosahedron());
    ASSERT_TRUE(loop_subdivide(m, w));
    ASSERT_EQ(m.num_vertices(), 42u);
    for (VertexId v : m.vertices()) {
      const double expected = v.index < 12 ? vertex_radius : edge_radius;
      EXPECT_NEAR(glm::length(m.position(v)), expected, kTol) << format_id(v);
    }
  }
}

// ---- positions with a boundary ---------------------------------------------------------------------

TEST(LoopSubdivision, FlatGridStaysFlatAndFollowsTheBoundaryRules) {
  // make_grid(2,2): v(j*3 + i) = (i, j, 0); 9 vertices, 16 edges, 8 triangles, one boundary loop.
  const HalfedgeMesh original = build_halfedge_mesh(make_grid(2, 2));
  ASSERT_EQ(original.num_edges(), 16u);
  for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
    HalfedgeMesh m = original;
    ASSERT_NO_FATAL_FAILURE(run_phases_and_check(m, w));
    EXPECT_EQ(m.num_vertices(), 9u + 16u);
    EXPECT_EQ(m.num_faces(), 32u);
    EXPECT_EQ(m.num_edges(), 2u * 16u + 3u * 8u);
    EXPECT_EQ(m.num_boundaries(), 1u);
    for (VertexId v : m.vertices()) EXPECT_EQ(m.position(v).z, 0.0) << format_id(v);
    // Corners: 3/4 p + 1/8 (two boundary neighbours). v0 also has the interior neighbour v4, which the
    // boundary rule ignores; v2 = (2,0) lies in one triangle only.
    EXPECT_TRUE(
        near(m.position(V(0)), 0.75 * glm::dvec3(0, 0, 0) + 0.125 * (glm::dvec3(1, 0, 0) + glm::dvec3(0, 1, 0))));
    EXPECT_TRUE(near(m.position(V(0)), {1.0 / 8.0, 1.0 / 8.0, 0}));
    EXPECT_TRUE(near(m.position(V(2)), {15.0 / 8.0, 1.0 / 8.0, 0}));
    EXPECT_TRUE(near(m.position(V(6)), {1.0 / 8.0, 15.0 / 8.0, 0}));
    EXPECT_TRUE(near(m.position(V(8)), {15.0 / 8.0, 15.0 / 8.0, 0}));
    // A straight boundary vertex stays: 3/4 (1,0) + 1/8 ((0,0) + (2,0)).
    EXPECT_TRUE(near(m.position(V(1)), {1, 0, 0}));
    // Boundary edge points are midpoints.
    const VertexId m01 = vertex_on_edge(m, 0, 1, 9), m25 = vertex_on_edge(m, 2, 5, 9);
    ASSERT_TRUE(m01.valid());
    ASSERT_TRUE(m25.valid());
    EXPECT_TRUE(near(m.position(m01), {0.5, 0, 0}));
    EXPECT_TRUE(near(m.position(m25), {2, 0.5, 0}));
    // The new vertices on the rim are boundary vertices.
    EXPECT_TRUE(m.is_boundary(m01));
    EXPECT_FALSE(m.is_boundary(vertex_on_edge(m, 1, 4, 9)));
  }
}

TEST(LoopSubdivision, BoundaryRulesIgnoreTheInterior) {
  // The same grid with its centre v4 lifted to z = 1: the rim may not move out of the plane.
  PolygonMesh p = make_grid(2, 2);
  p.positions[4].z = 1.0;
  HalfedgeMesh m = build_halfedge_mesh(p);
  const HalfedgeMesh original = m;
  ASSERT_TRUE(loop_subdivide(m, LoopWeights::Course));
  EXPECT_TRUE(valid(m));
  for (VertexId v : m.vertices()) {
    if (m.is_boundary(v)) {
      EXPECT_EQ(m.position(v).z, 0.0) << format_id(v);
    }
  }
  EXPECT_TRUE(near(m.position(V(0)), {1.0 / 8.0, 1.0 / 8.0, 0}));
  EXPECT_TRUE(near(m.position(vertex_on_edge(m, 0, 1, 9)), {0.5, 0, 0}));
  // v4 (valence 6, ring 0 1 3 5 7 8) is interior: u = 1/16.
  ASSERT_EQ(neighbours(original, V(4)), (std::vector<uint32_t>{0, 1, 3, 5, 7, 8}));
  EXPECT_TRUE(near(m.position(V(4)), interior_rule(original, 4, {0, 1, 3, 5, 7, 8}, LoopWeights::Course)));
  EXPECT_TRUE(near(m.position(V(4)), {1, 1, 10.0 / 16.0}));
  // Interior edge 1-4 lies in (0,1,4) and (1,5,4): 3/8 ((1,0,0) + (1,1,1)) + 1/8 ((0,0,0) + (2,1,0)).
  EXPECT_TRUE(near(m.position(vertex_on_edge(m, 1, 4, 9)), edge_rule(original, 1, 4, 0, 5)));
  EXPECT_TRUE(near(m.position(vertex_on_edge(m, 1, 4, 9)), {1, 0.5, 3.0 / 8.0}));
}

TEST(LoopSubdivision, FanWithValenceFiftyCentre) {
  for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
    HalfedgeMesh m = build_halfedge_mesh(make_fan(50));  // 51 vertices, 100 edges, 50 faces
    ASSERT_NO_FATAL_FAILURE(run_phases_and_check(m, w));
    EXPECT_EQ(m.num_vertices(), 151u);
    EXPECT_EQ(m.num_faces(), 200u);
    EXPECT_EQ(m.num_edges(), 350u);
    EXPECT_EQ(m.degree(V(0)), 50u);
    // The rim sums to zero, so the centre stays at the origin for any u.
    EXPECT_TRUE(near(m.position(V(0)), {0, 0, 0}));
    // A rim vertex: 3/4 p + 1/8 of its two rim neighbours at angles +-2 pi / 50.
    const double a = 2.0 * std::numbers::pi / 50.0;
    EXPECT_TRUE(near(m.position(V(1)), {0.75 + 0.25 * std::cos(a), 0, 0}));
  }
}

// ---- phases against one call -----------------------------------------------------------------------

TEST(LoopSubdivision, PhasesAndOneCallGiveTheSameMesh) {
  for (const PolygonMesh& p : {make_cube(), make_grid(3, 2), make_torus(6, 5), make_fan(9)}) {
    for (LoopWeights w : {LoopWeights::Course, LoopWeights::Loop}) {
      HalfedgeMesh phased = build_halfedge_mesh(p);
      HalfedgeMesh direct = phased;
      OpResult<LoopState> s = loop_compute_positions(phased, w);
      ASSERT_TRUE(s.ok());
      loop_split_edges(phased, s.value);
      loop_flip_edges(phased, s.value);
      loop_commit_positions(phased, s.value);
      ASSERT_TRUE(loop_subdivide(direct, w));
      EXPECT_TRUE(phased.same_as(direct));
    }
  }
}

// ---- refusals --------------------------------------------------------------------------------------

TEST(LoopSubdivision, RefusesQuadsNamingTheFaceAndChangesNothing) {
  HalfedgeMesh m = build_halfedge_mesh(make_cube_quads());
  const HalfedgeMesh copy = m;
  const uint64_t version = m.version();
  const Check check = can_loop_subdivide(m);
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(check.reason, std::string("f0 has 4 sides; Loop subdivision needs triangles; ") + kHowToTriangulate);
  const Check refused = loop_subdivide(m);
  EXPECT_FALSE(refused.ok);
  EXPECT_EQ(refused.reason, check.reason);
  EXPECT_TRUE(m.same_as(copy));
  EXPECT_EQ(m.version(), version);
  const OpResult<LoopState> phase1 = loop_compute_positions(m);
  EXPECT_FALSE(phase1.ok());
  EXPECT_EQ(phase1.check.reason, check.reason);
}

TEST(LoopSubdivision, RefusalNamesTheFirstNonTriangle) {
  // A square pyramid: four triangles, then the base quad as f4.
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  p.add_face({0, 1, 4});
  p.add_face({1, 2, 4});
  p.add_face({2, 3, 4});
  p.add_face({3, 0, 4});
  p.add_face({0, 3, 2, 1});
  HalfedgeMesh m = build_halfedge_mesh(p);
  const HalfedgeMesh copy = m;
  const Check refused = loop_subdivide(m);
  EXPECT_EQ(refused.reason, std::string("f4 has 4 sides; Loop subdivision needs triangles; ") + kHowToTriangulate);
  EXPECT_TRUE(m.same_as(copy));
}

TEST(LoopSubdivision, RefusesABrokenMeshWithItsFirstProblem) {
  HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  m.set_twin(HalfedgeId(0), HalfedgeId(4));  // h0's twin is really h5
  const HalfedgeMesh copy = m;
  const uint64_t version = m.version();
  const ValidationReport report = validate(m);
  ASSERT_FALSE(report.ok());
  const Check refused = loop_subdivide(m);
  EXPECT_FALSE(refused.ok);
  EXPECT_EQ(refused.reason, "Loop subdivision needs a valid mesh (" + report.summary() + ")");
  EXPECT_NE(refused.reason.find(report.violations.front().message), std::string::npos);
  EXPECT_TRUE(m.same_as(copy));
  EXPECT_EQ(m.version(), version);
}

TEST(LoopSubdivision, RefusesAValidMeshThatSplitCannotHandle) {
  // A "pillow": two triangles on the same three corners, glued along all three edges. The builder
  // refuses it as a repeated face, but pointer writes make it and validate() accepts it; split() cannot
  // split any of its edges, so Loop must refuse up front rather than stop half way.
  // f0 = (0,1,2) as h0 h1 h2; f1 = (0,2,1) as h3 h4 h5; e0 = 0-1, e1 = 1-2, e2 = 2-0.
  HalfedgeMesh m;
  for (int i = 0; i < 3; ++i) m.new_vertex({double(i == 1), double(i == 2), 0});
  for (int i = 0; i < 6; ++i) m.new_halfedge();
  for (int i = 0; i < 3; ++i) m.new_edge();
  const FaceId f0 = m.new_face(), f1 = m.new_face();
  const auto h = [](uint32_t i) { return HalfedgeId(i); };
  m.set_neighbors(h(0), h(1), h(5), V(0), EdgeId(0), f0);
  m.set_neighbors(h(1), h(2), h(4), V(1), EdgeId(1), f0);
  m.set_neighbors(h(2), h(0), h(3), V(2), EdgeId(2), f0);
  m.set_neighbors(h(3), h(4), h(2), V(0), EdgeId(2), f1);
  m.set_neighbors(h(4), h(5), h(1), V(2), EdgeId(1), f1);
  m.set_neighbors(h(5), h(3), h(0), V(1), EdgeId(0), f1);
  for (uint32_t i = 0; i < 3; ++i) {
    m.set_halfedge(V(i), h(i));
    m.set_halfedge(EdgeId(i), h(i));
  }
  m.set_halfedge(f0, h(0));
  m.set_halfedge(f1, h(3));
  ASSERT_TRUE(valid(m));
  const HalfedgeMesh copy = m;
  const Check refused = loop_subdivide(m);
  EXPECT_FALSE(refused.ok);
  EXPECT_EQ(refused.reason.rfind("Loop subdivision cannot split e0: ", 0), 0u) << refused.reason;
  EXPECT_TRUE(m.same_as(copy));
}

TEST(LoopSubdivision, EmptyMeshIsANoOp) {
  HalfedgeMesh m;
  EXPECT_TRUE(loop_subdivide(m));
  EXPECT_EQ(m.num_vertices(), 0u);
  EXPECT_EQ(m.num_faces(), 0u);
}

// ---- repeated levels -------------------------------------------------------------------------------

TEST(LoopSubdivision, TorusTwoAndThreeLevels) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(8, 6));  // V 48, E 144, F 96
  ASSERT_EQ(m.num_edges(), 144u);
  const size_t expected[3][3] = {{48 + 144, 2 * 144 + 3 * 96, 4 * 96},          // 192, 576, 384
                                 {192 + 576, 2 * 576 + 3 * 384, 4 * 384},       // 768, 2304, 1536
                                 {768 + 2304, 2 * 2304 + 3 * 1536, 4 * 1536}};  // 3072, 9216, 6144
  for (int level = 0; level < 3; ++level) {
    SCOPED_TRACE(level + 1);
    ASSERT_TRUE(loop_subdivide(m, level == 1 ? LoopWeights::Loop : LoopWeights::Course));
    EXPECT_TRUE(valid(m));
    EXPECT_EQ(m.num_vertices(), expected[level][0]);
    EXPECT_EQ(m.num_edges(), expected[level][1]);
    EXPECT_EQ(m.num_faces(), expected[level][2]);
    EXPECT_EQ(long(m.num_vertices()) - long(m.num_edges()) + long(m.num_faces()), 0);  // genus 1
  }
}

}  // namespace
}  // namespace meshedit
