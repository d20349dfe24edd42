// Repairing polygons: each defect on a hand-made mesh is fixed, reported with the input's own vertex and face
// numbers, and the result builds and validates; a mesh with nothing wrong comes back identical with no report.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/primitives.h"
#include "core/validate.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;

// The faces of `p` as lists of indices, for whole-mesh comparisons with readable failures.
std::vector<std::vector<uint32_t>> faces_of(const PolygonMesh& p) {
  std::vector<std::vector<uint32_t>> faces;
  for (size_t f = 0; f < p.num_faces(); ++f) faces.emplace_back(p.face(f).begin(), p.face(f).end());
  return faces;
}

// Repairs `input`, checks that the plain builder refused it and that the repaired polygons build and validate.
RepairResult repair_and_build(const PolygonMesh& input) {
  EXPECT_THROW(build_halfedge_mesh(input), MeshError) << "the input should need repair";
  RepairResult result = repair_polygons(input);
  try {
    const HalfedgeMesh mesh = build_halfedge_mesh(result.polygons);
    EXPECT_TRUE(validate(mesh).ok());
  } catch (const MeshError& e) {
    ADD_FAILURE() << "repaired polygons do not build: " << e.what();
  }
  return result;
}

TEST(MeshRepair, BowTieVertexIsSplitPerFan) {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({0, 3, 4});
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, Strings{"vertex 0 was a bow-tie: split into 0 and new vertex 5 (face 1 moved)"});
  EXPECT_EQ(r.report.summary(), "repaired: 1 bow-tie vertex split");
  EXPECT_EQ(r.report.split_vertices, 1u);
  ASSERT_EQ(r.polygons.num_vertices(), 6u);
  EXPECT_EQ(r.polygons.positions[5], p.positions[0]);
  EXPECT_EQ(faces_of(r.polygons), (std::vector<std::vector<uint32_t>>{{0, 1, 2}, {5, 3, 4}}));
}

TEST(MeshRepair, BowTieOfThreeFansNamesEachCopy) {
  // Three triangles meeting only at vertex 0.
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {0, 2, 1}, {1, 2, 1}};
  p.add_face({0, 1, 2});
  p.add_face({0, 3, 4});
  p.add_face({0, 5, 6});
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, Strings{"vertex 0 was a bow-tie: split into 0, new vertex 7 and new vertex 8 "
                                      "(face 1 moved to 7; face 2 moved to 8)"});
  EXPECT_EQ(faces_of(r.polygons), (std::vector<std::vector<uint32_t>>{{0, 1, 2}, {7, 3, 4}, {8, 5, 6}}));
}

TEST(MeshRepair, ThirdFaceOnAnEdgeIsDetached) {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  p.add_face({0, 1, 2});
  p.add_face({1, 0, 3});
  p.add_face({0, 1, 4});  // a fin on edge 0-1
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, Strings{"the edge between vertex 0 and vertex 1 had faces 0..2: face 2 detached "
                                      "(its corners there are now new vertices 5 and 6)"});
  EXPECT_EQ(r.report.summary(), "repaired: 1 face detached from an edge of 3+ faces");
  ASSERT_EQ(r.polygons.num_vertices(), 7u);
  EXPECT_EQ(r.polygons.positions[5], p.positions[0]);
  EXPECT_EQ(r.polygons.positions[6], p.positions[1]);
  EXPECT_EQ(faces_of(r.polygons), (std::vector<std::vector<uint32_t>>{{0, 1, 2}, {1, 0, 3}, {5, 6, 4}}));
}

TEST(MeshRepair, FaceUsingTheEdgeTheOtherWayIsKeptAtAnEdgeOfThreeFaces) {
  // Faces 0 and 1 use 0->1 the same way; face 2 uses it the other way and is the one kept with face 0.
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0, 1}, {0.5, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({0, 1, 3});
  p.add_face({1, 0, 4});
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.detached_faces, 1u);
  EXPECT_EQ(faces_of(r.polygons), (std::vector<std::vector<uint32_t>>{{0, 1, 2}, {5, 6, 3}, {1, 0, 4}}));
}

