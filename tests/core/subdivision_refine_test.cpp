// refine_mesh builds the children's connectivity itself; it must give exactly what build_halfedge_mesh gives for the
// same polygons (ids, pointers, positions, liveness, and the vouch for all-triangle results), for both rules, on
// closed meshes, meshes with boundaries, mixed polygons and meshes with dead slots.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/subdivision_refine.h"
#include "core/validate.h"

namespace meshedit {
namespace {

PolygonMesh pyramid_and_pentagon() {
  PolygonMesh m;
  m.add_vertex({-1, -1, 0});
  m.add_vertex({1, -1, 0});
  m.add_vertex({1, 1, 0});
  m.add_vertex({-1, 1, 0});
  m.add_vertex({0, 0, 2});
  m.add_vertex({0, -3, 0});
  m.add_vertex({2, -2, 0});
  m.add_face({0, 3, 2, 1});  // the base, open below along the pentagon's side
  m.add_face({0, 1, 4});
  m.add_face({1, 2, 4});
  m.add_face({2, 3, 4});
  m.add_face({3, 0, 4});
  return m;
}

PolygonMesh lone_hexagon() {
  PolygonMesh m;
  for (int i = 0; i < 6; ++i) m.add_vertex({std::cos(i * 1.0471975511965976), std::sin(i * 1.0471975511965976), 0.0});
  m.add_face({0, 1, 2, 3, 4, 5});
  return m;
}

void expect_refined_as_built(const HalfedgeMesh& mesh, const std::string& name) {
  for (RefineRule rule : {RefineRule::Quads, RefineRule::TrianglesInFour}) {
    SCOPED_TRACE(name + (rule == RefineRule::Quads ? ", quads" : ", triangles in four"));
    ASSERT_TRUE(can_refine(mesh, "test"));
    const RefineLayout layout = plan_refinement(mesh, rule);
    const std::vector<glm::dvec3> positions = midpoint_positions(mesh, layout);
    const HalfedgeMesh refined = refine_mesh(mesh, rule, layout, positions);
    const HalfedgeMesh built = build_halfedge_mesh(refined_polygons(mesh, rule, layout, positions));
    EXPECT_TRUE(refined.same_as(built));
    EXPECT_EQ(refined.proven_valid_triangles(), built.proven_valid_triangles());
    EXPECT_TRUE(validate(refined).ok()) << validate(refined).summary();
    EXPECT_EQ(refined.num_boundaries(), mesh.num_boundaries());
  }
}

TEST(SubdivisionRefine, DirectBuildEqualsTheBuilder) {
  expect_refined_as_built(build_halfedge_mesh(make_cube_quads()), "cube of quads");
  expect_refined_as_built(build_halfedge_mesh(make_icosahedron()), "icosahedron");
  expect_refined_as_built(build_halfedge_mesh(make_grid(3, 2)), "grid");
  expect_refined_as_built(build_halfedge_mesh(make_fan(7)), "fan");
  expect_refined_as_built(build_halfedge_mesh(pyramid_and_pentagon()), "open pyramid");
  expect_refined_as_built(build_halfedge_mesh(lone_hexagon()), "hexagon");
  HalfedgeMesh collapsed = build_halfedge_mesh(make_torus(8, 6));
  ASSERT_TRUE(collapse(collapsed, EdgeId(5)).ok());
  ASSERT_TRUE(collapse(collapsed, EdgeId(40)).ok());
  expect_refined_as_built(collapsed, "torus with dead slots");
}

// All triangles in, all triangles out: vouched like a built mesh. Quads out: not vouched.
TEST(SubdivisionRefine, VouchesForTrianglesOnly) {
  const HalfedgeMesh ico = build_halfedge_mesh(make_icosahedron());
  const RefineLayout four = plan_refinement(ico, RefineRule::TrianglesInFour);
  EXPECT_TRUE(
      refine_mesh(ico, RefineRule::TrianglesInFour, four, midpoint_positions(ico, four)).proven_valid_triangles());
  const RefineLayout quads = plan_refinement(ico, RefineRule::Quads);
  EXPECT_FALSE(refine_mesh(ico, RefineRule::Quads, quads, midpoint_positions(ico, quads)).proven_valid_triangles());
}

TEST(SubdivisionRefine, RefusesAnInvalidMesh) {
  HalfedgeMesh broken = build_halfedge_mesh(make_cube_quads());
  broken.set_twin(HalfedgeId(0), HalfedgeId(0));
  const Check refused = can_refine(broken, "Catmull-Clark subdivision");
  EXPECT_FALSE(refused);
  EXPECT_EQ(refused.reason.rfind("Catmull-Clark subdivision needs a valid mesh (", 0), 0u) << refused.reason;
}

}  // namespace
}  // namespace meshedit
