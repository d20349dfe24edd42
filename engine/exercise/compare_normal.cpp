// compare_normal: a vertex normal against the reference's, and a mesh it must not change (see
// internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <string>
#include <vector>

#include "core/history.h"
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
    std::string first;
    if (!changes.empty()) {
      const FieldChange& c = changes.front();
      first = ": " + format_id(c.element) + "." + c.field + " was " + c.before + ", is " + c.after;
    }
    out.add("vertex_normal changed the mesh" + first + " (" + plural(changes.size(), "change", "changes") +
            "); it must only read it");
  }
  report.equal = !out.any();
  report.identical = report.equal && bitwise_equal(got, want);
  if (report.equal && !report.identical) {
    report.notes.push_back("your normal differs from the reference's by " + format_number(d) + " (rounding; accepted)");
  }
}

}  // namespace meshedit::exercise_checks
