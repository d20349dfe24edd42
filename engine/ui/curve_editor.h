// The curve view's window: the controls, the canvas (ImDrawList only, no GL) and the table of every level's points,
// over a CurveEditorState (document/curve_view_state.h, where everything the keys and the mouse do is a plain
// function of the state). The drawing only turns ImGui's input into those functions and draws.
//
// Invariants: the drawing changes the state only through curve_view_state.h's functions (and `view`, the transform
// of the frame drawn), so what the tests prove about those functions is what the window does. With "mine" on
// (bezier_mine.h), the levels drawn are the student's evaluate_step's, the first one that is not the reference's in
// the palette's "wrong" colour over the reference's.
#pragma once

#include <string>

#include <imgui.h>

#include "document/curve_view_state.h"

namespace meshedit {

class BezierMine;
struct CurveMineLevels;

// An ImGui window (`title`) with the controls (step, curve, split, fit, add/remove, the t slider, and the
// "mine" switch when `mine` is given), the canvas and the table of every level's points. Place and size it
// with SetNextWindowPos/Size before calling. Needs a current ImGui context inside NewFrame/Render; makes no GL
// calls. With mine->curve_on(), runs the student's code through mine->curve_levels once per frame.
void draw_curve_editor(CurveEditorState& state, const char* title = "Curve editor", BezierMine* mine = nullptr);
// The same contents drawn into the current window or child (for embedding).
void draw_curve_editor_contents(CurveEditorState& state, BezierMine* mine = nullptr);
// Its three parts, for a window that places them apart (the app: the canvas in the view, the rest beside it).
// The canvas computes the frame's levels (running the student's code when "mine" is on): draw it before the levels.
void draw_curve_controls(CurveEditorState& state, BezierMine* mine = nullptr);  // the buttons and the t slider
void draw_curve_canvas(CurveEditorState& state, ImVec2 size, BezierMine* mine = nullptr);
void draw_curve_levels(CurveEditorState& state, BezierMine* mine = nullptr);  // the table of every level's points
// The canvas as a picture (a write-up's figure): what draw_curve_canvas draws, into `dl` at p0 (framebuffer pixels)
// with the region fitted to `size`, the levels `yours` (the student's, computed before; nullptr: the reference's)
// named as coming from `file`, and no key hints. Reads no input and runs no Lua.
void draw_curve_picture(ImDrawList* dl, CurveEditorState& state, ImVec2 p0, ImVec2 size, const CurveMineLevels* yours,
                        const std::string& file);

}  // namespace meshedit
