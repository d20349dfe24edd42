// Linear subdivision (see linear_subdivision.h): refine_mesh with midpoint positions, level by level.
#include "core/linear_subdivision.h"

#include "core/subdivision_refine.h"

namespace meshedit {

Check can_linear_subdivide(const HalfedgeMesh& mesh) { return can_refine(mesh, "linear subdivision"); }

Check linear_subdivide(HalfedgeMesh& mesh, int levels) {
  // Checked once: a level of an accepted mesh is valid and its faces have distinct corners, so it is accepted too.
  const Check check = can_linear_subdivide(mesh);
  if (!check) return check;
  for (int level = 0; level < levels; ++level) {
    const RefineLayout layout = plan_refinement(mesh, RefineRule::TrianglesInFour);
    mesh = refine_mesh(mesh, RefineRule::TrianglesInFour, layout, midpoint_positions(mesh, layout));
  }
  return Check::yes();
}

}  // namespace meshedit
