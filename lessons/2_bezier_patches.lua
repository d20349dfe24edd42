-- Part 2: Bézier patches: a 4x4 grid of control points, evaluated as four curves in u (the rows) and then
-- one curve in v (the column through the row points); the normal at (u, v) from the two tangents, on the probe the
-- student moves; then the Utah teapot, 32 such patches, and what makes two of them meet smoothly. Each step asks the
-- student to predict before it shows, and names the likely mistakes (u and v swapped, rows and columns swapped).
-- Numbers come from the project's Bézier code (meshedit.patch, p:evaluation), and the teapot from
-- assets/teapot.bez, found next to this file with lesson_file(). The last step runs the student's own evaluate
-- (your_turn) at the (u, v) of the hand computation. CI runs it headless:
--   meshedit lesson lessons/2_bezier_patches.lua --headless \
--     --answers tests/lesson/lessons/2_bezier_patches_answers.lua --student tests/exercise/solutions

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

-- A unit vector with three decimals: "(-0.647, 0.144, 0.749)".
local function unit(n)
  return string.format("(%.3f, %.3f, %.3f)", n.x, n.y, n.z)
end

local function near(p, q, tolerance)
  return (p - q):length() < (tolerance or 1e-3)
end

step("From curves to surfaces", function()
  show(hill)
  camera "fit"
  say [[
# Bézier patches

A **Bézier patch** is a surface made from a 4 by 4 grid of **control points**, 16 in all. On screen is a
small hill: the twelve points around the edge lie flat, the four in the middle are raised to height 2.
Each of the four **rows** of the grid is the control polygon of a cubic curve, as in part 1.]]
  choose {
    "Which of the control points does the surface pass through?",
    options = { "all sixteen", "the four corners", "the four raised middle points", "the twelve around the edge" },
    answer = "the four corners",
    feedback = {
      ["all sixteen"] = "A curve does not pass through its middle control points; a patch, made of curves, does "
        .. "not either.",
      ["the four raised middle points"] = "The raised points pull the surface up, but it stays below them: look "
        .. "at the top of the hill.",
      ["the twelve around the edge"] = "Each edge of the patch is a cubic curve: it passes through the ends of "
        .. "its control polygon, not through its middle points.",
      ["the four corners"] = "Yes: each edge is a cubic through its two end points, the corners.",
    },
    hint = "Each edge of the patch is a cubic curve with four of the control points. Which of them does it reach?",
  }
  say [[
The patch has two parameters, **u** and **v**, both between 0 and 1, one for each direction of the grid:
**u** runs along a row (here along x), **v** across the rows (along y).]]
  choose {
    "The points are stored row by row: `points[row * 4 + col + 1]`. Which index holds row 1, column 2 (rows and "
      .. "columns counted from 0)?",
    options = { "6", "7", "10" },
    answer = "7",
    feedback = {
      ["10"] = "10 = 2 * 4 + 1 + 1 is row 2, column 1: rows and columns swapped. The row is multiplied by 4.",
      ["6"] = "6 = 1 * 4 + 2 is the index counted from 0; Lua lists start at 1, hence the + 1.",
      ["7"] = "Yes: 1 * 4 + 2 + 1 = 7.",
    },
    hint = "A row holds 4 points, so each row moves the index on by 4.",
  }
  say("`points[7]` of the hill is " .. pt(hill.points[7]) .. ": x is the column, y the row, and it is raised.")
end)

