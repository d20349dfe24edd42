// The one-sided meshes of tests/data/repair (README.md there): a Moebius strip, a Klein bottle and a scan-like sheet
// with a twisted flap. Each is refused as read, and after one repair is cut where its faces cannot agree: the report
// names the cut edges and their faces with the file's numbers, the new vertices sit at their originals' positions in
// the faces named, each cut edge is a boundary edge on both sides, and the repaired mesh builds, validates and
// subdivides (triangulated for Loop, as it is for Catmull-Clark).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/validate.h"
#include "io/mesh_file.h"
#include "io/window_open.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::expect_subdivides;

using Strings = std::vector<std::string>;
using Faces = std::vector<std::vector<uint32_t>>;

fs::path repair_file(const std::string& name) { return testing::source_dir() / "tests" / "data" / "repair" / name; }

// A file as read, the builder's refusal of it, and its repair.
struct Repaired {
  PolygonMesh read;
  std::string refusal;
  RepairResult repair;
};

Repaired read_and_repair(const std::string& name) {
  Repaired r;
  r.read = load_mesh(repair_file(name));
  try {
    build_halfedge_mesh(r.read);
  } catch (const MeshError& e) {
    r.refusal = e.what();
  }
  r.repair = repair_polygons(r.read);
  return r;
}

Faces faces_of(const PolygonMesh& p) {
  Faces faces;
  for (size_t f = 0; f < p.num_faces(); ++f) faces.emplace_back(p.face(f).begin(), p.face(f).end());
  return faces;
}

// The output faces that use a vertex numbered `first_new` or more, and the sorted corners of those faces.
std::map<uint32_t, std::vector<uint32_t>> faces_with_new_vertices(const PolygonMesh& p, uint32_t first_new) {
  std::map<uint32_t, std::vector<uint32_t>> out;
  for (uint32_t f = 0; f < p.num_faces(); ++f) {
    for (uint32_t v : p.face(f)) {
      if (v >= first_new) out[f].push_back(v);
    }
  }
  return out;
}

// Face f's halfedge between a and b (either way), or an invalid id.
HalfedgeId edge_in_face(const HalfedgeMesh& m, FaceId f, uint32_t a, uint32_t b) {
  HalfedgeId found;
  m.for_each_face_halfedge(f, [&](HalfedgeId h) {
    const uint32_t from = m.vertex(h).index, to = m.vertex(m.next(h)).index;
    if ((from == a && to == b) || (from == b && to == a)) found = h;
  });
  return found;
}

// The repaired polygons built (a failure, and an empty mesh, if the builder refuses them), and validated.
HalfedgeMesh build_repaired(const RepairResult& r) {
  HalfedgeMesh mesh;
  try {
    mesh = build_halfedge_mesh(r.polygons);
  } catch (const MeshError& e) {
    ADD_FAILURE() << "repaired polygons do not build: " << e.what();
  }
  EXPECT_TRUE(validate(mesh).ok()) << validate(mesh).summary();
  return mesh;
}

// Every spot is a live id of `mesh` (built from r.polygons) whose face corners are the polygons'; each cut's spots
// are an edge of its first face and the same edge (at the same positions, other vertices) of its second, a boundary
// edge on both sides.
void expect_spots_in(const RepairResult& r, const HalfedgeMesh& mesh) {
  ASSERT_EQ(r.report.spots.size(), r.report.changes.size());
  for (size_t i = 0; i < r.report.spots.size(); ++i) {
    const RepairSpots& s = r.report.spots[i];
    SCOPED_TRACE(r.report.changes[i]);
    for (uint32_t v : s.vertices) ASSERT_TRUE(v < mesh.vertex_capacity() && mesh.alive(VertexId(v)));
    for (uint32_t f : s.faces) {
      ASSERT_TRUE(f < mesh.face_capacity() && mesh.alive(FaceId::face(f)));
      std::vector<uint32_t> corners;
      mesh.for_each_face_halfedge(FaceId::face(f), [&](HalfedgeId h) { corners.push_back(mesh.vertex(h).index); });
      EXPECT_EQ(corners, std::vector<uint32_t>(r.polygons.face(f).begin(), r.polygons.face(f).end()));
    }
    if (r.report.changes[i].find(" was cut: ") == std::string::npos) continue;
    ASSERT_EQ(s.vertices.size(), 4u);
    ASSERT_EQ(s.faces.size(), 2u);
    for (int side = 0; side < 2; ++side) {
      const HalfedgeId h =
          edge_in_face(mesh, FaceId::face(s.faces[side]), s.vertices[2 * side], s.vertices[2 * side + 1]);
      ASSERT_TRUE(h.valid()) << "side " << side;
      EXPECT_TRUE(mesh.face(mesh.twin(h)).is_boundary()) << "side " << side;
    }
    for (int end = 0; end < 2; ++end) {
      EXPECT_NE(s.vertices[end], s.vertices[end + 2]);
      EXPECT_EQ(r.polygons.positions[s.vertices[end]], r.polygons.positions[s.vertices[end + 2]]);
    }
  }
}

