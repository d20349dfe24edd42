// add_arrow (see arrow_overlay.h).
#include "render/arrow_overlay.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace meshedit {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A unit vector perpendicular to unit `d`.
glm::dvec3 any_perpendicular(const glm::dvec3& d) {
  const glm::dvec3 axis = std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(d, axis));
}

}  // namespace

void add_arrow(Overlay& overlay, const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& eye, glm::vec4 colour,
               float width) {
  const glm::dvec3 shaft = to - from;
  const double length = glm::length(shaft);
  if (!finite(from) || !finite(to) || !(length > 0.0) || !std::isfinite(length)) return;
  const glm::dvec3 d = shaft / length;
  glm::dvec3 side = glm::cross(d, eye - to);
  const double side_length = glm::length(side);
  side = side_length > 1e-12 * glm::length(eye - to) && side_length > 0.0 ? side / side_length : any_perpendicular(d);
  const double head = kArrowHeadFraction * length;
  const glm::dvec3 base = to - d * head;
  overlay.lines.push_back({{from, base}, colour, width, false});
  const glm::dvec3 half = side * (0.5 * kArrowHeadWidth * head);
  overlay.lines.push_back({{to, base + half, base - half}, colour, width, true});
}

}  // namespace meshedit
