// The builder's fast path against its checked path (build_detail, mesh_build_fast.h): the same mesh, id for id,
// on closed meshes, boundaries, polygons, unused vertices and the big torus; and the fast path stepping aside
// (returning false) for every kind of bad input, so the checked path can name the problem.
#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_build_fast.h"
#include "core/mesh_error.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

PolygonMesh with_faces(std::vector<glm::dvec3> positions, const std::vector<std::vector<uint32_t>>& faces) {
  PolygonMesh p;
  p.positions = std::move(positions);
  for (const auto& f : faces) p.add_face(f);
  return p;
}

std::vector<glm::dvec3> points(size_t n) {
  std::vector<glm::dvec3> out;
  for (size_t i = 0; i < n; ++i) out.emplace_back(double(i), double(i * i % 7), double(i % 3));
  return out;
}

::testing::AssertionResult paths_agree(const PolygonMesh& p) {
  HalfedgeMesh fast;
  size_t unused = 99;
  if (!build_detail::build_fast(p, fast, unused)) return ::testing::AssertionFailure() << "the fast path stepped aside";
  BuildReport report;
  const HalfedgeMesh checked = build_detail::build_checked(p, &report);
  if (unused != report.unused_vertices) return ::testing::AssertionFailure() << "unused " << unused;
  if (!fast.same_as(checked)) return ::testing::AssertionFailure() << "the meshes differ";
  if (fast.num_vertices() != checked.num_vertices() || fast.num_halfedges() != checked.num_halfedges() ||
      fast.num_edges() != checked.num_edges() || fast.num_faces() != checked.num_faces() ||
      fast.num_boundaries() != checked.num_boundaries()) {
    return ::testing::AssertionFailure() << "the live counts differ";
  }
  return ::testing::AssertionSuccess();
}

TEST(MeshBuildFast, SameMeshAsTheCheckedBuild) {
  for (const PolygonMesh& p : {make_tetrahedron(), make_cube(), make_cube_quads(), make_icosahedron(), make_grid(5, 3),
                               make_fan(12), make_torus(9, 7), make_torus_with_faces(20000)}) {
    EXPECT_TRUE(paths_agree(p));
  }
}

TEST(MeshBuildFast, TwoHolesMixedPolygonsAndAnUnusedVertex) {
  // A 3x1 strip of quads and triangles with vertex 8 unused, and a square annulus (two boundary loops).
  EXPECT_TRUE(paths_agree(with_faces(points(9), {{0, 1, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7, 6}})));
  const PolygonMesh annulus = with_faces(points(8), {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
  EXPECT_TRUE(paths_agree(annulus));
  EXPECT_EQ(build_halfedge_mesh(annulus).num_boundaries(), 2u);
  // A vertex of high valence (sorted with std::sort rather than insertion sort).
  EXPECT_TRUE(paths_agree(make_fan(40)));
}

TEST(MeshBuildFast, StepsAsideForEveryBadInputAndTheCheckedPathNamesIt) {
  const std::vector<PolygonMesh> bad = {
      with_faces(points(3), {{0, 1}}),                           // too few corners
      with_faces(points(3), {{0, 1, 1}}),                        // repeated corner
      with_faces(points(3), {{0, 1, 7}}),                        // out of range
      with_faces(points(4), {{0, 1, 2}, {0, 1, 3}}),             // same direction: inconsistent
      with_faces(points(5), {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}),  // three faces on one edge
      with_faces(points(3), {{0, 1, 2}, {0, 2, 1}}),             // repeated face
      with_faces(points(5), {{0, 1, 2}, {0, 3, 4}}),             // bow-tie at vertex 0
      with_faces(points(4), {{0, 1, 2, 3}, {0, 3, 2, 1}}),       // repeated quad
      // two closed tetrahedra sharing vertex 0: every edge has its twin, but 0 has two fans
      with_faces(points(7), {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}}),
      // a repeated triangle glued inside a bigger mesh (the torus's first face, reversed, on top of it)
      [] {
        PolygonMesh p = make_torus(6, 5);
        p.add_face({p.indices[0], p.indices[2], p.indices[1]});
        return p;
      }(),
  };
  for (const PolygonMesh& p : bad) {
    HalfedgeMesh fast;
    size_t unused = 0;
    EXPECT_FALSE(build_detail::build_fast(p, fast, unused));
    EXPECT_THROW(build_halfedge_mesh(p), MeshError);
  }
}

}  // namespace
}  // namespace meshedit
