// The patch view's drawing: the overlay over the tessellated surface (the control nets, and the (u, v) probe that
// shows the separable evaluation the course teaches: each row of the selected patch evaluated at u, then the column
// curve through those four points evaluated at v) and the ImGui panel, over a PatchViewState
// (document/patch_view_state.h).
//
// This module builds data and an ImGui panel only; the app hands the mesh to MeshRenderer and the overlay polylines
// to the renderer's overlay drawing. With the "mine" switch on (bezier_mine.h), the probe also shows the point the
// student's evaluate (scripts/student/patch.lua) gives, and how far it is from P(u, v).
//
// Invariants: the panel changes the state only through patch_view_state.h's functions and its toggles; the overlay
// is a plain function of the state (and "mine"), in the current theme's colours.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/bezier.h"
#include "document/patch_view_state.h"

namespace meshedit {

class BezierMine;
struct PatchMinePoint;

inline constexpr int kProbeCurveSamples = 32;  // segments of each sampled row and column curve

// ---- overlay geometry ------------------------------------------------------------------------------

enum class OverlayKind {
  ControlNet,     // a row or column of a 4x4 control net (4 points)
  RowCurve,       // row r of the probed patch as a curve in u (sampled)
  RowPoints,      // the four row curves evaluated at u (points only)
  ColumnPolygon,  // the control polygon of the column curve: the four row points
  ColumnLevel,    // a de Casteljau level of the column curve at v (3 points, then 2)
  ColumnCurve,    // the column curve through the row points, in v (sampled)
  SurfacePoint,   // P(u, v) (one point)
  MinePoint,      // the student's P(u, v) (one point), and the segment from it to the reference's when they differ
};

// One thing to draw over the surface, in the patches' own coordinates.
struct PatchOverlayItem {
  std::vector<glm::dvec3> points;
  glm::vec4 colour{1.0f};
  float width = 1.0f;        // line width in pixels, or point diameter when points_only
  bool points_only = false;  // draw the points as dots, no lines between them
  OverlayKind kind = OverlayKind::ControlNet;
  std::string label;  // for a legend or a tooltip: "row 2 at u", "P(u, v)"
};

// The 8 polylines of a control net: rows 0..3 (at(r, 0..3)) then columns 0..3 (at(0..3, c)), each
// labelled "<prefix>row r" / "<prefix>column c".
std::vector<PatchOverlayItem> control_net_polylines(const BezierPatch& patch, glm::vec4 colour, float width,
                                                    const std::string& label_prefix = "");

// Everything the probe shows for `patch` at (u, v) (not clamped here), in this order:
//   8 ControlNet polylines (control_net_polylines),
//   4 RowCurve polylines (samples + 1 points each, row r's curve from at(r,0) to at(r,3)),
//   1 RowPoints item (evaluate_patch_steps(patch, u, v).row_points, in row order),
//   1 ColumnPolygon polyline (the same 4 points),
//   2 ColumnLevel polylines (column_levels[1] and [2]: 3 and 2 points),
//   1 ColumnCurve polyline (samples + 1 points, from row point 0 to row point 3),
//   1 SurfacePoint item (evaluate_patch(patch, u, v)).
std::vector<PatchOverlayItem> build_probe_overlay(const BezierPatch& patch, double u, double v,
                                                  int samples = kProbeCurveSamples);

// What the renderer should draw over the surface, following the toggles:
// - show_control_net: the nets of all patches (dim), except the selected one when the probe shows it;
// - show_probe: build_probe_overlay of the selected patch at (u, v) (its net included, bright).
// - mine (when given and show_probe): the student's point, in the palette's mine colour when it is the reference's,
//   in its wrong colour with a segment to P(u, v) when not, and then P(u, v) in the reference colour (nothing when
//   the student's code failed).
// Colours are the current theme's (ui_palette()).
// Empty when there are no patches.
std::vector<PatchOverlayItem> patch_view_overlay(const PatchViewState& state, const PatchMinePoint* mine = nullptr);

// ---- ImGui -----------------------------------------------------------------------------------------

// An ImGui window (`title`): resolution slider, patch selector, u and v sliders, the toggles, the
// tessellation's numbers, and the table of the separable evaluation (row r at u -> point, then the
// column's de Casteljau levels at v -> P(u, v)). Calls update_tessellation after its controls, so the
// mesh is current for this frame's rendering. Needs a current ImGui frame; makes no GL calls. Given `mine`,
// adds the "mine" switch and, when it is on, your point, the verdict and any error (file:line).
void draw_patch_view_panel(PatchViewState& state, const char* title = "Patch view", BezierMine* mine = nullptr);
// The same contents drawn into the current window or child.
void draw_patch_view_panel_contents(PatchViewState& state, BezierMine* mine = nullptr);

}  // namespace meshedit
