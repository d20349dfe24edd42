// How the window opens a mesh file, for the tests of files from other programs: built as read, or, when the
// half-edge builder refuses (a MeshError), built from the repaired copy (File > Open a repaired copy); and the
// subdivisions every opened file must then survive.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/catmull_clark.h"
#include "core/halfedge_mesh.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/triangulate.h"
#include "core/validate.h"
#include "io/mesh_file.h"

namespace meshedit::testing {

// The half-edge mesh the window shows for a file. `repaired` says whether it took the repaired copy; `refusal` keeps
// the builder's message, `report` the repair's.
struct Opened {
  HalfedgeMesh mesh;
  bool repaired = false;
  std::string refusal;
  RepairReport report;
};

inline Opened open_as_the_window_does(const std::filesystem::path& path) {
  const PolygonMesh polygons = load_mesh(path);
  Opened opened;
  try {
    opened.mesh = build_halfedge_mesh(polygons);
  } catch (const MeshError& e) {
    opened.refusal = e.what();
    RepairResult repaired = repair_polygons(polygons);
    opened.report = repaired.report;
    opened.mesh = build_halfedge_mesh(repaired.polygons);
    opened.repaired = true;
  }
  return opened;
}

// Triangulated, Loop subdivides with the counts V + E, 4F; Catmull-Clark takes the mesh as it is (any polygons)
// with V + E + F vertices; each result validates.
inline void expect_subdivides(const HalfedgeMesh& mesh) {
  HalfedgeMesh triangles = mesh;
  ASSERT_TRUE(triangulate_mesh(triangles).check.ok);
  HalfedgeMesh loop = triangles;
  ASSERT_TRUE(loop_subdivide(loop).ok);
  EXPECT_EQ(loop.num_vertices(), triangles.num_vertices() + triangles.num_edges());
  EXPECT_EQ(loop.num_faces(), 4 * triangles.num_faces());
  EXPECT_TRUE(validate(loop).ok());
  HalfedgeMesh cc = mesh;
  ASSERT_TRUE(catmull_clark_subdivide(cc).ok);
  EXPECT_EQ(cc.num_vertices(), mesh.num_vertices() + mesh.num_edges() + mesh.num_faces());
  EXPECT_TRUE(validate(cc).ok());
}

}  // namespace meshedit::testing
