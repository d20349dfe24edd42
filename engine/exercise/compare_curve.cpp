// compare_curve: one de Casteljau step against the reference's (see internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <algorithm>
#include <string>

#include "core/translation.h"

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
          tr("the weights are swapped: point i of the step must be (1 - t) * p_i + t * p_(i+1), and yours are "
             "t * p_i + (1 - t) * p_(i+1)"));
    }
  }
  const std::string expected = std::to_string(want.size());
  const MessageParts counts = {
      {"count", std::to_string(got.size())}, {"expected", expected}, {"first", std::to_string(got.size() + 1)}};
  if (got.size() < want.size()) {
    const size_t missing = want.size() - got.size();
    if (prefix_matches && missing == 1) {
      out.add(
          tr_format("point {expected} of the step is missing (got {count} points, expected {expected}): n points "
                    "give n - 1, so the loop runs i = 1, ..., n - 1",
                    counts));
    } else if (prefix_matches) {
      out.add(tr_format(
          "points {first} to {expected} of the step are missing (got {count} points, expected {expected})", counts));
    } else {
      out.add(tr_format("the step has {count} points, expected {expected} (n points give n - 1)", counts));
    }
  } else if (got.size() > want.size()) {
    out.add(got.size() == input.points.size()
                ? tr_format("the step has {count} points, expected {expected}: one step turns n points into n - 1 "
                            "(yours has as many as it was given)",
                            counts)
                : tr_format("the step has {count} points, expected {expected}: one step turns n points into n - 1",
                            counts));
  }
  double worst = 0.0;
  for (size_t i = 0; i < common; ++i) {
    const double d = glm::distance(got[i], want[i]);
    worst = std::max(worst, d);
    if (!(d <= tolerance)) {
      out.add(tr_format("point {number} is {position}, expected {expected}", {{"number", std::to_string(i + 1)},
                                                                              {"position", position_text(got[i])},
                                                                              {"expected", position_text(want[i])}}));
    }
  }
  report.equal = !out.any();
  report.identical =
      report.equal && got.size() == want.size() && std::equal(got.begin(), got.end(), want.begin(), bitwise_equal);
  if (report.equal && !report.identical) {
    report.notes.push_back(
        tr_format("your points differ from the reference's by at most {distance} (rounding; accepted)",
                  {{"distance", format_number(worst)}}));
  }
}

}  // namespace meshedit::exercise_checks