long euler_characteristic(const HalfedgeMesh& m) {
  return long(m.num_vertices()) - long(m.num_edges()) + long(m.num_faces());
}

// The walk from face 0 goes round both ways and meets itself between faces 2 and 3, where the orientations it fixed
// make both use edge 6-7 the same way: cut there, the strip opens into a band of six quads (a disk, one boundary).
TEST(RepairFiles, AMoebiusStripIsCutOnceAcrossAndOpensAsAStrip) {
  const Repaired m = read_and_repair("moebius_strip.obj");
  EXPECT_EQ(m.refusal,
            "faces 0 and 5 both go from vertex 0 to vertex 1: their orientations are inconsistent (flip one of them)");
  const RepairResult& r = m.repair;
  EXPECT_EQ(r.report.changes, (Strings{"faces 3..5 reversed to agree with face 0",
                                       "the edge between vertex 6 and vertex 7 was cut: faces 2 and 3 disagree on its "
                                       "direction; it is now between vertex 6 and vertex 7 in face 2, and between new "
                                       "vertex 12 and new vertex 13 in face 3"}));
  EXPECT_EQ(r.report.summary(), "repaired: 3 faces reversed, 1 edge cut where its faces disagree");
  ASSERT_EQ(r.polygons.num_vertices(), 14u);
  EXPECT_EQ(std::vector<glm::dvec3>(r.polygons.positions.begin(), r.polygons.positions.begin() + 12), m.read.positions);
  EXPECT_EQ(r.polygons.positions[12], m.read.positions[6]);
  EXPECT_EQ(r.polygons.positions[13], m.read.positions[7]);
  // Faces 3..5 reversed (corner 0 first, then the others backwards); face 3 on new vertices 12 and 13.
  EXPECT_EQ(faces_of(r.polygons),
            (Faces{{0, 1, 3, 2}, {2, 3, 5, 4}, {4, 5, 7, 6}, {12, 8, 9, 13}, {8, 10, 11, 9}, {10, 1, 0, 11}}));
  EXPECT_EQ(r.report.spots[1].vertices, (std::vector<uint32_t>{6, 7, 12, 13}));
  EXPECT_EQ(r.report.spots[1].faces, (std::vector<uint32_t>{2, 3}));
  const HalfedgeMesh mesh = build_repaired(r);
  expect_spots_in(r, mesh);
  EXPECT_EQ(mesh.num_boundaries(), 1u);
  EXPECT_EQ(mesh.num_edges(), 19u);  // 6 x 4 sides: 5 shared, 14 on the boundary
  EXPECT_EQ(euler_characteristic(mesh), 1);
  expect_subdivides(mesh);
  EXPECT_TRUE(repair_polygons(r.polygons).report.empty());
}

