// compare_meshes (up to renumbering) and compare_meshes_exact (pointer for pointer): renumbered copies are
// equal and map vertex to vertex; a moved vertex, a reversed face, a missing face, extra elements and broken
// cycles are reported with the exact messages; the tolerance is inclusive and works across hash cells; the
// message cap counts everything but keeps 20.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_compare.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;

// The same surface with vertex i renamed perm[i], faces listed backwards, each starting one corner later.
PolygonMesh renumbered(const PolygonMesh& in, const std::vector<uint32_t>& perm) {
  PolygonMesh out;
  out.positions.resize(in.positions.size());
  for (size_t i = 0; i < perm.size(); ++i) out.positions[perm[i]] = in.positions[i];
  for (size_t f = in.num_faces(); f-- > 0;) {
    const auto face = in.face(f);
    std::vector<uint32_t> corners;
    for (size_t k = 0; k < face.size(); ++k) corners.push_back(perm[face[(k + 1) % face.size()]]);
    out.add_face(corners);
  }
  return out;
}

std::vector<uint32_t> reversed_order(size_t n) {
  std::vector<uint32_t> perm(n);
  std::iota(perm.begin(), perm.end(), 0u);
  std::reverse(perm.begin(), perm.end());
  return perm;
}

size_t faces_around(const PolygonMesh& p, uint32_t v) {
  size_t n = 0;
  for (size_t f = 0; f < p.num_faces(); ++f) {
    const auto face = p.face(f);
    n += std::count(face.begin(), face.end(), v);
  }
  return n;
}

bool has(const Strings& list, const std::string& s) { return std::find(list.begin(), list.end(), s) != list.end(); }

TEST(MeshCompare, IdenticalMeshesAreEqualBothWays) {
  const HalfedgeMesh m = build_halfedge_mesh(make_icosahedron());
  const MeshComparison loose = compare_meshes(m, m);
  EXPECT_TRUE(loose.equal);
  EXPECT_EQ(loose.total_differences, 0u);
  EXPECT_EQ(loose.summary(), "equal");
  for (VertexId v : m.vertices()) EXPECT_EQ(loose.vertex_map[v.index], v);
  const MeshComparison exact = compare_meshes_exact(m, m, {0.0, 20});
  EXPECT_TRUE(exact.equal);
  EXPECT_TRUE(exact.differences.empty());
}

TEST(MeshCompare, RenumberedCopiesAreEqualUpToRenumberingOnly) {
  for (const PolygonMesh& shape : {make_icosahedron(), make_grid(3, 2), make_cube_quads(), make_torus(6, 4)}) {
    const std::vector<uint32_t> perm = reversed_order(shape.num_vertices());
    const HalfedgeMesh reference = build_halfedge_mesh(shape);
    const HalfedgeMesh yours = build_halfedge_mesh(renumbered(shape, perm));
    const MeshComparison c = compare_meshes(yours, reference);
    EXPECT_TRUE(c.equal) << c.summary();
    for (uint32_t i = 0; i < perm.size(); ++i) EXPECT_EQ(c.vertex_map[perm[i]], VertexId(i));
    EXPECT_TRUE(c.extra_faces.empty() && c.missing_faces.empty() && c.extra_edges.empty());
    EXPECT_FALSE(compare_meshes_exact(yours, reference).equal);
  }
}

