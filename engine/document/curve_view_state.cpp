// The curve view's state changes, all pure: see curve_view_state.h.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers          finite, point_count, closest_parameter
//   view transform   curve_to_screen, screen_to_curve, fit_region, view_for
//   state            the pure state changes: step_level, set_t, add_point, remove_point, drag_point, hit_test
//   what is drawn    all_levels, shown_levels, split_halves, sample_curve
//   mouse            handle_canvas_input
#include "document/curve_view_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace meshedit {

namespace {

// ---- helpers ---------------------------------------------------------------------------------------

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

int point_count(const CurveEditorState& state) { return static_cast<int>(state.curve.control_points.size()); }

// Closest parameter on segment [a, b] to p, in [0, 1]; 0 for a degenerate segment.
double closest_parameter(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const glm::dvec2 d = b - a;
  const double len2 = glm::dot(d, d);
  if (!(len2 > 0.0)) return 0.0;
  return std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0);
}

}  // namespace

// ---- view transform --------------------------------------------------------------------------------

glm::dvec2 curve_to_screen(const CurveView& view, glm::dvec2 p) {
  const glm::dvec2 mid = view.canvas_min + 0.5 * view.canvas_size;
  return {mid.x + (p.x - view.centre.x) * view.scale, mid.y - (p.y - view.centre.y) * view.scale};
}

glm::dvec2 screen_to_curve(const CurveView& view, glm::dvec2 s) {
  const glm::dvec2 mid = view.canvas_min + 0.5 * view.canvas_size;
  return {view.centre.x + (s.x - mid.x) / view.scale, view.centre.y - (s.y - mid.y) / view.scale};
}

CurveRegion fit_region(std::span<const glm::dvec2> points, double margin) {
  glm::dvec2 lo(std::numeric_limits<double>::infinity());
  glm::dvec2 hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec2& p : points) {
    if (!finite(p)) continue;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (!(lo.x <= hi.x)) return CurveRegion{};  // no finite point
  double size = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(size > 0.0)) {
    // Coincident points: a unit box around them, so the view has a scale at all.
    const glm::dvec2 mid = 0.5 * (lo + hi);
    return CurveRegion{mid - glm::dvec2(0.5), mid + glm::dvec2(0.5)};
  }
  const double pad = std::max(margin, 0.0) * size;
  return CurveRegion{lo - glm::dvec2(pad), hi + glm::dvec2(pad)};
}

CurveView view_for(const CurveRegion& region, glm::dvec2 canvas_min, glm::dvec2 canvas_size) {
  CurveView view;
  view.canvas_min = canvas_min;
  view.canvas_size = glm::max(canvas_size, glm::dvec2(1.0));
  view.centre = 0.5 * (region.min + region.max);
  const glm::dvec2 extent = region.max - region.min;
  const double sx = extent.x > 0.0 ? view.canvas_size.x / extent.x : std::numeric_limits<double>::infinity();
  const double sy = extent.y > 0.0 ? view.canvas_size.y / extent.y : std::numeric_limits<double>::infinity();
  const double scale = std::min(sx, sy);
  view.scale = std::isfinite(scale) && scale > 0.0 ? scale : 1.0;
  return view;
}

// ---- state -----------------------------------------------------------------------------------------

BezierCurve default_curve() { return BezierCurve{{{0.1, 0.2}, {0.25, 0.8}, {0.75, 0.85}, {0.9, 0.3}}}; }

CurveEditorState make_curve_editor(BezierCurve curve) {
  CurveEditorState state;
  state.curve = curve.control_points.empty() ? default_curve() : std::move(curve);
  fit_view(state);
  return state;
}

void step_level(CurveEditorState& state) {
  const int n = point_count(state);
  state.levels_shown = n > 0 ? (shown_level(state) + 1) % n : 0;
}

int shown_level(const CurveEditorState& state) {
  return std::clamp(state.levels_shown, 0, std::max(0, point_count(state) - 1));
}

void toggle_curve(CurveEditorState& state) { state.show_curve = !state.show_curve; }

void toggle_split(CurveEditorState& state) { state.show_split = !state.show_split; }

void toggle_tangent(CurveEditorState& state) { state.show_tangent = !state.show_tangent; }

void set_t(CurveEditorState& state, double t) {
  if (std::isnan(t)) return;
  state.t = std::clamp(t, 0.0, 1.0);
}

void scroll_t(CurveEditorState& state, double offset) { set_t(state, state.t + kCurveScrollStep * offset); }

void fit_view(CurveEditorState& state) {
  state.region = fit_region(state.curve.control_points);
  state.view = view_for(state.region, state.view.canvas_min, state.view.canvas_size);
}

