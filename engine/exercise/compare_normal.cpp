// compare_normal: a vertex normal against the reference's, and a mesh it must not change (see
// internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <string>
#include <vector>

#include "core/history.h"
#include "core/translation.h"
#include "exercise/internal/normal_diagnosis.h"

namespace meshedit::exercise_checks {

// A wrong normal is explained by what it is made of (normal_diagnosis.h); the mesh must not change.
void compare_normal(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const glm::dvec3 got = report.mine.points[0];
  const glm::dvec3 want = report.reference.points[0];
  const HalfedgeMesh& mesh = *input.mesh;
  const double d = glm::distance(got, want);
  if (std::string wrong = explain_vertex_normal(mesh, VertexId(input.element.index), got, want); !wrong.empty()) {
    out.add(std::move(wrong));
  }
  if (report.mine.mesh && !report.mine.mesh->same_as(mesh)) {
    const std::vector<FieldChange> changes = diff(mesh, *report.mine.mesh);
    MessageParts parts = {{"count", std::to_string(changes.size())}};
    if (changes.empty()) {
      out.add(tr_format("vertex_normal changed the mesh ({count} changes); it must only read it", parts));
    } else {
      const FieldChange& c = changes.front();
      parts.emplace_back(
          "change",
          tr_format("{element}.{field} was {before}, is {after}",
                    {{"element", format_id(c.element)}, {"field", c.field}, {"before", c.before}, {"after", c.after}}));
      out.add(
          changes.size() == 1
              ? tr_format("vertex_normal changed the mesh: {change} ({count} change); it must only read it", parts)
              : tr_format("vertex_normal changed the mesh: {change} ({count} changes); it must only read it", parts));
    }
  }
  report.equal = !out.any();
  report.identical = report.equal && bitwise_equal(got, want);
  if (report.equal && !report.identical) {
    report.notes.push_back(tr_format("your normal differs from the reference's by {distance} (rounding; accepted)",
                                     {{"distance", format_number(d)}}));
  }
}

}  // namespace meshedit::exercise_checks