step("Rows in u", function()
  show(hill)
  say [[
To evaluate the patch at (u, v), use de Casteljau twice:

- first, evaluate each of the **four rows** as a curve at **u**: that gives four points
- then, those four points are the control points of one more curve, the **column**: evaluate it at **v**]]
  choose {
    "How many one-dimensional de Casteljau evaluations (whole curves, each down to a single point) does one point "
      .. "of a patch take?",
    options = { "4", "5", "8", "16" },
    answer = "5",
    feedback = {
      ["4"] = "4 are the rows: their four points still need one more curve, the column, to become one point.",
      ["8"] = "8 evaluates every row and every column of the grid; only one column is needed, the one through the "
        .. "four row points.",
      ["16"] = "16 is the number of control points, not of curves: each curve takes a whole row of four.",
      ["5"] = "Yes: four rows and one column.",
    },
    hint = "Count the row curves, then the curves that the row points make.",
  }
  local row1 = meshedit.curve { hill.points[5], hill.points[6], hill.points[7], hill.points[8] }
  local at = row1:evaluate(0.25)
  answer {
    "Row 1 is (0, 1, 0), (1, 1, 2), (2, 1, 2), (3, 1, 0). Where is its point at u = 0.25? Give x, y, z.",
    point = { at.x, at.y, at.z },
    feedback = function(p)
      local swapped = row1:evaluate(0.75)
      if near(p, swapped) then return pt(p) .. " is the row's point at 0.75: u and 1 - u swapped." end
      if near(p, meshedit.vec3(1.5, 1, 1)) then
        return "(1.5, 1, 1) is the average of the row's four points: the curve's point weights them."
      end
      if math.abs(p.x - at.x) < 1e-3 and math.abs(p.z - at.z) > 1e-3 then
        return "x is right; the height is not: run the steps on z too, 0, 2, 2, 0."
      end
    end,
    hint = "Its heights 0, 2, 2, 0 are part 1's y values, so z is part 1's y at 0.25; x goes 0, 1, 2, 3, evenly "
      .. "spaced, so x = 3u.",
  }
  local e = hill:evaluation(0.25, 0.5)
  local rows = {}
  for i, p in ipairs(e.rows) do rows[i] = pt(p) end
  say("Yes. The four rows at u = 0.25 give " .. table.concat(rows, ", ")
    .. ": the two flat rows stay at height 0, and every row point has x = 0.75.")
end)

step("Then the column in v", function()
  show(hill)
  local u, v = 0.25, 0.5
  local e = hill:evaluation(u, v)
  local swapped = hill:evaluate(v, u)
  local rows = {}
  for i, p in ipairs(e.rows) do rows[i] = pt(p) end
  say("The four row points at u = 0.25 are " .. table.concat(rows, ", ") .. ". They are the control points of "
    .. "the column curve.")
  answer {
    "Where is the patch's point P(0.25, 0.5)? Give x, y, z.",
    point = { e.point.x, e.point.y, e.point.z },
    feedback = function(p)
      if near(p, swapped) then
        return pt(p) .. " is P(0.5, 0.25): u and v swapped. u is for the rows (x here), v for the column through "
          .. "the row points (y)."
      end
      if near(p, e.rows[2]) or near(p, e.rows[3]) then
        return pt(p) .. " is a row point: the column curve through all four row points is still to evaluate."
      end
      if math.abs(p.z - 0.5625) < 1e-3 then
        return "z = 0.5625 is the average of the row points' heights: the column's point weights them."
      end
    end,
    hint = "Run de Casteljau on the four row points at v = 0.5; x stays 0.75.",
  }
  say("Yes: **P(0.25, 0.5) = " .. pt(e.point) .. "**. See it in the patch view: set **u** to 0.25 and **v** to "
    .. "0.5; the probe point P(u, v) is drawn on the surface and listed in the panel. Swapping u and v gives "
    .. pt(swapped) .. ", the mirror point across the diagonal: on this symmetric hill only x and y tell them apart.")
  say [[
Doing the columns in v first and then a row in u gives the very same point; MeshEdit follows the assignment's
order, rows first.]]
end)

-- The patch with rows and columns swapped: its rows are `patch`'s columns.
local function transposed(patch)
  local points = {}
  for r = 0, 3 do
    for c = 0, 3 do points[c * 4 + r + 1] = patch.points[r * 4 + c + 1] end
  end
  return meshedit.patch(points)
end

-- The tangents at (u, v) as lesson 1 found a curve's: 3 times the difference of the last level's two points, for
-- the column curve through the rows at u (along v) and for the row curve through the columns at v (along u); their
-- cross product, normalised, is the normal.
local function tangents(patch, u, v)
  local along_v = patch:evaluation(u, v).column_levels[3]
  local along_u = transposed(patch):evaluation(v, u).column_levels[3]
  local tu, tv = (along_u[2] - along_u[1]) * 3, (along_v[2] - along_v[1]) * 3
  return tu, tv, tu:cross(tv):normalized()
end