TEST(MeshRepair, RepeatedFaceIsDropped) {
  PolygonMesh p = make_cube();
  const std::vector<uint32_t> face3(p.face(3).begin(), p.face(3).end());
  p.add_face({face3[1], face3[0], face3[2]});  // face 12: face 3's corners, the other way round
  p.add_face({face3[2], face3[0], face3[1]});  // face 13: again
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, (Strings{"face 12 repeated face 3: dropped", "face 13 repeated face 3: dropped"}));
  EXPECT_EQ(r.report.summary(), "repaired: 2 repeated faces dropped");
  EXPECT_EQ(r.polygons.positions, make_cube().positions);
  EXPECT_EQ(faces_of(r.polygons), faces_of(make_cube()));
}

TEST(MeshRepair, DegenerateFacesAreDropped) {
  PolygonMesh p = make_grid(2, 1);  // vertices 0, 1, 2 lie on the x axis
  p.add_face({0, 1, 2});            // face 4: zero area
  p.add_face({3, 3, 4});            // face 5: a repeated corner
  p.add_face({4, 5});               // face 6: two corners
  p.add_face({0, 1, 9});            // face 7: no vertex 9
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes,
            (Strings{"face 4 has zero area: dropped", "face 5 repeats vertex 3: dropped",
                     "face 6 has 2 corners: dropped", "face 7 uses vertex 9, but there are only 6: dropped"}));
  EXPECT_EQ(r.report.summary(), "repaired: 4 degenerate faces dropped");
  EXPECT_EQ(r.polygons.positions, make_grid(2, 1).positions);
  EXPECT_EQ(faces_of(r.polygons), faces_of(make_grid(2, 1)));
}

// `p` with face f's corners 1 and 2 swapped.
void flip_face(PolygonMesh& p, size_t f) {
  std::swap(p.indices[p.face_offsets[f] + 1], p.indices[p.face_offsets[f] + 2]);
}

TEST(MeshRepair, OneFlippedFaceInAGridIsReversed) {
  PolygonMesh p = make_grid(3, 3);
  flip_face(p, 7);
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, Strings{"face 7 reversed to agree with face 0"});
  EXPECT_EQ(r.report.summary(), "repaired: 1 face reversed");
  EXPECT_EQ(faces_of(r.polygons), faces_of(make_grid(3, 3)));
}

TEST(MeshRepair, TheMajorityOrientationIsKept) {
  // Faces 0..9 of 18 flipped: the flipped ones are the majority, so faces 10..17 are reversed to agree with them.
  PolygonMesh p = make_grid(3, 3);
  for (size_t f = 0; f < 10; ++f) flip_face(p, f);
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, Strings{"faces 10..17 reversed to agree with face 0"});
  EXPECT_EQ(r.report.reversed_faces, 8u);
  const PolygonMesh grid = make_grid(3, 3);
  for (size_t f = 0; f < grid.num_faces(); ++f) {
    const auto g = grid.face(f);
    // Every face now goes the flipped way: corner 0 first, then the other two swapped.
    EXPECT_EQ(faces_of(r.polygons)[f], (std::vector<uint32_t>{g[0], g[2], g[1]})) << "face " << f;
  }
}

TEST(MeshRepair, UnusedVerticesAreDroppedAndTheRestRenumbered) {
  // The tetrahedron with an unused vertex inserted as vertex 1 and another appended as vertex 5.
  const PolygonMesh tet = make_tetrahedron();
  PolygonMesh p;
  p.positions = {tet.positions[0], {9, 9, 9}, tet.positions[1], tet.positions[2], tet.positions[3], {7, 7, 7}};
  for (size_t f = 0; f < tet.num_faces(); ++f) {
    std::vector<uint32_t> corners;
    for (uint32_t i : tet.face(f)) corners.push_back(i == 0 ? 0 : i + 1);
    p.add_face(corners);
  }
  const RepairResult r = repair_polygons(p);  // the builder accepts unused vertices (as dead ids)
  EXPECT_EQ(r.report.changes, Strings{"vertices 1, 5 were used by no face: dropped"});
  EXPECT_EQ(r.report.summary(), "repaired: 2 unused vertices dropped");
  EXPECT_EQ(r.polygons.positions, tet.positions);
  EXPECT_EQ(faces_of(r.polygons), faces_of(tet));
  EXPECT_TRUE(validate(build_halfedge_mesh(r.polygons)).ok());
}