int add_point(CurveEditorState& state, glm::dvec2 position) {
  if (!finite(position)) return -1;
  auto& points = state.curve.control_points;
  const int n = point_count(state);
  int index = n;
  if (n >= 2) {
    int best = 0;
    double best_s = 0.0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i + 1 < n; ++i) {
      const double s = closest_parameter(points[i], points[i + 1], position);
      const glm::dvec2 q = points[i] + s * (points[i + 1] - points[i]);
      const double d2 = glm::dot(position - q, position - q);
      if (d2 < best_d2) {
        best = i;
        best_s = s;
        best_d2 = d2;
      }
    }
    if (best == 0 && best_s == 0.0) {
      index = 0;
    } else if (best == n - 2 && best_s == 1.0) {
      index = n;
    } else {
      index = best + 1;
    }
  }
  points.insert(points.begin() + index, position);
  if (state.hovered >= index) ++state.hovered;
  if (state.dragged >= index) ++state.dragged;
  return index;
}

int add_point_default(CurveEditorState& state) {
  const auto& points = state.curve.control_points;
  if (points.empty()) return add_point(state, glm::dvec2(0.5));
  if (points.size() == 1) return add_point(state, points[0] + glm::dvec2(0.1, 0.0));
  return add_point(state, 0.5 * (points[points.size() - 2] + points.back()));
}

bool remove_point(CurveEditorState& state, int index) {
  const int n = point_count(state);
  if (index < 0 || index >= n || n <= 2) return false;
  state.curve.control_points.erase(state.curve.control_points.begin() + index);
  const auto follow = [index](int& i) {
    if (i == index) {
      i = -1;
    } else if (i > index) {
      --i;
    }
  };
  follow(state.hovered);
  follow(state.dragged);
  state.levels_shown = shown_level(state);
  return true;
}

bool drag_point(CurveEditorState& state, int index, glm::dvec2 position) {
  if (index < 0 || index >= point_count(state) || !finite(position)) return false;
  state.curve.control_points[index] = position;
  return true;
}

int hit_test(const CurveEditorState& state, glm::dvec2 screen_point, double radius) {
  int best = -1;
  double best_d2 = radius * radius;
  for (int i = 0; i < point_count(state); ++i) {
    const glm::dvec2 d = curve_to_screen(state.view, state.curve.control_points[i]) - screen_point;
    const double d2 = glm::dot(d, d);
    if (d2 <= best_d2) {  // `<=`: a later (drawn on top) point wins a tie
      best = i;
      best_d2 = d2;
    }
  }
  return best;
}

// ---- what is drawn ---------------------------------------------------------------------------------

std::vector<std::vector<glm::dvec2>> all_levels(const CurveEditorState& state) {
  return de_casteljau_levels(state.curve.control_points, state.t);
}

std::vector<std::vector<glm::dvec2>> shown_levels(const CurveEditorState& state) {
  auto levels = all_levels(state);
  const size_t keep = static_cast<size_t>(shown_level(state)) + 1;
  if (levels.size() > keep) levels.resize(keep);
  return levels;
}

CurveSplit<glm::dvec2> split_halves(const CurveEditorState& state) {
  return split_curve(state.curve.control_points, state.t);
}

std::vector<glm::dvec2> sample_curve(std::span<const glm::dvec2> points, int segments) {
  std::vector<glm::dvec2> samples;
  if (points.empty()) return samples;
  segments = std::max(segments, 1);
  samples.reserve(static_cast<size_t>(segments) + 1);
  for (int i = 0; i <= segments; ++i) samples.push_back(evaluate_curve(points, static_cast<double>(i) / segments));
  return samples;
}

// ---- mouse -----------------------------------------------------------------------------------------

void handle_canvas_input(CurveEditorState& state, const CanvasInput& input) {
  if (state.dragged >= point_count(state)) state.dragged = -1;
  if (state.dragged >= 0) {
    if (input.left_down) {
      drag_point(state, state.dragged, screen_to_curve(state.view, input.mouse) + state.drag_offset);
      state.hovered = state.dragged;
      return;
    }
    state.dragged = -1;
  }
  if (!input.hovered) {
    state.hovered = -1;
    return;
  }
  int hit = hit_test(state, input.mouse);
  if (input.left_double_clicked && hit < 0) {
    hit = add_point(state, screen_to_curve(state.view, input.mouse));
  } else if (input.left_pressed && hit >= 0) {
    state.dragged = hit;
    state.drag_offset = state.curve.control_points[hit] - screen_to_curve(state.view, input.mouse);
  } else if (input.left_pressed && !input.left_double_clicked) {
    state.clicked = screen_to_curve(state.view, input.mouse);
  } else if (input.right_pressed && hit >= 0) {
    if (remove_point(state, hit)) hit = -1;
  }
  if (input.wheel != 0.0) scroll_t(state, input.wheel);
  state.hovered = hit;
}

}  // namespace meshedit
