// The lesson globals that show things which follow the view, and read it: live text, plots in the panel, arrows in
// the scene, the curve view's t and control points, and the patch view's probe.
//
// Lua API:
//   live(function() return "t = " .. string.format("%.2f", curve_t()) end)
//       a text block whose text is the function's value (tostring, then the markdown of say()), evaluated now and
//       again every frame by the runner (LessonRunner::refresh_live)
//   plot { title = "Bernstein weights", x = {0, 1}, y = {0, 1} (optional: the samples' range), samples = 100,
//          curves = { {label = "B0", fn = function(t) ... end, colour = "blue"}, ... },
//          marker = function() return curve_t() end }
//       a picture in the panel: each fn sampled once, now, at samples + 1 equally spaced x; marker (optional) is read
//       every frame like a live block, and its x (nil: none) is drawn as a vertical line
//   arrow(from, to [, colour])   an arrow over the mesh view, from and to points ({x, y, z} or vec3), cleared with the
//                                step's other marks (default colour: the last-edit colour)
//   curve_t()      -> the curve view's t, or nil when the curve view is not on screen
//   curve_points() -> the curve view's control points as vec3 (z = 0), as the student left them, or nil
//   patch_uv()     -> u, v, i: the patch view's probe and the probed patch's index in the shown list (from 1), or nil
//                     when the patch view is not on screen
//
// Invariants:
// - A live function or a marker runs in phase Live: it may read (selection, current_mesh, curve_t, curve_points,
//   patch_uv) but
//   not change anything (say, show, highlight, wait_for... are errors naming the call).
// - An error in a live function or a marker is kept with its block as "lesson.lua:LINE: message" (the place live() or
//   plot{} was called when the message has none) and stops that block for the rest of the step; the step goes on. A
//   live value that is not text is shown as tostring gives it.
// - A plot's curves must give a finite number at every sample; anything else is a Lua error at plot{}'s line naming
//   the curve and the x. Bad fields (unknown names, x not two increasing numbers, no curves) are errors there too.
#pragma once

#include "lesson/internal/lesson_api.h"

namespace meshedit {

// Defines live, plot, arrow, curve_t, curve_points and patch_uv in `runtime`, bound to `script`.
void open_lesson_displays(LuaRuntime& runtime, LessonScript& script);

// Evaluates `live` (or the marker of `plot`) on thread L in phase Live, setting its text (marker) or its error. Raises
// nothing: the function's errors are caught and kept; only a runtime that is out of budget stops it.
void evaluate_live(lua_State* L, LessonScript& script, LessonLive& live);
void evaluate_marker(lua_State* L, LessonScript& script, LessonPlot& plot);

}  // namespace meshedit
