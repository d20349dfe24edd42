// The overlays of a flip, split or collapse at a moment of its animation (see edit_animation.h).
#include "render/edit_animation.h"

namespace meshedit {
namespace {

// t within [0, 1]; NaN (a broken frame time) as 0.
double clamp01(double t) { return t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0; }

glm::dvec3 lerp(const glm::dvec3& from, const glm::dvec3& to, double p) { return from + (to - from) * p; }

// Adds the segment from `start` to `end`, unless it has no length to see.
void add_line(Overlay& overlay, const glm::dvec3& start, const glm::dvec3& end, const EditAnimationLook& look) {
  if (start == end) return;
  overlay.lines.push_back({{start, end}, look.colour, look.line_width, false});
}

void add_point(Overlay& overlay, const glm::dvec3& at, float size, const EditAnimationLook& look) {
  if (size <= 0.0f) return;
  overlay.points.push_back({at, look.colour, size});
}

void draw(Overlay& overlay, const FlipMotion& flip, double p, const EditAnimationLook& look) {
  const glm::dvec3 from_a = lerp(flip.a, flip.d, p), from_b = lerp(flip.b, flip.c, p);
  add_line(overlay, from_a, from_b, look);
  add_point(overlay, from_a, look.point_size, look);
  add_point(overlay, from_b, look.point_size, look);
}

void draw(Overlay& overlay, const SplitMotion& split, double p, const EditAnimationLook& look) {
  if (p <= 0.0) return;  // before the split there is only the edge, which the mesh draws
  const glm::dvec3 m = lerp((split.a + split.b) * 0.5, split.m, p);
  for (const glm::dvec3& end : split.new_edge_ends) add_line(overlay, m, lerp(m, end, p), look);
  add_point(overlay, m, float(p) * look.point_size, look);
}

void draw(Overlay& overlay, const CollapseMotion& collapse, double p, const EditAnimationLook& look) {
  const glm::dvec3 a = lerp(collapse.a, collapse.meet, p), b = lerp(collapse.b, collapse.meet, p);
  for (const glm::dvec3& end : collapse.a_neighbours) add_line(overlay, a, end, look);
  for (const glm::dvec3& end : collapse.b_neighbours) add_line(overlay, b, end, look);
  add_line(overlay, a, b, look);
  add_point(overlay, a, look.point_size, look);
  if (b != a) add_point(overlay, b, look.point_size, look);
}

}  // namespace

double ease_in_out(double t) {
  t = clamp01(t);
  return t * t * (3.0 - 2.0 * t);
}

double operation_progress(double t, PlayDirection direction) {
  t = clamp01(t);
  return ease_in_out(direction == PlayDirection::Forward ? t : 1.0 - t);
}

Overlay edit_overlay(const EditMotion& motion, double progress, const EditAnimationLook& look) {
  const double p = clamp01(progress);
  Overlay overlay;
  overlay.on_top = true;
  std::visit([&](const auto& m) { draw(overlay, m, p, look); }, motion);
  return overlay;
}

Overlay edit_animation_frame(const EditAnimation& animation, double t, const EditAnimationLook& look) {
  return edit_overlay(animation.motion, operation_progress(t, animation.direction), look);
}

}  // namespace meshedit
