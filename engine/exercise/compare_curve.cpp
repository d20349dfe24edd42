// compare_curve: one de Casteljau step against the reference's (see internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <algorithm>
#include <string>

namespace meshedit::exercise_checks {

void compare_curve(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const auto& got = report.mine.points;
  const auto& want = report.reference.points;
  const double tolerance = points_tolerance(input.points);
  const size_t common = std::min(got.size(), want.size());
  bool prefix_matches = true;
  for (size_t i = 0; i < common; ++i) prefix_matches = prefix_matches && within(got[i], want[i], tolerance);

  // Swapped weights: t p_i + (1 - t) p_(i+1).
  if (got.size() == want.size() && !prefix_matches) {
    bool swapped = true;
    for (size_t i = 0; i < got.size(); ++i) {
      const glm::dvec3 other = input.t * input.points[i] + (1.0 - input.t) * input.points[i + 1];
      swapped = swapped && within(got[i], other, tolerance);
    }
    if (swapped) {
      out.add(
          "the weights are swapped: point i of the step must be (1 - t) * p_i + t * p_(i+1), and yours are "
          "t * p_i + (1 - t) * p_(i+1)");
    }
  }
  const std::string expected = std::to_string(want.size());
  if (got.size() < want.size()) {
    const size_t missing = want.size() - got.size();
    if (prefix_matches && missing == 1) {
      out.add("point " + expected + " of the step is missing (got " + std::to_string(got.size()) +
              " points, expected " + expected + "): n points give n - 1, so the loop runs i = 1, ..., n - 1");
    } else if (prefix_matches) {
      out.add("points " + std::to_string(got.size() + 1) + " to " + expected + " of the step are missing (got " +
              std::to_string(got.size()) + " points, expected " + expected + ")");
    } else {
      out.add("the step has " + std::to_string(got.size()) + " points, expected " + expected +
              " (n points give n - 1)");
    }
  } else if (got.size() > want.size()) {
    out.add("the step has " + std::to_string(got.size()) + " points, expected " + expected +
            ": one step turns n points into n - 1" +
            (got.size() == input.points.size() ? " (yours has as many as it was given)" : ""));
  }
  double worst = 0.0;
  for (size_t i = 0; i < common; ++i) {
    const double d = glm::distance(got[i], want[i]);
    worst = std::max(worst, d);
    if (!(d <= tolerance)) {
      out.add("point " + std::to_string(i + 1) + " is " + position_text(got[i]) + ", expected " +
              position_text(want[i]));
    }
  }
  report.equal = !out.any();
  report.identical =
      report.equal && got.size() == want.size() && std::equal(got.begin(), got.end(), want.begin(), bitwise_equal);
  if (report.equal && !report.identical) {
    report.notes.push_back("your points differ from the reference's by at most " + format_number(worst) +
                           " (rounding; accepted)");
  }
}

}  // namespace meshedit::exercise_checks
