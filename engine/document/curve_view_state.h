// The curve view's state: a 2D Bézier curve whose control points the student drags, adds and removes, with the
// de Casteljau levels at t revealed one step at a time (E), the full curve (C), the split at t and the tangent at C(t).
// ui/curve_editor.h draws it and turns ImGui's input into the calls below.
//
// Everything the keys and the mouse do is a plain function of CurveEditorState, so it is tested without a window.
//
// Invariants kept by the functions below (not by direct writes to the fields):
// - t is finite and in [0, 1];
// - levels_shown is in [0, max(0, n-1)] for n control points (n-1 steps reach the single curve point);
// - hovered and dragged are -1 or a valid control point index; they follow their point when points are
//   inserted or removed, and become -1 when their point is removed;
// - the curve never drops below 2 control points through remove_point (a curve loaded with fewer keeps
//   them; nothing here requires 2);
// - control points stay finite: add_point and drag_point refuse NaN or infinite positions.
// The app owns the keyboard: it maps E to step_level, C to toggle_curve and M to the "mine" switch.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "core/bezier.h"

namespace meshedit {

// ---- view transform --------------------------------------------------------------------------------

// The part of the curve plane the canvas shows. Kept in the state, so dragging a point outside it does
// not move the view under the cursor; "Fit" (fit_view) recomputes it.
struct CurveRegion {
  glm::dvec2 min{0.0, 0.0};
  glm::dvec2 max{1.0, 1.0};
};

// Curve coordinates (y up) to screen pixels (y down, top-left origin) with one uniform scale.
struct CurveView {
  glm::dvec2 canvas_min{0.0, 0.0};   // top-left corner of the canvas, in screen pixels
  glm::dvec2 canvas_size{1.0, 1.0};  // in pixels
  glm::dvec2 centre{0.5, 0.5};       // the curve point drawn at the canvas centre
  double scale = 1.0;                // pixels per curve unit, > 0
};

glm::dvec2 curve_to_screen(const CurveView& view, glm::dvec2 p);
glm::dvec2 screen_to_curve(const CurveView& view, glm::dvec2 screen_point);

// The bounding box of the finite points, grown on every side by `margin` times its larger side.
// Coincident points (or a single one) get a unit-sized box around them; no finite point gives [0,1]^2.
CurveRegion fit_region(std::span<const glm::dvec2> points, double margin = 0.1);

// Shows all of `region` in the canvas, centred, keeping the aspect ratio (the larger scale that fits).
// Canvas sizes below one pixel are treated as one pixel.
CurveView view_for(const CurveRegion& region, glm::dvec2 canvas_min, glm::dvec2 canvas_size);

// ---- state -----------------------------------------------------------------------------------------

inline constexpr double kCurveScrollStep = 0.01;  // t change per scroll notch (the course's value)
inline constexpr double kCurvePickRadius = 10.0;  // pixels around a control point that grab it
inline constexpr int kCurveSamples = 200;         // segments of the full curve (the course steps t by 0.005)

struct CurveEditorState {
  BezierCurve curve;
  double t = 0.5;
  int levels_shown = 0;              // de Casteljau steps drawn: 0 = control polygon only, n-1 = down to C(t)
  bool show_curve = false;           // C; the course viewer also starts without the curve
  bool show_split = false;           // both halves of the curve cut at t
  bool show_tangent = false;         // the arrow C'(t) / n from C(t): the last step's segment, moved to start at C(t)
  int hovered = -1;                  // control point under the mouse
  int dragged = -1;                  // control point being moved
  glm::dvec2 drag_offset{0.0, 0.0};  // point minus mouse (curve units) when the drag began: no jump
  CurveRegion region;                // the curve-plane rectangle the canvas shows
  CurveView view;                    // the transform of the last drawn frame; hit tests use it
  // A left press on the canvas away from every control point (curve coordinates): set by handle_canvas_input, taken
  // (and reset) by whoever answers clicks on the curve (the app: a lesson's pick on the curve).
  std::optional<glm::dvec2> clicked;
};

// A cubic that shows off the construction (its levels do not overlap at t = 0.5).
BezierCurve default_curve();

// A state showing `curve` (an empty curve is replaced by default_curve(): there would be nothing to
// show or drag), with the region fitted to its control points.
CurveEditorState make_curve_editor(BezierCurve curve);

// ---- what the keys and buttons do ------------------------------------------------------------------

// E: one more de Casteljau level, back to 0 after the last (levels_shown = (levels_shown + 1) % n).
void step_level(CurveEditorState& state);
// levels_shown kept inside [0, max(0, n-1)] whatever was written to it directly: the last level drawn.
int shown_level(const CurveEditorState& state);
// C.
void toggle_curve(CurveEditorState& state);
void toggle_split(CurveEditorState& state);
void toggle_tangent(CurveEditorState& state);
// Clamps to [0, 1]; NaN leaves t unchanged.
void set_t(CurveEditorState& state, double t);
// Scroll wheel: t += kCurveScrollStep * offset, clamped. Unlike the course viewer this works at every
// level (t also moves the split and the table).
void scroll_t(CurveEditorState& state, double offset);
// Refits the region to the control points.
void fit_view(CurveEditorState& state);

// Inserts a control point at `position` (curve coordinates) and returns its index, or -1 if the
// position is not finite. Where it goes: next to the nearest part of the control polygon, so a click
// beside a segment bends that segment and the curve keeps its overall order:
// - with fewer than 2 points, it is appended;
// - otherwise find the polygon segment (p_i, p_i+1) nearest to `position` (the lowest i on ties). If
//   the nearest polygon point is the first control point itself, the new point is prepended (index 0);
//   if it is the last control point, appended (index n); otherwise inserted between p_i and p_i+1
//   (index i+1).
int add_point(CurveEditorState& state, glm::dvec2 position);
// The "Add point" button: the midpoint of the last polygon segment (so it is inserted at index n-1
// and the curve changes little), or near the only point. Returns the new index.
int add_point_default(CurveEditorState& state);
// Removes control point `index`. Refused (returns false, nothing changes) for a bad index or when only
// 2 points are left. levels_shown is clamped to the new n-1.
bool remove_point(CurveEditorState& state, int index);
// Moves control point `index` to `position` (curve coordinates); false for a bad index or position.
bool drag_point(CurveEditorState& state, int index, glm::dvec2 position);

// The control point within `radius` pixels of `screen_point` under state.view, nearest first; on a tie
// the highest index (it is drawn on top). -1 if none.
int hit_test(const CurveEditorState& state, glm::dvec2 screen_point, double radius = kCurvePickRadius);

// ---- what is drawn ---------------------------------------------------------------------------------

// Every de Casteljau level at t: levels[0] = control points, ..., levels[n-1] = {C(t)}.
std::vector<std::vector<glm::dvec2>> all_levels(const CurveEditorState& state);
// The levels drawn: levels[0 .. levels_shown].
std::vector<std::vector<glm::dvec2>> shown_levels(const CurveEditorState& state);
// The two halves' control points at t (split_curve of the control points).
CurveSplit<glm::dvec2> split_halves(const CurveEditorState& state);
// segments + 1 curve points at t = i / segments (segments >= 1); empty for no control points.
std::vector<glm::dvec2> sample_curve(std::span<const glm::dvec2> points, int segments = kCurveSamples);

// ---- mouse -----------------------------------------------------------------------------------------

// One frame of mouse input over the canvas, in screen pixels (the window fills it from ImGui).
struct CanvasInput {
  glm::dvec2 mouse{0.0, 0.0};
  bool hovered = false;              // the mouse is over the canvas and nothing else holds it
  bool left_pressed = false;         // left button went down this frame
  bool left_down = false;            // left button is held
  bool left_double_clicked = false;  // second press of a double click (left_pressed is true too)
  bool right_pressed = false;
  double wheel = 0.0;  // scroll notches, positive away from the user
};

// Applies one frame of input:
// - a drag in progress follows the mouse while the left button is held (even off the canvas), keeping
//   the offset it started with, and ends when it is released;
// - over the canvas: a double click on empty canvas adds a point there (add_point); a left press on a
//   point starts dragging it, elsewhere it sets `clicked`; a right press on a point removes it (remove_point); the
//   wheel moves t.
// hovered is updated to the point under the mouse (the dragged point while dragging).
void handle_canvas_input(CurveEditorState& state, const CanvasInput& input);

}  // namespace meshedit