TEST(MeshRepair, SeveralDefectsAreReportedWithTheOriginalNumbers) {
  // Vertex 0 unused; a bow-tie at vertex 1; face 2 repeats face 0; face 3 is flipped against face 4.
  PolygonMesh p;
  p.positions = {{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {-2, -1, 0}};
  p.add_face({1, 2, 3});
  p.add_face({1, 4, 5});
  p.add_face({2, 3, 1});
  p.add_face({4, 5, 6});  // shares 4-5 with face 1 in the same direction
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, (Strings{"face 2 repeated face 0: dropped", "face 3 reversed to agree with face 1",
                                       "vertex 1 was a bow-tie: split into 1 and new vertex 6 (face 1 moved)",
                                       "vertex 0 was used by no face: dropped"}));
  EXPECT_EQ(r.report.summary(),
            "repaired: 1 bow-tie vertex split, 1 repeated face dropped, 1 face reversed, 1 unused vertex dropped");
  // Old vertex k is now k - 1; the copy of vertex 1 is the last one.
  ASSERT_EQ(r.polygons.num_vertices(), 7u);
  EXPECT_EQ(r.polygons.positions[6], p.positions[1]);
  EXPECT_EQ(faces_of(r.polygons), (std::vector<std::vector<uint32_t>>{{0, 1, 2}, {6, 3, 4}, {3, 5, 4}}));
}

// Six quads (as triangles) around a circle, the last one joined with a half twist: vertex 2i and 2i + 1 are the
// two sides at angle 60i degrees, faces 2i and 2i + 1 the quad from there to the next.
PolygonMesh moebius_strip() {
  PolygonMesh p;
  for (int i = 0; i < 6; ++i) {
    const double t = 2 * M_PI * i / 6, half = t / 2;
    for (double side : {-0.3, 0.3}) {
      p.add_vertex({std::cos(t) * (1 + side * std::cos(half)), std::sin(t) * (1 + side * std::cos(half)),
                    side * std::sin(half)});
    }
  }
  for (uint32_t i = 0; i < 6; ++i) {
    const uint32_t a = 2 * i, b = 2 * i + 1;
    const uint32_t c = i < 5 ? 2 * i + 3 : 0, d = i < 5 ? 2 * i + 2 : 1;  // the twist: 0 and 1 swap sides
    p.add_face({a, b, c});
    p.add_face({a, c, d});
  }
  return p;
}

