// Bézier curves and tensor-product patches by de Casteljau's algorithm, with every intermediate level
// kept so lessons and the curve view can show each step.
//
// Conventions:
// - One de Casteljau step maps n points to n-1: p'_i = (1-t) p_i + t p_{i+1}, computed exactly in that
//   form (so t = 0 and t = 1 reproduce control points bit for bit when they are finite).
// - A patch holds 4x4 control points row-major: points[row * 4 + col]. Rows are curves in u; the four
//   row results form a curve in v (the CS184 order: each row at u, then the column at v).
// - Nothing here throws or asserts: an empty curve evaluates to a NaN point, and NaN or infinite input
//   (control points or parameters) only propagates into NaN or infinite output.
// - t outside [0, 1] is allowed and extrapolates the same polynomial.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/polygon_mesh.h"

namespace meshedit {

struct BezierCurve {
  std::vector<glm::dvec2> control_points;
};

struct BezierPatch {
  std::array<glm::dvec3, 16> points{};
  const glm::dvec3& at(int row, int col) const { return points[row * 4 + col]; }
  glm::dvec3& at(int row, int col) { return points[row * 4 + col]; }
};

// ---- curves (2D for the curve editor, 3D for patch rows and columns) ---------------------------------

// One de Casteljau step: n points become n-1 (empty for n <= 1).
std::vector<glm::dvec2> de_casteljau_step(std::span<const glm::dvec2> points, double t);
std::vector<glm::dvec3> de_casteljau_step(std::span<const glm::dvec3> points, double t);

// Every level of the pyramid: levels[0] is a copy of `points`, levels[k] has n-k points (k steps), and
// the last level holds the single curve point. n levels for n points; no levels for an empty input.
std::vector<std::vector<glm::dvec2>> de_casteljau_levels(std::span<const glm::dvec2> points, double t);
std::vector<std::vector<glm::dvec3>> de_casteljau_levels(std::span<const glm::dvec3> points, double t);

// The curve point at t (the last level). A single control point is returned as is; an empty list gives
// a point whose coordinates are quiet NaN.
glm::dvec2 evaluate_curve(std::span<const glm::dvec2> points, double t);
glm::dvec3 evaluate_curve(std::span<const glm::dvec3> points, double t);
inline glm::dvec2 evaluate_curve(const BezierCurve& curve, double t) { return evaluate_curve(curve.control_points, t); }

// The two halves of a curve cut at t, each with as many control points as the curve:
// - left[k]  = levels[k].front()                  (left[0] = first control point, left.back() = C(t))
// - right[k] = levels[n-1-k].back()               (right[0] = C(t), right.back() = last control point)
// So left(s) = C(t s) and right(s) = C(t + (1-t) s) for s in [0, 1]: both keep the curve's direction.
// An empty curve gives two empty halves.
template <class Point>
struct CurveSplit {
  std::vector<Point> left;
  std::vector<Point> right;
};
CurveSplit<glm::dvec2> split_curve(std::span<const glm::dvec2> points, double t);
CurveSplit<glm::dvec3> split_curve(std::span<const glm::dvec3> points, double t);

// C'(t): the degree n times the difference of the two points of the next-to-last level (so the last step's segment
// is C'(t) / n, the tangent at C(t)). Zero for fewer than 2 control points.
glm::dvec2 curve_derivative(std::span<const glm::dvec2> points, double t);

// The point of the curve for t in [0, 1] nearest to `target`: its t, the point and the distance to it. The curve is
// sampled at kNearestSamples + 1 values of t and the nearest sample refined between its neighbours, so the answer is
// the true nearest point unless two parts of the curve pass within a sample's length of each other. An empty curve
// gives t = 0, a NaN point and an infinite distance.
struct CurveNearest {
  double t = 0.0;
  glm::dvec2 point{0.0};
  double distance = 0.0;
};
inline constexpr int kNearestSamples = 256;
CurveNearest nearest_on_curve(std::span<const glm::dvec2> points, glm::dvec2 target);

// ---- patches -------------------------------------------------------------------------------------

// What separable evaluation passes through, for drawing the intermediate points:
// - row_points[r]: row r of the patch (points[r*4 .. r*4+3]) evaluated at u;
// - column_levels: the de Casteljau levels of row_points at v (4, 3, 2 and 1 points;
//   column_levels[0] equals row_points);
// - point: the surface point, column_levels.back()[0].
struct PatchEvaluation {
  std::array<glm::dvec3, 4> row_points{};
  std::vector<std::vector<glm::dvec3>> column_levels;
  glm::dvec3 point{};
};
PatchEvaluation evaluate_patch_steps(const BezierPatch& patch, double u, double v);

// The surface point at (u, v); bit-identical to evaluate_patch_steps(patch, u, v).point.
// Corners: (0,0) -> at(0,0), (1,0) -> at(0,3), (0,1) -> at(3,0), (1,1) -> at(3,3).
glm::dvec3 evaluate_patch(const BezierPatch& patch, double u, double v);

}  // namespace meshedit
