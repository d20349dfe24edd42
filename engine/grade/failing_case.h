// failing_case_of: the input of a failed expect.exercise on a mesh, as a FailingCase (grade_types.h) the window can
// open in its Exercises tab and the grader can draw: the input mesh and the student's mesh with every record kept, so
// both read back with the ids the grader's words name.
//
// Invariants:
// - Only mesh exercises have a case (none for points or a patch).
// - case_mesh(failing_case_of(e, input)) has the input mesh's records exactly, and case_element names the element
//   the student's function was given there.
#pragma once

#include <optional>

#include "exercise/exercises.h"
#include "grade/grade_types.h"

namespace meshedit {

// `mine` is the student's mesh after the call (nullptr: none).
std::optional<FailingCase> failing_case_of(Exercise exercise, const ExerciseInput& input,
                                           const HalfedgeMesh* mine = nullptr);

// The case's input mesh and the student's (nullopt when the case has none). Throw MeshError for a text that is not
// mesh records (from another tool, or damaged).
HalfedgeMesh case_mesh(const FailingCase& failing_case);
std::optional<HalfedgeMesh> case_mine(const FailingCase& failing_case);
// The case's element in that mesh; invalid for the whole mesh, or when the mesh has no such live element.
ElementRef case_element(const HalfedgeMesh& mesh, const FailingCase& failing_case);

}  // namespace meshedit