TEST(MeshCompare, MovedVertexNamesBothSidesAndTheNearest) {
  const PolygonMesh cube = make_cube();
  const HalfedgeMesh reference = build_halfedge_mesh(cube);
  HalfedgeMesh yours = reference;
  yours.set_position(VertexId(3), {0.5, 0.5, -0.25});
  const MeshComparison c = compare_meshes(yours, reference);
  EXPECT_FALSE(c.equal);
  const std::string faces = std::to_string(faces_around(cube, 3));
  const std::string edges = std::to_string(reference.degree(VertexId(3)));
  EXPECT_EQ(c.differences,
            (Strings{"your vertex v3 at (0.5, 0.5, -0.25) has no match in the reference; the nearest is reference v3 "
                     "at (0.5, 0.5, -0.5), 0.25 away",
                     "reference vertex v3 at (0.5, 0.5, -0.5) has no match in yours; the nearest is your v3 at "
                     "(0.5, 0.5, -0.25), 0.25 away",
                     faces + " of your faces and " + faces +
                         " of the reference's touch a vertex without a match and were not compared",
                     edges + " of your edges and " + edges +
                         " of the reference's touch a vertex without a match and were not compared"}));
  EXPECT_EQ(c.total_differences, 4u);
  EXPECT_EQ(c.unmatched_vertices, std::vector<VertexId>{VertexId(3)});
  EXPECT_EQ(c.unmatched_reference, std::vector<VertexId>{VertexId(3)});
  EXPECT_FALSE(c.vertex_map[3].valid());
  EXPECT_EQ(c.vertex_map[2], VertexId(2));
  EXPECT_EQ(c.summary(), "4 differences; first: " + c.differences[0]);
  // Exactly: one position field.
  EXPECT_EQ(compare_meshes_exact(yours, reference).differences,
            Strings{"v3.position is (0.5, 0.5, -0.25) in yours, (0.5, 0.5, -0.5) in the reference"});
}

TEST(MeshCompare, TwoOfYourVerticesOnOneReferenceVertex) {
  const HalfedgeMesh reference = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh yours = reference;
  yours.set_position(VertexId(2), reference.position(VertexId(1)));
  const MeshComparison c = compare_meshes(yours, reference);
  ASSERT_GE(c.differences.size(), 2u);
  // v1 pairs first (the lower id at distance 0); v2 finds v1 taken.
  EXPECT_EQ(c.differences[0].rfind("your vertex v2 at", 0), 0u) << c.differences[0];
  EXPECT_NE(c.differences[0].find("the nearest is reference v1"), std::string::npos) << c.differences[0];
  EXPECT_NE(c.differences[0].find(", 0 away (already matched to your v1)"), std::string::npos) << c.differences[0];
  EXPECT_EQ(c.differences[1].rfind("reference vertex v2 at", 0), 0u) << c.differences[1];
}

TEST(MeshCompare, ReversedOrientationIsNamedPerFace) {
  PolygonMesh flipped = make_tetrahedron();
  for (size_t f = 0; f < flipped.num_faces(); ++f) {
    std::reverse(flipped.indices.begin() + flipped.face_offsets[f],
                 flipped.indices.begin() + flipped.face_offsets[f + 1]);
  }
  const HalfedgeMesh reference = build_halfedge_mesh(make_tetrahedron());
  const HalfedgeMesh yours = build_halfedge_mesh(flipped);
  const MeshComparison c = compare_meshes(yours, reference);
  // Tetrahedron faces (0 1 2) (0 3 1) (0 2 3) (1 3 2); reversed they are (2 1 0) (1 3 0) (3 2 0) (2 3 1).
  EXPECT_EQ(c.differences,
            (Strings{"your face f0 (v2 v1 v0) has the opposite orientation of reference face f0 (v0 v1 v2)",
                     "your face f1 (v1 v3 v0) has the opposite orientation of reference face f1 (v0 v3 v1)",
                     "your face f2 (v3 v2 v0) has the opposite orientation of reference face f2 (v0 v2 v3)",
                     "your face f3 (v2 v3 v1) has the opposite orientation of reference face f3 (v1 v3 v2)"}));
  EXPECT_EQ(c.reversed_faces.size(), 4u);
  EXPECT_EQ(c.missing_faces.size(), 4u);
  EXPECT_TRUE(c.extra_edges.empty());  // the edges join the same pairs
}

