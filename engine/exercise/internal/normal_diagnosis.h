// What to tell a student whose vertex normal is wrong: the recipe it is made of (normal_recipes.h), named with the
// faces it leaves out, counts alone or turns inwards, and what the course asks for instead (every real face's cross
// product, summed, then normalised; boundary loops skipped with f:is_boundary()). Part of the normals comparison
// (exercise_compare.cpp), so the window, the lessons and the grader say it alike.
//
//   explain_vertex_normal(mesh, v, yours, reference)
//     -> "your normal (0.1, 0.2, 0.97) leaves out f3, one of the 4 faces around v0; the reference (...) adds ..."
//
// Invariants:
// - "" when yours is within 1e-9 of the reference (the comparison's tolerance), else one sentence: the recipe's
//   (one choice changed: its own words; two: the recipe described and one fix per choice), the nearest recipe's
//   hedged with its angle, or, when no recipe explains yours, how far it is from the reference.
// - Faces are named with format_id ("f3", a boundary loop "b0"), positions with format_position, lengths and
//   distances with format_number.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit {

std::string explain_vertex_normal(const HalfedgeMesh& mesh, VertexId v, const glm::dvec3& yours,
                                  const glm::dvec3& reference);

}  // namespace meshedit
