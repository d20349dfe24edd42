// Bézier curves and tensor-product patches by de Casteljau's algorithm, with every intermediate level
// kept so lessons and the curve view can show each step.
//
// Conventions:
// - One de Casteljau step maps n points to n-1: p'_i = (1-t) p_i + t p_{i+1}.
// - A patch holds 4x4 control points row-major: points[row * 4 + col]. Rows are curves in u; the four
//   row results form a curve in v (the CS184 order: each row at u, then the column at v).
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

}  // namespace meshedit