TEST(MeshCompare, OneReversedTriangleBesideARightOne) {
  // Two separate triangles; yours has the second one reversed (its boundary loop runs the other way too).
  PolygonMesh ref;
  for (const glm::dvec3& p : {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(5, 0, 0),
                              glm::dvec3(6, 0, 0), glm::dvec3(5, 1, 0)}) {
    ref.add_vertex(p);
  }
  ref.add_face({0, 1, 2});
  ref.add_face({3, 4, 5});
  PolygonMesh mine = ref;
  mine.indices = {0, 1, 2, 3, 5, 4};
  const MeshComparison c = compare_meshes(build_halfedge_mesh(mine), build_halfedge_mesh(ref));
  ASSERT_EQ(c.differences.size(), 3u) << c.summary();
  EXPECT_EQ(c.differences[0], "your face f1 (v3 v5 v4) has the opposite orientation of reference face f1 (v3 v4 v5)");
  EXPECT_EQ(c.differences[1].rfind("your boundary loop b1 (", 0), 0u) << c.differences[1];
  EXPECT_NE(c.differences[1].find(") is not in the reference"), std::string::npos) << c.differences[1];
  EXPECT_EQ(c.differences[2].rfind("reference boundary loop b1 (", 0), 0u) << c.differences[2];
  EXPECT_EQ(c.reversed_faces, std::vector<FaceId>{FaceId::face(1)});
  EXPECT_EQ(c.extra_boundaries, std::vector<FaceId>{FaceId::boundary(1)});
  EXPECT_EQ(c.missing_boundaries, std::vector<FaceId>{FaceId::boundary(1)});
}

TEST(MeshCompare, MissingFaceAndTheBoundaryItChanges) {
  // grid(1,1): f0 = (0 1 3), f1 = (0 3 2); yours lacks f1.
  const PolygonMesh grid = make_grid(1, 1);
  PolygonMesh fewer;
  fewer.positions = grid.positions;
  fewer.add_face(grid.face(0));
  const HalfedgeMesh reference = build_halfedge_mesh(grid);
  BuildReport report;
  const HalfedgeMesh yours = build_halfedge_mesh(fewer, &report);
  ASSERT_EQ(report.unused_vertices, 1u);  // v2 is a dead slot in yours
  const MeshComparison c = compare_meshes(yours, reference);
  EXPECT_FALSE(c.equal);
  ASSERT_GE(c.differences.size(), 6u) << c.summary();
  EXPECT_EQ(c.differences[0], "the reference has 4 vertices, yours 3");
  EXPECT_EQ(c.differences[1], "the reference has 5 edges, yours 3");
  EXPECT_EQ(c.differences[2], "the reference has 2 faces, yours 1");
  EXPECT_EQ(c.differences[3], "the reference has 10 halfedges, yours 6");
  EXPECT_EQ(c.differences[4],
            "reference vertex v2 at (0, 1, 0) has no match in yours; the nearest is your v0 at (0, 0, 0), 1 away "
            "(already matched to reference v0)");
  EXPECT_TRUE(has(c.differences,
                  "0 of your faces and 1 of the reference's touch a vertex without a match and were "
                  "not compared"))
      << c.summary();
  EXPECT_EQ(c.missing_faces, std::vector<FaceId>{FaceId::face(1)});
  EXPECT_TRUE(c.extra_faces.empty());
  EXPECT_EQ(c.missing_edges.size(), 2u);  // v0-v2, v2-v3 (v0-v3 is in yours, on the boundary now)
  EXPECT_TRUE(c.extra_edges.empty());
  EXPECT_EQ(c.extra_boundaries.size(), 1u);
  EXPECT_EQ(c.missing_boundaries.size(), 1u);

  // A face missing where every corner is still matched: a hole in the middle of grid(3,3), whose inner
  // vertices are v5 v6 v9 v10.
  const PolygonMesh big = make_grid(3, 3);
  PolygonMesh gap;
  gap.positions = big.positions;
  size_t removed = big.num_faces();
  for (size_t f = 0; f < big.num_faces(); ++f) {
    const auto face = big.face(f);
    const bool inner =
        std::all_of(face.begin(), face.end(), [](uint32_t v) { return v == 5 || v == 6 || v == 9 || v == 10; });
    if (inner && removed == big.num_faces()) removed = f;
    else gap.add_face(face);
  }
  ASSERT_LT(removed, big.num_faces());
  const auto hole = big.face(removed);
  const MeshComparison g = compare_meshes(build_halfedge_mesh(gap), build_halfedge_mesh(big));
  const std::string message = "reference face f" + std::to_string(removed) + " (v" + std::to_string(hole[0]) + " v" +
                              std::to_string(hole[1]) + " v" + std::to_string(hole[2]) + ") is missing from yours";
  EXPECT_TRUE(has(g.differences, message)) << message << "\n" << g.summary();
  EXPECT_EQ(g.missing_faces, std::vector<FaceId>{FaceId::face(static_cast<uint32_t>(removed))});
  EXPECT_EQ(g.extra_boundaries.size(), 1u);  // the hole
  EXPECT_TRUE(g.missing_edges.empty());
}

