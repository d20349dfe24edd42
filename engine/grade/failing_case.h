// failing_case_of: the input of a failed expect.exercise on a mesh, as a FailingCase (grade_types.h) the window can
// open in its Exercises tab: the input mesh as OBJ text and the element by the OBJ indices of its corners.
//
// Invariants:
// - Only mesh exercises have a case (none for points or a patch); the input mesh is written as to_polygon_mesh makes
//   it (live vertices renumbered densely in id order), so building the OBJ again gives vertex i at OBJ index i.
// - case_element(case_mesh(c), c) is the element failing_case_of was given.
// - Never throws for a mesh the exercise accepted: a mesh whose faces do not close gives no case (nullopt).
#pragma once

#include <optional>

#include "exercise/exercises.h"
#include "grade/grade_types.h"

namespace meshedit {

std::optional<FailingCase> failing_case_of(Exercise exercise, const ExerciseInput& input);

// The case's input mesh, built again (vertex i is v_i). Throws FileError or MeshError for a case whose text is not a
// mesh (one from another tool, or damaged).
HalfedgeMesh case_mesh(const FailingCase& failing_case);
// The case's element in that mesh: found by its corners, so it is the same element whatever ids the mesh had in the
// suite; invalid for the whole mesh, or when no element of the mesh has those corners.
ElementRef case_element(const HalfedgeMesh& mesh, const FailingCase& failing_case);

}  // namespace meshedit
