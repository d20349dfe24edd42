// An arrow as overlay lines (overlay_renderer.h): a shaft from its foot to its tip and a closed triangular head, the
// head turned to face the eye so it reads as an arrow from any side. Lessons draw normals and directions with it.
//
// Invariants: the head is a fifth of the arrow's length and 0.6 times as wide as it is long, in the plane that holds
// the arrow and faces the eye as well as it can; looking straight along the arrow, the head lies across any direction
// perpendicular to it. A zero-length or non-finite arrow adds nothing.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/overlay_renderer.h"

namespace meshedit {

inline constexpr double kArrowHeadFraction = 0.2;
inline constexpr double kArrowHeadWidth = 0.6;  // the head's width over its length

// Adds the arrow's shaft and head to `overlay.lines` (two polylines, `width` pixels wide).
void add_arrow(Overlay& overlay, const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& eye, glm::vec4 colour,
               float width);

}  // namespace meshedit