TEST(MeshCompare, RenumberedMessagesShowYourIdsToo) {
  // Yours is the tetrahedron without f0 = (0 1 2), with vertex i renamed 3 - i.
  const PolygonMesh tetrahedron = make_tetrahedron();
  PolygonMesh open;
  open.positions = tetrahedron.positions;
  for (size_t f = 1; f < 4; ++f) open.add_face(tetrahedron.face(f));
  const HalfedgeMesh reference = build_halfedge_mesh(tetrahedron);
  const HalfedgeMesh yours = build_halfedge_mesh(renumbered(open, {3, 2, 1, 0}));
  const MeshComparison c = compare_meshes(yours, reference);
  EXPECT_TRUE(has(c.differences, "reference face f0 (v0 v1 v2; your v3 v2 v1) is missing from yours")) << c.summary();
  EXPECT_EQ(c.vertex_map[3], VertexId(0));
  EXPECT_EQ(c.extra_boundaries.size(), 1u);
}

TEST(MeshCompare, ToleranceIsInclusiveAndCrossesCells) {
  const HalfedgeMesh reference = build_halfedge_mesh(make_tetrahedron());
  const glm::dvec3 p = reference.position(VertexId(0));
  const auto moved = [&](const glm::dvec3& delta) {
    HalfedgeMesh m = reference;
    m.set_position(VertexId(0), p + delta);
    return m;
  };
  EXPECT_TRUE(compare_meshes(moved({0.5e-9, 0, 0}), reference).equal);
  EXPECT_FALSE(compare_meshes(moved({2e-9, 0, 0}), reference).equal);
  EXPECT_TRUE(compare_meshes(moved({2e-9, 0, 0}), reference, {1e-8, 20}).equal);
  // Zero tolerance: bit for bit.
  EXPECT_TRUE(compare_meshes(reference, reference, {0.0, 20}).equal);
  EXPECT_FALSE(compare_meshes(moved({1e-15, 0, 0}), reference, {0.0, 20}).equal);

  // A distance of exactly the tolerance matches; the two points lie in different cells of size 0.25.
  PolygonMesh a;
  a.add_vertex({0, 0, 0});
  a.add_vertex({1, 0, 0});
  a.add_vertex({0, 1, 0});
  a.add_face({0, 1, 2});
  PolygonMesh b = a;
  b.positions[1] = {1.25, 0, 0};
  const HalfedgeMesh ma = build_halfedge_mesh(a), mb = build_halfedge_mesh(b);
  EXPECT_TRUE(compare_meshes(ma, mb, {0.25, 20}).equal);
  EXPECT_FALSE(compare_meshes(ma, mb, {0.2499, 20}).equal);
  b.positions[1] = {1.0, -0.1, 0.1};  // across cell boundaries in y and z at tolerance 0.2
  EXPECT_TRUE(compare_meshes(ma, build_halfedge_mesh(b), {0.2, 20}).equal);
  // Negative zero and zero are the same point.
  b.positions[1] = {1.0, -0.0, -0.0};
  EXPECT_TRUE(compare_meshes(ma, build_halfedge_mesh(b), {0.0, 20}).equal);
}

TEST(MeshCompare, NonFinitePositionsMatchNothing) {
  const HalfedgeMesh reference = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh yours = reference;
  yours.set_position(VertexId(1), {std::nan(""), 0, 0});
  const MeshComparison c = compare_meshes(yours, reference);
  ASSERT_FALSE(c.differences.empty());
  EXPECT_EQ(c.differences[0], "your vertex v1 at (nan, 0, 0) has a position that is not finite; it matches nothing");
  EXPECT_EQ(c.unmatched_vertices, std::vector<VertexId>{VertexId(1)});
}

