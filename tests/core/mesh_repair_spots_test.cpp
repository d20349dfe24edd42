// The spots of a repair report (mesh_repair.h): each change names where it is in the repaired polygons, as output
// vertex and face indices, and those are the VertexId and FaceId of the half-edge mesh built from them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_repair.h"
#include "core/primitives.h"
#include "core/validate.h"

namespace meshedit {
namespace {

using Indices = std::vector<uint32_t>;

// Checks that every spot is a vertex or face of the mesh built from r.polygons with the same id: the vertex's
// position and the face's corners, in order from its first halfedge, are the polygons'.
void expect_spots_are_built_ids(const RepairResult& r) {
  ASSERT_EQ(r.report.spots.size(), r.report.changes.size());
  const HalfedgeMesh mesh = build_halfedge_mesh(r.polygons);
  ASSERT_TRUE(validate(mesh).ok());
  for (size_t i = 0; i < r.report.spots.size(); ++i) {
    const RepairSpots& s = r.report.spots[i];
    for (uint32_t v : s.vertices) {
      ASSERT_LT(v, r.polygons.num_vertices()) << r.report.changes[i];
      ASSERT_TRUE(mesh.alive(VertexId(v))) << r.report.changes[i];
      EXPECT_EQ(mesh.position(VertexId(v)), r.polygons.positions[v]) << r.report.changes[i];
    }
    for (uint32_t f : s.faces) {
      ASSERT_LT(f, r.polygons.num_faces()) << r.report.changes[i];
      ASSERT_TRUE(mesh.alive(FaceId(f))) << r.report.changes[i];
      Indices corners;
      mesh.for_each_face_halfedge(FaceId(f), [&](HalfedgeId h) { corners.push_back(mesh.vertex(h).index); });
      EXPECT_EQ(corners, Indices(r.polygons.face(f).begin(), r.polygons.face(f).end())) << r.report.changes[i];
    }
  }
}

TEST(MeshRepairSpots, ABowTieSplitNamesTheVertexItsCopyAndTheMovedFace) {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({0, 3, 4});
  const RepairResult r = repair_polygons(p);
  ASSERT_EQ(r.report.spots.size(), 1u);
  EXPECT_EQ(r.report.spots[0].vertices, (Indices{0, 5}));
  EXPECT_EQ(r.report.spots[0].faces, (Indices{1}));
  expect_spots_are_built_ids(r);
}

TEST(MeshRepairSpots, ADetachedFaceNamesItsFaceAndItsTwoNewVertices) {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  p.add_face({0, 1, 2});
  p.add_face({1, 0, 3});
  p.add_face({0, 1, 4});  // a fin on edge 0-1
  const RepairResult r = repair_polygons(p);
  ASSERT_EQ(r.report.spots.size(), 1u);
  EXPECT_EQ(r.report.spots[0].vertices, (Indices{5, 6}));
  EXPECT_EQ(r.report.spots[0].faces, (Indices{2}));
  expect_spots_are_built_ids(r);
}

TEST(MeshRepairSpots, DroppedFacesPointAtTheirSurvivorsAndDroppedVerticesAtNothing) {
  // Vertex 0 unused; a bow-tie at vertex 1; face 2 repeats face 0; face 3 is flipped against face 4. The output
  // numbers differ from the file's: old vertex k is k - 1, face 3 is output face 2.
  PolygonMesh p;
  p.positions = {{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {-2, -1, 0}};
  p.add_face({1, 2, 3});
  p.add_face({1, 4, 5});
  p.add_face({2, 3, 1});
  p.add_face({4, 5, 6});
  const RepairResult r = repair_polygons(p);
  ASSERT_EQ(r.report.changes.size(), 4u);
  ASSERT_EQ(r.report.spots.size(), 4u);
  // "face 2 repeated face 0: dropped": face 0.
  EXPECT_EQ(r.report.spots[0].vertices, Indices{});
  EXPECT_EQ(r.report.spots[0].faces, (Indices{0}));
  // "face 3 reversed to agree with face 1": output face 2.
  EXPECT_EQ(r.report.spots[1].vertices, Indices{});
  EXPECT_EQ(r.report.spots[1].faces, (Indices{2}));
  // "vertex 1 was a bow-tie: split into 1 and new vertex 6 (face 1 moved)": output vertices 0 and 6, face 1.
  EXPECT_EQ(r.report.spots[2].vertices, (Indices{0, 6}));
  EXPECT_EQ(r.report.spots[2].faces, (Indices{1}));
  // "vertex 0 was used by no face: dropped": nothing.
  EXPECT_TRUE(r.report.spots[3].empty());
  expect_spots_are_built_ids(r);
}

TEST(MeshRepairSpots, ADegenerateFacePointsAtItsCornersThatAreVertices) {
  PolygonMesh p = make_grid(2, 1);
  p.add_face({0, 1, 2});  // face 4: zero area
  p.add_face({0, 1, 9});  // face 5: no vertex 9
  const RepairResult r = repair_polygons(p);
  ASSERT_EQ(r.report.spots.size(), 2u);
  EXPECT_EQ(r.report.spots[0].vertices, (Indices{0, 1, 2}));
  EXPECT_EQ(r.report.spots[1].vertices, (Indices{0, 1}));
  EXPECT_EQ(r.report.spots[0].faces, Indices{});
  expect_spots_are_built_ids(r);
}

TEST(MeshRepairSpots, ABowTieAFinAndAFlippedFaceTogether) {
  // Triangles 0 and 1 touch only at vertex 0; triangles 2, 3 and 4 share the edge 5-6 (a fin); triangle 5 shares the
  // edge 6-7 with triangle 2 the same way round (flipped).
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0},   {1, 1, 0},    {-1, 0, 0},  {-1, -1, 0}, {3, 0, 0},
                 {4, 0, 0}, {3.5, 1, 0}, {3.5, -1, 0}, {3.5, 0, 1}, {4.5, 1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({0, 3, 4});
  p.add_face({5, 6, 7});
  p.add_face({6, 5, 8});
  p.add_face({5, 6, 9});
  p.add_face({6, 7, 10});
  const RepairResult r = repair_polygons(p);
  ASSERT_EQ(r.report.changes.size(), 3u) << ::testing::PrintToString(r.report.changes);
  // Detached: face 4, its corners on 5-6 now vertices 11 and 12.
  EXPECT_EQ(r.report.spots[0].vertices, (Indices{11, 12}));
  EXPECT_EQ(r.report.spots[0].faces, (Indices{4}));
  // Reversed: face 5.
  EXPECT_EQ(r.report.spots[1].faces, (Indices{5}));
  // The bow-tie at vertex 0: its copy is vertex 13, made after the fin's two.
  EXPECT_EQ(r.report.spots[2].vertices, (Indices{0, 13}));
  EXPECT_EQ(r.report.spots[2].faces, (Indices{1}));
  expect_spots_are_built_ids(r);
}

// Three quads round a circle, the last joined with a half twist, after an unused vertex 0: the file's vertex k is
// output vertex k - 1, and the two new vertices are output vertices 6 and 7. The walk from face 0 meets itself
// across edge 5-6 (the file's numbers), between faces 1 and 2; the report names the file's vertices and the new
// vertices' output numbers, the spots give the edge in output numbers on face 1's side, then on face 2's, and the
// two faces.
TEST(MeshRepairSpots, ACutNamesTheEdgeOnBothSidesAndItsTwoFaces) {
  PolygonMesh p;
  p.positions = {{9, 9, 9},        {1, 0, 0},         {1.5, 0, 0.2},     {-0.5, 0.9, -0.2},
                 {-0.7, 1.2, 0.2}, {-0.5, -0.9, 0.1}, {-0.8, -1.3, -0.1}};
  p.add_face({1, 2, 4, 3});
  p.add_face({3, 4, 6, 5});
  p.add_face({5, 6, 1, 2});  // the twist: 1 and 2 swap sides
  const RepairResult r = repair_polygons(p);
  ASSERT_EQ(r.report.changes,
            (std::vector<std::string>{"face 2 reversed to agree with face 0",
                                      "the edge between vertex 5 and vertex 6 was cut: faces 1 and 2 disagree on its "
                                      "direction; it is now between vertex 5 and vertex 6 in face 1, and between new "
                                      "vertex 6 and new vertex 7 in face 2",
                                      "vertex 0 was used by no face: dropped"}));
  EXPECT_EQ(r.polygons.indices, (Indices{0, 1, 3, 2, 2, 3, 5, 4, 6, 1, 0, 7}));
  EXPECT_EQ(r.polygons.positions[6], p.positions[5]);
  EXPECT_EQ(r.polygons.positions[7], p.positions[6]);
  EXPECT_EQ(r.report.spots[0].faces, (Indices{2}));
  EXPECT_EQ(r.report.spots[1].vertices, (Indices{4, 5, 6, 7}));
  EXPECT_EQ(r.report.spots[1].faces, (Indices{1, 2}));
  expect_spots_are_built_ids(r);
}

}  // namespace
}  // namespace meshedit
