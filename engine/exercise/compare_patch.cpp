// compare_patch: a Bézier patch point against the reference's (see internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include "core/bezier.h"

namespace meshedit::exercise_checks {

void compare_patch(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const glm::dvec3 got = report.mine.points[0];
  const glm::dvec3 want = report.reference.points[0];
  const double tolerance = points_tolerance(input.patch.points);
  const double d = glm::distance(got, want);
  if (!(d <= tolerance)) {
    const glm::dvec3 transposed = evaluate_patch(input.patch, input.v, input.u);
    if (within(got, transposed, tolerance) && !within(transposed, want, tolerance)) {
      out.add("your point " + position_text(got) + " is the surface point at (u, v) = (" + format_number(input.v) +
              ", " + format_number(input.u) + "), not (" + format_number(input.u) + ", " + format_number(input.v) +
              "): u and v are swapped. Evaluate each row at u, then the column of the four row results at v");
    } else {
      out.add("your point " + position_text(got) + " is not the surface point " + position_text(want) +
              " at (u, v) = (" + format_number(input.u) + ", " + format_number(input.v) + "); it is " +
              format_number(d) + " away");
    }
  }
  report.equal = !out.any();
  report.identical = report.equal && bitwise_equal(got, want);
  if (report.equal && !report.identical) {
    report.notes.push_back("your point differs from the reference's by " + format_number(d) + " (rounding; accepted)");
  }
}

}  // namespace meshedit::exercise_checks
