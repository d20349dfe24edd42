-- Part 2: Bézier patches: a 4x4 grid of control points, evaluated as four curves in u (the rows) and then
-- one curve in v (the column through the row points); then the Utah teapot, 32 such patches. Numbers come
-- from the project's Bézier code (meshedit.patch, p:evaluation), and the teapot from assets/teapot.bez,
-- found next to this file with lesson_file(). CI runs it headless:
--   meshedit lesson lessons/2_bezier_patches.lua --headless --answers tests/script/lessons/2_bezier_patches_answers.lua

lesson {
  title = "Bézier patches and the teapot",
  summary = "From curves to surfaces: sixteen control points, rows in u then a column in v, and the teapot.",
}

-- A gentle hill over [0, 3] x [0, 3]: row r (0..3) at y = r, column c at x = c; the middle four points raised.
local hill_points = {}
for r = 0, 3 do
  for c = 0, 3 do
    local raised = (r == 1 or r == 2) and (c == 1 or c == 2)
    hill_points[#hill_points + 1] = { c, r, raised and 2 or 0 }
  end
end
local hill = meshedit.patch(hill_points)

local function pt(p)
  return string.format("(%g, %g, %g)", p.x, p.y, p.z)
end

step("From curves to surfaces", function()
  show(hill)
  camera "fit"
  say [[
# Bézier patches

A **Bézier patch** is a surface made from a 4 by 4 grid of **control points**, 16 in all. On screen is a
small hill: the twelve points around the edge lie flat, the four in the middle are raised to height 2.]]
  say [[
Each of the four **rows** of the grid is the control polygon of a cubic curve, just like in part 1. A point
of the surface has two parameters, **u** and **v**, both between 0 and 1, one for each direction of
the grid.]]
end)

step("Rows in u, then the column in v", function()
  show(hill)
  local u, v = 0.5, 0.5
  local e = hill:evaluation(u, v)
  local rows = {}
  for i, p in ipairs(e.rows) do rows[i] = pt(p) end
  say [[
To evaluate the patch at (u, v), use de Casteljau twice:

1. evaluate each of the **four rows** as a curve at **u**: that gives four points
2. those four points are the control points of one more curve, the **column**: evaluate it at **v**]]
  say("For the hill at u = 0.5, v = 0.5 the four row points are " .. table.concat(rows, ", ")
    .. ", and the column curve through them gives **" .. pt(e.point) .. "**.")
  say [[
The middle of the hill is lower than its raised control points: like a curve, a patch is pulled towards
its control points but passes only through the four corners.]]
  say [[
How many one-dimensional de Casteljau evaluations (whole curves, each down to a single point) does one
point of a patch take? Press the number.]]
  wait_for { key = "5", hint = "Count the row curves, then the column curve" }
  say [[
Right: **5**, four rows and one column. (Doing the columns in v first and then a row in u gives the very
same point; MeshEdit follows the assignment's order, rows first.)]]
end)

step("The Utah teapot", function()
  local patches = meshedit.load_patches(lesson_file("../assets/teapot.bez"))
  show(patches)
  camera "fit"
  say("# The teapot\n\nThe **Utah teapot** (Martin Newell, 1975) is made of **" .. #patches
    .. " Bézier patches**: rim, body, lid, handle and spout. That is only " .. 16 * #patches
    .. " control points for the whole smooth shape.")
  say [[
The view draws each patch by evaluating it on a grid of (u, v) values and joining the points into
triangles. Move the **resolution** slider to see how many points that takes; switch the **control nets**
on to see the grey points that shape it.]]
  wait_for { button = "Continue" }
end)

step("Where patches meet", function()
  local patches = meshedit.load_patches(lesson_file("../assets/teapot.bez"))
  show(patches)
  local first = patches[1]
  local row = {}
  for c = 1, 4 do row[c] = first.points[c] end
  local edge_curve = meshedit.curve(row)
  local u = 0.3
  local on_patch, on_curve = first:evaluate(u, 0), edge_curve:evaluate(u)
  say [[
Why do 32 separate patches look like one smooth pot? Look at the edge of a patch where v = 0: the column
curve there ends at its first control point, which is the first row's point. So the whole edge **is the
first row's curve**, and depends on those four points only.]]
  say("Checked on the first teapot patch at u = 0.3: the patch gives " .. pt(on_patch)
    .. " and the curve of its first row gives " .. pt(on_curve) .. ". "
    .. (on_patch == on_curve and "The same point." or "They differ!"))
  say [[
Two patches that share the four points of an edge therefore share the whole edge: no gaps. The
teapot's modeller also kept, along most edges, the control points on either side in line, so the surface
turns smoothly from one patch to the next.]]
end)

step("Your turn", function()
  show(hill)
  say [[
# Your code

Open `scripts/student/patch.lua` and write `evaluate(patch, u, v)`. `patch.points` holds the 16 control
points row by row (`patch.points[row * 4 + col + 1]`). Use your curve step from part 1: four rows at **u**,
then the column at **v**.

Check it right here: tick **mine** in the patch view (or press **M**). The probe point at (u, v) is then also
computed by your `evaluate`: a bluish-green dot inside the vermillion P(u, v) when it is right, a vermillion dot
joined to P(u, v) when it is not (P(u, v) is then the reference's, in the plain ink colour), with both points in
the panel (and a hint when u and v are swapped); a Lua error shows its `patch.lua:LINE`. Move u and v, pick other
patches; save the file and the view runs the new version.

Or check it from a terminal, with the grading suite:

    meshedit grade --suite tests/grading/suites/patch.lua --submission scripts/student

When it is right, it gives the very points of the teapot you saw here.]]
end)
