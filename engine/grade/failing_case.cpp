// The input of a failed mesh check as a case the window can open and the grader can draw (see failing_case.h).
#include "grade/failing_case.h"

#include "core/mesh_records.h"

namespace meshedit {

std::optional<FailingCase> failing_case_of(Exercise exercise, const ExerciseInput& input, const HalfedgeMesh* mine) {
  if (!is_mesh_exercise(exercise) || !input.mesh) return std::nullopt;
  FailingCase out;
  out.exercise = exercise_info(exercise).function;
  out.input = input.describe(exercise);
  out.mesh = format_mesh_records(*input.mesh);
  if (input.element.valid()) out.element = format_id(input.element);
  if (mine) out.mine = format_mesh_records(*mine);
  return out;
}

HalfedgeMesh case_mesh(const FailingCase& failing_case) {
  return parse_mesh_records(failing_case.mesh, "the test's input");
}

std::optional<HalfedgeMesh> case_mine(const FailingCase& failing_case) {
  if (failing_case.mine.empty()) return std::nullopt;
  return parse_mesh_records(failing_case.mine, "your mesh");
}

ElementRef case_element(const HalfedgeMesh& mesh, const FailingCase& failing_case) {
  const std::optional<ElementRef> element = parse_element(failing_case.element);
  if (!element || !mesh.alive(*element)) return {};
  return *element;
}

}  // namespace meshedit
