// Linear subdivision (see linear_subdivision.h): refine_mesh with midpoint positions, level by level.
#include "core/linear_subdivision.h"

#include "core/subdivision_refine.h"

namespace meshedit {

Check can_linear_subdivide(const HalfedgeMesh& mesh) { return can_refine(mesh, "linear subdivision"); }

OpResult<LinearState> linear_compute_points(const HalfedgeMesh& mesh) {
  OpResult<LinearState> result;
  result.check = can_linear_subdivide(mesh);
  if (!result.check) return result;
  result.value.layout = plan_refinement(mesh, RefineRule::TrianglesInFour);
  result.value.position = midpoint_positions(mesh, result.value.layout);
  return result;
}

void linear_refine(HalfedgeMesh& mesh, const LinearState& state) {
  mesh.replace_with(refine_mesh(mesh, RefineRule::TrianglesInFour, state.layout, state.position));
}

Check linear_subdivide(HalfedgeMesh& mesh, int levels) {
  // Checked once: a level of an accepted mesh is valid and its faces have distinct corners, so it is accepted too.
  const Check check = can_linear_subdivide(mesh);
  if (!check) return check;
  for (int level = 0; level < levels; ++level) {
    const RefineLayout layout = plan_refinement(mesh, RefineRule::TrianglesInFour);
    mesh.replace_with(refine_mesh(mesh, RefineRule::TrianglesInFour, layout, midpoint_positions(mesh, layout)));
  }
  return Check::yes();
}

}  // namespace meshedit
