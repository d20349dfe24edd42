// de Casteljau's algorithm for curves and separable patch evaluation (contracts in bezier.h).
//
// Every evaluation path goes through `lerp_step`, so the pyramid a lesson shows, the curve point, the
// split halves and the tessellated surface agree bit for bit.
#include "core/bezier.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace meshedit {
namespace {

template <class Point>
Point lerp_step(const Point& a, const Point& b, double t) {
  return (1.0 - t) * a + t * b;
}

template <class Point>
std::vector<Point> step_impl(std::span<const Point> points, double t) {
  std::vector<Point> out;
  if (points.size() < 2) return out;
  out.reserve(points.size() - 1);
  for (size_t i = 0; i + 1 < points.size(); ++i) out.push_back(lerp_step(points[i], points[i + 1], t));
  return out;
}

template <class Point>
std::vector<std::vector<Point>> levels_impl(std::span<const Point> points, double t) {
  std::vector<std::vector<Point>> levels;
  if (points.empty()) return levels;
  levels.reserve(points.size());
  levels.emplace_back(points.begin(), points.end());
  while (levels.back().size() > 1) levels.push_back(step_impl<Point>(levels.back(), t));
  return levels;
}

// In place on a copy: no pyramid allocation, same arithmetic as levels_impl.
template <class Point>
Point evaluate_impl(std::span<const Point> points, double t) {
  if (points.empty()) return Point(std::numeric_limits<double>::quiet_NaN());
  std::vector<Point> work(points.begin(), points.end());
  for (size_t n = work.size(); n > 1; --n) {
    for (size_t i = 0; i + 1 < n; ++i) work[i] = lerp_step(work[i], work[i + 1], t);
  }
  return work[0];
}

template <class Point>
CurveSplit<Point> split_impl(std::span<const Point> points, double t) {
  CurveSplit<Point> halves;
  const auto levels = levels_impl(points, t);
  const size_t n = levels.size();
  halves.left.reserve(n);
  halves.right.reserve(n);
  for (size_t k = 0; k < n; ++k) {
    halves.left.push_back(levels[k].front());
    halves.right.push_back(levels[n - 1 - k].back());
  }
  return halves;
}

// One cubic, fixed size: the step order of step_impl, without the heap.
glm::dvec3 evaluate_cubic(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3,
                          double t) {
  const glm::dvec3 a0 = lerp_step(p0, p1, t), a1 = lerp_step(p1, p2, t), a2 = lerp_step(p2, p3, t);
  const glm::dvec3 b0 = lerp_step(a0, a1, t), b1 = lerp_step(a1, a2, t);
  return lerp_step(b0, b1, t);
}

std::array<glm::dvec3, 4> rows_at(const BezierPatch& patch, double u) {
  std::array<glm::dvec3, 4> rows;
  for (int r = 0; r < 4; ++r) {
    rows[r] = evaluate_cubic(patch.at(r, 0), patch.at(r, 1), patch.at(r, 2), patch.at(r, 3), u);
  }
  return rows;
}

}  // namespace

std::vector<glm::dvec2> de_casteljau_step(std::span<const glm::dvec2> points, double t) { return step_impl(points, t); }
std::vector<glm::dvec3> de_casteljau_step(std::span<const glm::dvec3> points, double t) { return step_impl(points, t); }

std::vector<std::vector<glm::dvec2>> de_casteljau_levels(std::span<const glm::dvec2> points, double t) {
  return levels_impl(points, t);
}
std::vector<std::vector<glm::dvec3>> de_casteljau_levels(std::span<const glm::dvec3> points, double t) {
  return levels_impl(points, t);
}

glm::dvec2 evaluate_curve(std::span<const glm::dvec2> points, double t) { return evaluate_impl(points, t); }
glm::dvec3 evaluate_curve(std::span<const glm::dvec3> points, double t) { return evaluate_impl(points, t); }

CurveSplit<glm::dvec2> split_curve(std::span<const glm::dvec2> points, double t) { return split_impl(points, t); }
CurveSplit<glm::dvec3> split_curve(std::span<const glm::dvec3> points, double t) { return split_impl(points, t); }

glm::dvec2 curve_derivative(std::span<const glm::dvec2> points, double t) {
  if (points.size() < 2) return glm::dvec2(0.0);
  const std::vector<std::vector<glm::dvec2>> levels = de_casteljau_levels(points, t);
  const std::vector<glm::dvec2>& last_pair = levels[levels.size() - 2];
  return static_cast<double>(points.size() - 1) * (last_pair[1] - last_pair[0]);
}

CurveNearest nearest_on_curve(std::span<const glm::dvec2> points, glm::dvec2 target) {
  CurveNearest nearest;
  if (points.empty()) {
    nearest.point = glm::dvec2(std::numeric_limits<double>::quiet_NaN());
    nearest.distance = std::numeric_limits<double>::infinity();
    return nearest;
  }
  const auto distance_at = [&](double t) { return glm::length(evaluate_curve(points, t) - target); };
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kNearestSamples; ++i) {
    const double d = distance_at(static_cast<double>(i) / kNearestSamples);
    if (d < best_distance) best = i, best_distance = d;
  }
  // Golden-section search between the best sample's neighbours, where the distance has one minimum.
  double low = std::max(0, best - 1) / static_cast<double>(kNearestSamples);
  double high = std::min(kNearestSamples, best + 1) / static_cast<double>(kNearestSamples);
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 60 && high - low > 1e-12; ++i) {
    const double a = high - ratio * (high - low), b = low + ratio * (high - low);
    if (distance_at(a) <= distance_at(b)) high = b;
    else low = a;
  }
  nearest.t = (low + high) / 2.0;
  if (distance_at(nearest.t) > best_distance) nearest.t = static_cast<double>(best) / kNearestSamples;
  nearest.point = evaluate_curve(points, nearest.t);
  nearest.distance = glm::length(nearest.point - target);
  return nearest;
}

PatchEvaluation evaluate_patch_steps(const BezierPatch& patch, double u, double v) {
  PatchEvaluation result;
  result.row_points = rows_at(patch, u);
  result.column_levels = levels_impl<glm::dvec3>(result.row_points, v);
  result.point = result.column_levels.back().front();
  return result;
}

glm::dvec3 evaluate_patch(const BezierPatch& patch, double u, double v) {
  const auto rows = rows_at(patch, u);
  return evaluate_cubic(rows[0], rows[1], rows[2], rows[3], v);
}

}  // namespace meshedit
