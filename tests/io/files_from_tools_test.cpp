// Files written by the programs students bring meshes from (tests/data/from_tools/README.md: Blender's .obj, .ply,
// .stl and .glb exporters, a scan's defects in a Blender PLY, an OpenSCAD part): each opens as the window opens it,
// plainly or after at most one repair, with the file's own first position, and then triangulates, subdivides (Loop
// and Catmull-Clark) and validates.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/triangulate.h"
#include "core/validate.h"
#include "io/mesh_file.h"
#include "support/test_support.h"
#include "window_open.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::expect_subdivides;
using testing::open_as_the_window_does;
using testing::Opened;

fs::path from_tools(const std::string& name) { return testing::source_dir() / "tests" / "data" / "from_tools" / name; }

TEST(FilesFromTools, BlendersSuzanneObjOpensAsExportedAndSubdivides) {
  const Opened suzanne = open_as_the_window_does(testing::source_dir() / "assets" / "suzanne.obj");
  EXPECT_FALSE(suzanne.repaired) << suzanne.refusal;
  EXPECT_EQ(suzanne.mesh.num_vertices(), 507u);
  EXPECT_EQ(suzanne.mesh.num_edges(), 1005u);
  EXPECT_EQ(suzanne.mesh.num_faces(), 500u);
  EXPECT_EQ(suzanne.mesh.num_boundaries(), 4u);  // each eye is a bowl apart from the head, which has a hole for it
  EXPECT_EQ(suzanne.mesh.position(VertexId(0)), glm::dvec3(0.4375, 0.164062, 0.765625));  // the file's first v
  EXPECT_TRUE(validate(suzanne.mesh).ok());
  HalfedgeMesh triangles = suzanne.mesh;
  EXPECT_EQ(triangulate_mesh(triangles).value.polygons_split, 468u);
  EXPECT_EQ(triangles.num_faces(), 968u);
  expect_subdivides(suzanne.mesh);
}

// Blender's PLY repeats a vertex wherever its texture coordinate changes, and STL stores corners: read, each vertex
// is joined to the others at its position, which also joins two of the eyes' rim vertices to the head's (the OBJ
// keeps them apart at the same place), making two bow-ties that one repair splits again. What opens is the OBJ's
// Suzanne: the same positions, boundaries and counts. Blender's PLY and STL exporters keep its own axes (Z up) where
// its OBJ exporter turns them (Y up): Blender's (x, y, z) is the .obj's (x, z, -y), rounded there to six decimals.
TEST(FilesFromTools, BlendersPlyAndStlOfSuzanneOpenRepairedAsTheObjsSuzanne) {
  const HalfedgeMesh obj = build_halfedge_mesh(load_mesh(testing::source_dir() / "assets" / "suzanne.obj"));
  // The vertices each file holds, and those left once joined (STL's corners are joined by its reader).
  const std::pair<const char*, std::pair<size_t, size_t>> files[] = {{"suzanne.ply", {556, 505}},
                                                                     {"suzanne.stl", {505, 505}}};
  for (const auto& [name, vertices] : files) {
    SCOPED_TRACE(name);
    const LoadedFile file = load_file(from_tools(name));
    EXPECT_EQ(file.mesh.num_vertices(), vertices.second);
    EXPECT_EQ(file.joined_vertices, vertices.first - vertices.second);
    const Opened opened = open_as_the_window_does(from_tools(name));
    ASSERT_TRUE(opened.repaired);
    EXPECT_EQ(opened.report.split_vertices, 2u) << opened.report.summary();
    EXPECT_EQ(opened.mesh.num_vertices(), obj.num_vertices());
    EXPECT_EQ(opened.mesh.num_boundaries(), obj.num_boundaries());
    EXPECT_TRUE(validate(opened.mesh).ok());
    for (VertexId v : opened.mesh.vertices()) {
      const glm::dvec3 p = opened.mesh.position(v);
      bool found = false;
      for (VertexId w : obj.vertices()) {
        const glm::dvec3 q = obj.position(w);
        found = found || glm::length(glm::dvec3(q.x, -q.z, q.y) - p) < 1e-6;
      }
      ASSERT_TRUE(found) << "v" << v.index << " is at no vertex of the .obj";
    }
    expect_subdivides(opened.mesh);
  }
}

// Blender's glTF of a flat-shaded mesh repeats every vertex for each face around it (7872 vertices for 3936
// triangles); joined by position, the subdivided Suzanne is one surface again (her eyes apart), with no repair.
TEST(FilesFromTools, BlendersGltfOfASubdividedSuzanneOpensJoinedIntoOneSurface) {
  const LoadedFile file = load_file(from_tools("suzanne_subsurf.glb"));
  EXPECT_EQ(file.joined_vertices, 5860u);
  const Opened opened = open_as_the_window_does(from_tools("suzanne_subsurf.glb"));
  EXPECT_FALSE(opened.repaired) << opened.refusal;
  EXPECT_EQ(opened.mesh.num_vertices(), 2012u);
  EXPECT_EQ(opened.mesh.num_faces(), 3936u);
  EXPECT_EQ(opened.mesh.num_boundaries(), 4u);  // as the .obj's: each eye's rim and the head's hole for it
  EXPECT_TRUE(validate(opened.mesh).ok());
  expect_subdivides(opened.mesh);
}

TEST(FilesFromTools, AScanWithAHoleAndABowTieOpensRepairedAndSubdivides) {
  const Opened scan = open_as_the_window_does(from_tools("scan_sphere.ply"));
  ASSERT_TRUE(scan.repaired);
  EXPECT_NE(scan.refusal.find("bow-tie"), std::string::npos) << scan.refusal;
  EXPECT_NE(scan.report.summary().find("bow-tie"), std::string::npos) << scan.report.summary();
  EXPECT_GE(scan.mesh.num_boundaries(), 2u);  // the cap's hole and the faces missing around the bow-tie
  EXPECT_TRUE(validate(scan.mesh).ok());
  expect_subdivides(scan.mesh);
}

TEST(FilesFromTools, AnOpenScadPartOpensAfterAtMostOneRepairAndSubdivides) {
  const Opened part = open_as_the_window_does(from_tools("bracket.stl"));
  EXPECT_TRUE(validate(part.mesh).ok());
  EXPECT_EQ(part.mesh.num_boundaries(), 0u);  // a closed solid
  expect_subdivides(part.mesh);
}

}  // namespace
}  // namespace meshedit
