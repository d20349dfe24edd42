// plot_value (see lesson_blocks.h).
#include "lesson/lesson_blocks.h"

#include <algorithm>

namespace meshedit {

std::optional<double> plot_value(const LessonPlotCurve& curve, double x) {
  const std::vector<glm::dvec2>& p = curve.points;
  if (p.empty()) return std::nullopt;
  if (x <= p.front().x) return p.front().y;
  if (x >= p.back().x) return p.back().y;
  const auto after = std::upper_bound(p.begin(), p.end(), x, [](double v, const glm::dvec2& q) { return v < q.x; });
  const glm::dvec2 b = *after, a = *(after - 1);
  const double s = b.x > a.x ? (x - a.x) / (b.x - a.x) : 0.0;
  return a.y + s * (b.y - a.y);
}

}  // namespace meshedit