step("The normal at (u, v)", function()
  show(hill)
  camera "fit"
  local top = hill:evaluate(0.5, 0.5)
  local tu, tv, n = tangents(hill, 0.5, 0.5)
  say [[
Shading a patch needs its **normal** at every (u, v). Lesson 1 found a curve's tangent in its last level: 3 times
the difference of the two level-2 points. A patch has a curve through every point in each direction: the column
curve (along v) and the row curve through the four columns at v (along u), so it has two tangents.]]
  local up = "Straight up"
  choose {
    "At the top of the hill, (u, v) = (0.5, 0.5), which way does the normal point?",
    options = { up, "Along u, the way the rows run", "Toward the corner (0, 0)" },
    answer = up,
    feedback = {
      ["Along u, the way the rows run"] = "Along u is a tangent: it lies in the surface. The normal is square to "
        .. "both tangents.",
      ["Toward the corner (0, 0)"] = "The hill is the same seen from every side of its middle, so at the middle "
        .. "nothing picks out one corner.",
      [up] = "Yes: at the top both tangents are level, so the normal, square to both, points straight up.",
    },
    hint = "The normal is square to the surface. How does the surface lie at the very top of the hill?",
  }
  arrow(top, top + n, "blue")
  say("At (0.5, 0.5) the tangents are Tu = " .. pt(tu) .. " and Tv = " .. pt(tv) .. "; their cross product, "
    .. "normalised, is n = " .. unit(n) .. " (blue arrow, from P = " .. pt(top) .. ").")
  live(function()
    local u, v = patch_uv()
    if not u then return "(the patch view is not on screen)" end
    local a, b, normal = tangents(hill, u, v)
    return string.format("At the probe (u, v) = (%.2f, %.2f): Tu = %s, Tv = %s, n = %s", u, v, pt(a), pt(b),
      unit(normal))
  end)
  say [[
Now move the probe (the **u** and **v** sliders of the Patches panel, on the right) onto the slope: **u below
0.3**, with v between 0.3 and 0.7.]]
  local u = wait_for {
    hint = "Drag u below 0.3, v between 0.3 and 0.7",
    condition = function()
      local pu, pv = patch_uv()
      if pu and pu < 0.3 and pv >= 0.3 and pv <= 0.7 then return pu end
      return false
    end,
  }
  local _, v = patch_uv()
  local p = hill:evaluate(u, v)
  local _, _, slope = tangents(hill, u, v)
  clear()
  arrow(p, p + slope, "blue")
  local down = "Away from the top, toward u = 0"
  choose {
    "The blue arrow is the normal at your probe. Which way does it lean?",
    options = { down, "Toward the top", "It points straight up" },
    answer = slope.x < 0 and down or "Toward the top",
    feedback = {
      ["Toward the top"] = "The slope rises toward the top, so a normal square to it tips back, away from the top.",
      ["It points straight up"] = string.format("Its x is %.3f: not 0. Only where the surface is level does it "
        .. "point straight up.", slope.x),
      [down] = "Yes: the surface rises toward the top, and the normal, square to it, tips the other way.",
    },
    hint = "Picture a ramp rising to the right: which way does a stick standing square to it lean?",
  }
  say("At (" .. string.format("%.2f, %.2f", u, v) .. ") the normal is " .. unit(slope) .. ". Phong shading in part 3 "
    .. "uses normals like these; here each comes straight from the two tangents.")
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
triangles. At **resolution** n, each patch is cut into n by n small squares.]]
  choose {
    "At resolution 8, how many points of one patch does the view evaluate?",
    options = { "16", "64", "81" },
    answer = "81",
    feedback = {
      ["64"] = "64 counts the squares. A row of 8 squares has 9 corners: the points are one more each way.",
      ["16"] = "16 are the control points, which the view does not draw on the surface: it evaluates the patch "
        .. "at values of u and v.",
      ["81"] = "Yes: 9 values of u (0, 1/8, ..., 1) times 9 values of v.",
    },
    hint = "Count the corners along one side of 8 squares in a row first.",
  }
  say [[
Move the **resolution** slider and watch the panel's count of vertices and triangles follow. The **control net**
box (on at the start) draws the nets that shape the pot, grey for every patch but the probed one; untick it to see
the surface alone.]]
end)

