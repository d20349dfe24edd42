// Bézier curves and patches for scripts: the `meshedit.curve` / `meshedit.patch` userdata, every de Casteljau
// level for lessons, and loading the course's .bzc and .bez files.
//
// Lua API (points are vec3, see vec3_bindings.h; plain {x, y, z} tables are accepted as input; 2D curves
// have z = 0):
//   meshedit.curve(points) -> curve           1 to kMaxCurvePoints control points
//   c:evaluate(t) -> vec3                      the curve point
//   c:levels(t) -> { {vec3...}, ... }          [k + 1] = level k: [1] = level 0, the control points, as the curve
//                                              view numbers them; the last entry is the single point
//   c:step(points, t) -> {vec3...}             one de Casteljau step of any list of points (n -> n-1)
//   c:split(t) -> left, right                  two curves, each with as many points as c
//   c.points -> {vec3...}   #c -> number of control points   tostring(c) -> "curve (4 points)"
//   meshedit.patch(points16) -> patch          16 control points, row-major (points[row * 4 + col + 1])
//   p:evaluate(u, v) -> vec3                   rows at u, then the column at v (the course's order)
//   p:rows(u) -> {vec3 x 4}                    each row evaluated at u
//   p:evaluation(u, v) -> {rows = {vec3 x 4}, column_levels = {{4}, {3}, {2}, {1}}, point = vec3}
//   p.points -> {vec3 x 16}   tostring(p) -> "patch"
//   meshedit.load_curve(path) -> curve         a .bzc file (io/bzc_io.h)
//   meshedit.load_patches(path) -> {patch...}  a .bez file (io/bez_io.h)
//
// Invariants:
// - Curves and patches are immutable values: every read (c.points, levels...) returns fresh tables, so a
//   script changing them never changes the curve. Results are the core's (core/bezier.h) bit for bit.
// - Errors are Lua's "bad argument" messages naming the argument and, for lists, the 1-based position of the
//   offending point: "bad argument #1 to 'curve' (point 3 must be a vec3 or a table {x, y, z} of
//   numbers, got string)". File errors carry the file name and line (FileError's text).
// - The number of control points of a curve is capped so that levels() (n(n+1)/2 points) stays small.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "core/bezier.h"

struct lua_State;

namespace meshedit {

inline constexpr size_t kMaxCurvePoints = 1024;

// Adds curve, patch, load_curve and load_patches to the table at the top of the stack (the meshedit module)
// and registers the metatables. Calling it again on the same state is harmless.
void open_bezier_bindings(lua_State* L);

// Pushes a curve userdata holding a copy of the points (at most kMaxCurvePoints; more raise a Lua error).
void push_curve(lua_State* L, const std::vector<glm::dvec3>& points);
// The control points of the curve userdata at `index`, or nullptr if it is not a curve.
const std::vector<glm::dvec3>* to_curve(lua_State* L, int index);

// Pushes a patch userdata holding a copy of the patch.
void push_patch(lua_State* L, const BezierPatch& patch);
// The patch userdata at `index`, or nullptr if it is not a patch.
const BezierPatch* to_patch(lua_State* L, int index);

}  // namespace meshedit