// A closed one-sided surface: the walk's cuts close into a loop of six edges through vertices 4, 5, 13, 12, 20 and
// 28, each of them inner, so each is split in two (new vertices 32..37). Cut, the bottle is an annulus: orientable,
// two boundaries, Euler characteristic 0 as before.
TEST(RepairFiles, AKleinBottleIsCutAlongALoopIntoAnAnnulus) {
  const Repaired k = read_and_repair("klein_bottle.obj");
  EXPECT_EQ(k.refusal,
            "faces 0 and 23 both go from vertex 8 to vertex 0: their orientations are inconsistent (flip one of them)");
  const RepairResult& r = k.repair;
  const std::string disagree = " disagree on its direction; it is now between ";
  EXPECT_EQ(
      r.report.changes,
      (Strings{"faces 5..7, 12..15, 20..23, 28..31 reversed to agree with face 0",
               "the edge between vertex 4 and vertex 28 was cut: faces 27 and 28" + disagree +
                   "vertex 4 and vertex 28 in face 27, and between new vertex 32 and new vertex 37 in face 28",
               "the edge between vertex 20 and vertex 28 was cut: faces 19 and 20" + disagree +
                   "vertex 20 and vertex 28 in face 19, and between new vertex 36 and new vertex 37 in face 20",
               "the edge between vertex 4 and vertex 5 was cut: faces 4 and 28" + disagree +
                   "vertex 4 and vertex 5 in face 4, and between new vertex 32 and new vertex 33 in face 28",
               "the edge between vertex 5 and vertex 13 was cut: faces 4 and 5" + disagree +
                   "vertex 5 and vertex 13 in face 4, and between new vertex 33 and new vertex 35 in face 5",
               "the edge between vertex 12 and vertex 13 was cut: faces 4 and 12" + disagree +
                   "vertex 12 and vertex 13 in face 4, and between new vertex 34 and new vertex 35 in face 12",
               "the edge between vertex 12 and vertex 20 was cut: faces 11 and 12" + disagree +
                   "vertex 12 and vertex 20 in face 11, and between new vertex 34 and new vertex 36 in face 12"}));
  EXPECT_EQ(r.report.summary(), "repaired: 15 faces reversed, 6 edges cut where faces disagree");
  ASSERT_EQ(r.polygons.num_vertices(), 38u);
  const uint32_t originals[] = {4, 5, 12, 13, 20, 28};  // of new vertices 32..37
  for (uint32_t i = 0; i < 6; ++i) EXPECT_EQ(r.polygons.positions[32 + i], k.read.positions[originals[i]]);
  // The faces on the far side of the loop, on the new vertices.
  EXPECT_EQ(faces_with_new_vertices(r.polygons, 32),
            (std::map<uint32_t, std::vector<uint32_t>>{
                {5, {33, 35}}, {12, {34, 36, 35}}, {13, {35}}, {20, {36, 37}}, {28, {37, 32, 33}}, {29, {33}}}));
  EXPECT_EQ(faces_of(r.polygons)[28], (std::vector<uint32_t>{37, 32, 33, 29}));
  const HalfedgeMesh mesh = build_repaired(r);
  expect_spots_in(r, mesh);
  EXPECT_EQ(mesh.num_boundaries(), 2u);
  EXPECT_EQ(euler_characteristic(mesh), 0);
  expect_subdivides(mesh);
  EXPECT_TRUE(repair_polygons(r.polygons).report.empty());
}

// The flipped faces 6 and 7 are reversed back, and the flap is cut across where the walk meets itself: three edges
// from one side of the flap (vertex 29) to the other (vertex 34) through vertices 33 and 30 of its middle row, inner
// vertices, each split in two. What opens is the sheet with the flap as a handle cut through: a disk.
TEST(RepairFiles, AScanWithATwistedFlapIsReorientedAndCutAcrossTheFlap) {
  const Repaired s = read_and_repair("scan_with_twisted_flap.obj");
  EXPECT_EQ(s.refusal,
            "faces 4 and 6 both go from vertex 3 to vertex 8: their orientations are inconsistent (flip one of them)");
  const RepairResult& r = s.repair;
  const std::string disagree = " disagree on its direction; it is now between ";
  EXPECT_EQ(
      r.report.changes,
      (Strings{"faces 6, 7, 41, 43..47 reversed to agree with face 0",
               "the edge between vertex 30 and vertex 33 was cut: faces 40 and 43" + disagree +
                   "vertex 30 and vertex 33 in face 40, and between new vertex 36 and new vertex 37 in face 43",
               "the edge between vertex 30 and vertex 34 was cut: faces 42 and 43" + disagree +
                   "vertex 30 and vertex 34 in face 42, and between new vertex 36 and new vertex 38 in face 43",
               "the edge between vertex 29 and vertex 33 was cut: faces 40 and 41" + disagree +
                   "vertex 29 and vertex 33 in face 40, and between new vertex 35 and new vertex 37 in face 41"}));
  EXPECT_EQ(r.report.summary(), "repaired: 8 faces reversed, 3 edges cut where faces disagree");
  ASSERT_EQ(r.polygons.num_vertices(), 39u);
  const uint32_t originals[] = {29, 30, 33, 34};  // of new vertices 35..38
  for (uint32_t i = 0; i < 4; ++i) EXPECT_EQ(r.polygons.positions[35 + i], s.read.positions[originals[i]]);
  EXPECT_EQ(faces_with_new_vertices(r.polygons, 35),
            (std::map<uint32_t, std::vector<uint32_t>>{
                {41, {35, 37}}, {43, {36, 37, 38}}, {44, {37}}, {46, {37, 38}}, {47, {37}}}));
  EXPECT_EQ(faces_of(r.polygons)[43], (std::vector<uint32_t>{36, 37, 38}));
  const HalfedgeMesh mesh = build_repaired(r);
  expect_spots_in(r, mesh);
  EXPECT_EQ(mesh.num_boundaries(), 1u);
  EXPECT_EQ(euler_characteristic(mesh), 1);
  expect_subdivides(mesh);
  EXPECT_TRUE(repair_polygons(r.polygons).report.empty());
}

}  // namespace
}  // namespace meshedit