step("Where patches meet", function()
  local patches = meshedit.load_patches(lesson_file("../assets/teapot.bez"))
  show(patches)
  say [[
Why do 32 separate patches look like one smooth pot? Look at one edge of a patch, where v = 0.]]
  choose {
    "Along the edge v = 0 of a patch, which control points decide the edge curve?",
    options = { "the first row's four points", "the first column's four points", "all sixteen",
                "the four corners" },
    answer = "the first row's four points",
    feedback = {
      ["the first column's four points"] = "The first column is the edge u = 0: rows and columns swapped. At "
        .. "v = 0 it is the column curve that is at its start.",
      ["all sixteen"] = "At v = 0 the column curve is at its first control point, which is the first row's point: "
        .. "the other rows drop out.",
      ["the four corners"] = "The corners are the ends of the edge; its middle is pulled by two more points.",
      ["the first row's four points"] = "Yes: the column curve at v = 0 is its first control point, the first "
        .. "row's point at u.",
    },
    hint = "Evaluate the column curve at v = 0: which of its four control points is left?",
  }
  local first = patches[1]
  local row = {}
  for c = 1, 4 do row[c] = first.points[c] end
  local edge_curve = meshedit.curve(row)
  local u = 0.3
  local on_patch, on_curve = first:evaluate(u, 0), edge_curve:evaluate(u)
  say("Checked on the first teapot patch at u = 0.3: the patch at v = 0 gives " .. pt(on_patch)
    .. " and the curve of its first row gives " .. pt(on_curve) .. ". "
    .. (on_patch == on_curve and "The same point." or "They differ!"))
  say [[
Two patches that share the four points of an edge therefore share the whole edge: no gaps.]]
  local smooth = "The points next to the edge, on both sides, in line with it"
  choose {
    "No gap is not yet smooth: the surface could still fold along the edge. What else must the two patches' "
      .. "control points do for the surface to turn smoothly across it?",
    options = { smooth, "Share their four corners", "Nothing more: a shared edge is smooth" },
    answer = smooth,
    feedback = {
      ["Share their four corners"] = "Sharing the edge's four points already makes them share its corners; the "
        .. "question is what happens across the edge, not along it.",
      ["Nothing more: a shared edge is smooth"] = "Two curves can meet at a point and still make a corner there: "
        .. "lesson 1's tangent at t = 0 is 3 (P1 - P0), set by the point next to the end.",
      [smooth] = "Yes: across the edge, each column curve's tangent at its end is 3 (P1 - P0), set by the row next "
        .. "to the edge. When the row before the edge on one patch, the edge and the row after it on the other lie "
        .. "in line (and evenly spaced), the tangents across the edge agree and the surface turns smoothly.",
    },
    hint = "Think of lesson 1: what sets a curve's tangent at its first point?",
  }
  say [[
The teapot's modeller kept, along most edges, the control points on either side in line, so the surface turns
smoothly from one patch to the next.]]
end)

step("Your turn", function()
  show(hill)
  say [[
# Your code

Open `scripts/student/patch.lua` and write `evaluate(patch, u, v)`. `patch.points` holds the 16 control
points row by row (`patch.points[row * 4 + col + 1]`). Evaluate the four rows at **u**, then the column at
**v**, with de Casteljau steps as in part 1. Each exercise file runs on its own (in the window and in grading,
`patch.lua` is loaded alone), so part 1's `evaluate_step` is not there to call: copy it into `patch.lua` as a
local function. The lesson runs it on the hill at u = 0.25, v = 0.5, the point you computed by hand,
each time you save the file, and compares it with the reference; a Lua error shows its `patch.lua:LINE`.]]
  your_turn {
    exercise = "patch",
    patch = hill,
    u = 0.25,
    v = 0.5,
    hint = "Evaluate each row (points 1-4, 5-8, 9-12, 13-16) at u, then the curve through those four points at v.",
  }
  say [[
Your `evaluate` gives the reference's P(0.25, 0.5). Now try it everywhere: tick **mine** in the patch view (or
press **M**). The probe point at (u, v) is then also computed by your `evaluate`: a bluish-green dot inside the
vermillion P(u, v) when it is right, a vermillion dot joined to P(u, v) when it is not. Move u and v, pick other
patches; save the file and the view runs the new version.

The grading suite runs the same checks from a terminal:

    meshedit grade --suite tests/grading/suites/patch.lua --submission scripts/student

When it is right, it gives the very points of the teapot you saw here.]]
  wait_for { key = "M", hint = "Press M to check your evaluate in the patch view" }
end)