TEST(MeshCompare, ExactNamesEveryChangedPointerAfterAFlip) {
  const HalfedgeMesh reference = build_halfedge_mesh(make_grid(1, 1));
  HalfedgeMesh yours = reference;
  ASSERT_TRUE(flip(yours, EdgeId(2)).ok());
  const MeshComparison exact = compare_meshes_exact(yours, reference);
  EXPECT_FALSE(exact.equal);
  // From flip_test: h2 now runs v2 -> v1 with next h1 (it ran v3 -> v0 with next h0).
  EXPECT_TRUE(has(exact.differences, "h2.next is h1 in yours, h0 in the reference")) << exact.summary();
  EXPECT_TRUE(has(exact.differences, "h2.vertex is v2 in yours, v3 in the reference")) << exact.summary();
  // Up to renumbering the flipped diagonal is an edge the reference lacks, and the old one is missing.
  const MeshComparison loose = compare_meshes(yours, reference);
  EXPECT_TRUE(has(loose.differences, "your edge e2 (v2 v1) is not in the reference")) << loose.summary();
  EXPECT_TRUE(has(loose.differences, "reference edge e2 (v3 v0) is missing from yours")) << loose.summary();
  EXPECT_EQ(loose.extra_edges, std::vector<EdgeId>{EdgeId(2)});
  EXPECT_EQ(loose.missing_edges, std::vector<EdgeId>{EdgeId(2)});
  EXPECT_EQ(loose.extra_faces.size(), 2u);
}

TEST(MeshCompare, ExactReportsElementsOnlyOneSideHas) {
  const HalfedgeMesh reference = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh yours = reference;
  yours.new_vertex({1, 2, 3});
  yours.delete_element(EdgeId(5));
  EXPECT_EQ(compare_meshes_exact(yours, reference).differences,
            (Strings{"the reference has 4 vertices, yours 5", "the reference has 6 edges, yours 5",
                     "yours has v4, the reference does not", "the reference has e5, yours does not"}));
}

TEST(MeshCompare, BrokenCyclesAreReportedNotFollowed) {
  const HalfedgeMesh reference = build_halfedge_mesh(make_tetrahedron());
  HalfedgeMesh yours = reference;
  yours.set_next(HalfedgeId(2), HalfedgeId(1));  // f0: h0 h1 h2 h1 h2 ... never back to h0
  const MeshComparison c = compare_meshes(yours, reference);
  EXPECT_FALSE(c.equal);
  EXPECT_TRUE(has(c.differences,
                  "your face f0 cannot be walked: its next-cycle does not close, has fewer than 3 halfedges, or "
                  "reaches a dead element"))
      << c.summary();
  EXPECT_TRUE(has(c.differences, "reference face f0 (v0 v1 v2) is missing from yours")) << c.summary();
  HalfedgeMesh dead = reference;
  dead.delete_element(dead.halfedge(EdgeId(0)));
  const MeshComparison d = compare_meshes(dead, reference);
  EXPECT_TRUE(has(d.differences, "your edge e0 cannot be read: its halfedge, twin or their vertices are dead"))
      << d.summary();
}

TEST(MeshCompare, CapKeepsTwentyAndCountsAll) {
  const HalfedgeMesh reference = build_halfedge_mesh(make_grid(10, 10));
  HalfedgeMesh yours = reference;
  for (VertexId v : yours.vertices()) yours.set_position(v, yours.position(v) + glm::dvec3(0, 0, 1));
  const MeshComparison c = compare_meshes(yours, reference);
  EXPECT_EQ(c.differences.size(), 20u);
  // 121 of yours and 121 of the reference unmatched, plus one "not compared" line for faces, loops and edges.
  EXPECT_EQ(c.total_differences, 121u + 121u + 3u);
  EXPECT_EQ(c.unmatched_vertices.size(), 121u);
  const MeshComparison few = compare_meshes(yours, reference, {1e-9, 3});
  EXPECT_EQ(few.differences.size(), 3u);
  EXPECT_EQ(few.total_differences, c.total_differences);
}

}  // namespace
}  // namespace meshedit
