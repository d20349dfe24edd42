// compare_patch: a Bézier patch point against the reference's (see internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include "core/bezier.h"
#include "core/translation.h"

namespace meshedit::exercise_checks {

void compare_patch(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const glm::dvec3 got = report.mine.points[0];
  const glm::dvec3 want = report.reference.points[0];
  const double tolerance = points_tolerance(input.patch.points);
  const double d = glm::distance(got, want);
  if (!(d <= tolerance)) {
    const glm::dvec3 transposed = evaluate_patch(input.patch, input.v, input.u);
    const MessageParts parts = {{"point", position_text(got)},
                                {"expected", position_text(want)},
                                {"u", format_number(input.u)},
                                {"v", format_number(input.v)},
                                {"distance", format_number(d)}};
    if (within(got, transposed, tolerance) && !within(transposed, want, tolerance)) {
      out.add(
          tr_format("your point {point} is the surface point at (u, v) = ({v}, {u}), not ({u}, {v}): u and v are "
                    "swapped. Evaluate each row at u, then the column of the four row results at v",
                    parts));
    } else {
      out.add(
          tr_format("your point {point} is not the surface point {expected} at (u, v) = ({u}, {v}); it is "
                    "{distance} away",
                    parts));
    }
  }
  report.equal = !out.any();
  report.identical = report.equal && bitwise_equal(got, want);
  if (report.equal && !report.identical) {
    report.notes.push_back(tr_format("your point differs from the reference's by {distance} (rounding; accepted)",
                                     {{"distance", format_number(d)}}));
  }
}

}  // namespace meshedit::exercise_checks
