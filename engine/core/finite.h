// finite(p): true when every coordinate of a position is a finite number (no NaN, no infinity). The one test the
// core, io and render use before trusting a position (validation, drawing, comparisons, vouching a mesh valid).
#pragma once

#include <cmath>

#include <glm/vec3.hpp>

namespace meshedit {

inline bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace meshedit