// The walk from face 0 goes both ways round and meets itself at faces 5 and 6, which the orientations it fixed make
// use edge 6-7 the same way: that edge is cut, its ends copied for face 6's side (and face 7, which shares vertex 6
// with face 6 only). What is left is a strip of 12 triangles with one boundary of 14 edges.
TEST(MeshRepair, AMoebiusStripIsCutAcrossWhereTheWalkMeetsItself) {
  const PolygonMesh p = moebius_strip();
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, (Strings{"faces 6..11 reversed to agree with face 0",
                                       "the edge between vertex 6 and vertex 7 was cut: faces 5 and 6 disagree on its "
                                       "direction; it is now between vertex 6 and vertex 7 in face 5, and between new "
                                       "vertex 12 and new vertex 13 in face 6"}));
  EXPECT_EQ(r.report.summary(), "repaired: 6 faces reversed, 1 edge cut where its faces disagree");
  EXPECT_EQ(r.report.cut_edges, 1u);
  EXPECT_EQ(r.report.reversed_faces, 6u);
  ASSERT_EQ(r.polygons.num_vertices(), 14u);
  EXPECT_EQ(std::vector<glm::dvec3>(r.polygons.positions.begin(), r.polygons.positions.begin() + 12), p.positions);
  EXPECT_EQ(r.polygons.positions[12], p.positions[6]);
  EXPECT_EQ(r.polygons.positions[13], p.positions[7]);
  EXPECT_EQ(faces_of(r.polygons), (std::vector<std::vector<uint32_t>>{{0, 1, 3},
                                                                      {0, 3, 2},
                                                                      {2, 3, 5},
                                                                      {2, 5, 4},
                                                                      {4, 5, 7},
                                                                      {4, 7, 6},
                                                                      {12, 9, 13},
                                                                      {12, 8, 9},
                                                                      {8, 11, 9},
                                                                      {8, 10, 11},
                                                                      {10, 0, 11},
                                                                      {10, 1, 0}}));
  const HalfedgeMesh mesh = build_halfedge_mesh(r.polygons);
  EXPECT_EQ(mesh.num_boundaries(), 1u);
  EXPECT_EQ(mesh.num_halfedges() - 3 * mesh.num_faces(), 14u);  // the boundary's halfedges
}

// Vertex 6, an end of the cut edge, is also a bow-tie: a triangle (face 12) touches it alone. The cut splits the
// strip's fan there (face 6's side gets new vertex 14), then step 5 splits the bow-tie as ever (face 12 moved).
TEST(MeshRepair, ACutEndThatIsAlsoABowTieIsCutThenSplit) {
  PolygonMesh p = moebius_strip();
  p.add_vertex({-1.5, 0.2, 1});
  p.add_vertex({-1.5, -0.2, 1});
  p.add_face({6, 12, 13});
  const RepairResult r = repair_and_build(p);
  EXPECT_EQ(r.report.changes, (Strings{"faces 6..11 reversed to agree with face 0",
                                       "the edge between vertex 6 and vertex 7 was cut: faces 5 and 6 disagree on its "
                                       "direction; it is now between vertex 6 and vertex 7 in face 5, and between new "
                                       "vertex 14 and new vertex 15 in face 6",
                                       "vertex 6 was a bow-tie: split into 6 and new vertex 16 (face 12 moved)"}));
  ASSERT_EQ(r.polygons.num_vertices(), 17u);
  for (uint32_t copy : {14u, 16u}) EXPECT_EQ(r.polygons.positions[copy], p.positions[6]);
  EXPECT_EQ(r.polygons.positions[15], p.positions[7]);
  EXPECT_EQ(faces_of(r.polygons)[5], (std::vector<uint32_t>{4, 7, 6}));
  EXPECT_EQ(faces_of(r.polygons)[6], (std::vector<uint32_t>{14, 9, 15}));
  EXPECT_EQ(faces_of(r.polygons)[7], (std::vector<uint32_t>{14, 8, 9}));
  EXPECT_EQ(faces_of(r.polygons)[12], (std::vector<uint32_t>{16, 12, 13}));
}

TEST(MeshRepair, AGoodMeshIsLeftAsItIs) {
  for (const PolygonMesh& good : {make_icosahedron(), make_cube_quads(), make_grid(4, 2), make_torus(8, 6)}) {
    const RepairResult r = repair_polygons(good);
    EXPECT_TRUE(r.report.empty());
    EXPECT_EQ(r.report.summary(), "nothing to repair");
    EXPECT_EQ(r.polygons.positions, good.positions);
    EXPECT_EQ(r.polygons.indices, good.indices);
    EXPECT_EQ(r.polygons.face_offsets, good.face_offsets);
  }
}

TEST(MeshRepair, NumberListsWriteRunsAsRanges) {
  EXPECT_EQ(number_list({}), "");
  EXPECT_EQ(number_list({3}), "3");
  EXPECT_EQ(number_list({5, 3}), "3, 5");
  EXPECT_EQ(number_list({20, 21, 22, 23, 4, 1, 2}), "1, 2, 4, 20..23");
}

}  // namespace
}  // namespace meshedit
