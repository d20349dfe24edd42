// Building half-edge meshes from polygons: exact ids and pointers, boundaries, and every refusal.
#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

TEST(MeshBuild, TetrahedronCounts) {
  const HalfedgeMesh m = build_halfedge_mesh(make_tetrahedron());
  EXPECT_EQ(m.num_vertices(), 4u);
  EXPECT_EQ(m.num_edges(), 6u);
  EXPECT_EQ(m.num_faces(), 4u);
  EXPECT_EQ(m.num_halfedges(), 12u);
  EXPECT_EQ(m.num_boundaries(), 0u);
}

}  // namespace
}  // namespace meshedit
