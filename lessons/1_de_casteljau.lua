-- Part 1: Bézier curves by de Casteljau's algorithm: control points, the levels at a parameter t, the curve
-- traced as t moves, and splitting a curve in two. Every number the lesson prints is computed by the
-- project's own Bézier code (meshedit.curve), so the text never drifts from what the curve view draws.
-- CI runs it headless:
--   meshedit lesson lessons/1_de_casteljau.lua --headless --answers tests/script/lessons/1_de_casteljau_answers.lua

lesson {
  title = "de Casteljau's algorithm",
  summary = "How four points make a curve: the levels at t, the point they end in, and how one split gives two curves.",
}

-- A cubic: four control points, drawn in the z = 0 plane.
local curve = meshedit.curve { {0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0} }

-- "(1.25, 1.5)": a point as the panel prints it (2D, short numbers).
local function pt(p)
  return string.format("(%g, %g)", p.x, p.y)
end

local function list(points)
  local parts = {}
  for i, p in ipairs(points) do parts[i] = pt(p) end
  return table.concat(parts, ", ")
end

step("Four points, one curve", function()
  show(curve)
  camera "fit"
  say [[
# Bézier curves

A **Bézier curve** is drawn from a few **control points**. On screen is a *cubic*: four control points,
joined by the **control polygon**.]]
  say("The control points are " .. list(curve.points) .. ".")
  say [[
The curve starts at the first point and ends at the last one. It does not pass through the two middle
points: they *pull* the curve towards them. Drag a control point in the view and watch the curve follow.]]
end)

step("One level at a time", function()
  show(curve)
  local levels = curve:levels(0.5)
  say [[
To find the point of the curve at a parameter **t** between 0 and 1, de Casteljau's algorithm only ever
does one thing: it takes two neighbouring points and goes the fraction **t** of the way from the first to
the second, `(1 - t) * a + t * b`.]]
  say("Doing that to every neighbouring pair of the 4 control points gives 3 new points: that is one **level**. "
    .. "At t = 0.5:\n\n"
    .. "- level 0, the control points: " .. list(levels[1]) .. "\n"
    .. "- level 1: " .. list(levels[2]) .. "\n"
    .. "- level 2: " .. list(levels[3]) .. "\n"
    .. "- level 3: " .. list(levels[4]))
  say [[
Level k comes after k steps, so the control points are level 0, as in the table of the curve view. Each level
has one point fewer than the one before. The last level is a single point, and that point **is on the
curve**. Press **E** to draw one more level in the view.]]
  wait_for { key = "E", hint = "Press E to draw the next level" }
  say [[
Keep pressing **E** to add the levels one by one, down to the single point.]]
end)

step("Count the points", function()
  show(curve)
  say [[
A quick check. A **quartic** curve has 5 control points. How many points are in its **level 2** (two
steps of de Casteljau after the control points, level 0)?

Press the number on the keyboard.]]
  wait_for { key = "3", hint = "Press the number of points: 5 control points, then two steps" }
  say [[
Right: 3. Every step turns n points into n - 1, so 5 control points give 4, then 3, then 2, then 1.
A curve with n control points needs n - 1 steps to reach its point.]]
end)

step("Moving t", function()
  say [[
Now let **t** run from 0 to 1. For each t the levels give one point; together those points are the curve.
Watch the curve being traced from its start.]]
  -- The left part of the split at t is exactly the curve from 0 to t: showing it traces the curve.
  animate(3, function(t)
    local traced = curve:split(math.max(t, 1e-3))
    show(traced)
  end)
  show(curve)
  local quarter = curve:evaluate(0.25)
  say("At t = 0 the point is the first control point, at t = 1 the last. At t = 0.25 it is "
    .. pt(quarter) .. ": not a quarter of the way along the polygon, because the curve moves at its own speed.")
  say [[
In the view, drag the **t** slider (or scroll over the view) to move t yourself. Press **C** to hide and
show the curve, so you can see the levels alone.]]
  wait_for { key = "C", hint = "Press C to hide or show the curve" }
end)

step("Splitting a curve", function()
  local t = 0.5
  local levels = curve:levels(t)
  local left, right = curve:split(t)
  show(left)
  say [[
The levels hide a gift. Take the **first** point of every level: they are the control points of the
curve's part from 0 to t. Take the **last** point of every level, backwards: they control the part from
t to 1. Splitting a curve costs nothing more than evaluating it.]]
  -- Check the claim on the curve itself before saying it.
  local agree = true
  for k = 1, #levels do
    if left.points[k] ~= levels[k][1] or right.points[k] ~= levels[#levels - k + 1][#levels[#levels - k + 1]] then
      agree = false
    end
  end
  say("At t = 0.5 the left half has control points " .. list(left.points) .. " and the right half "
    .. list(right.points) .. ". Checked against the levels: " .. (agree and "they match." or "they DO NOT match."))
  say [[
On screen is the left half alone: the same shape as the first half of the curve, with its own four
control points. Splitting again and again gives control polygons that hug the curve ever closer, which
is how curves are drawn and intersected fast.]]
  wait_for { button = "Continue" }
end)

step("Your turn", function()
  show(curve)
  say [[
# Your code

Open `scripts/student/curve.lua` and write `evaluate_step(points, t)`: given a list of points, return
the next level, one point fewer.

Check it right here: tick **mine** in the curve view (or press **M**), then press **E**. Each level is now made
by your function from the level before and checked against the reference. A level that differs is drawn in
vermillion over the reference's (faint), its first wrong point ringed, and the line above the curve names the
level, the point and both values; a Lua error shows its `curve.lua:LINE`. Save the file and the view runs the new
version; drag the points or move t to try other inputs.

Or check it from a terminal, with the grading suite:

    meshedit grade --suite tests/grading/suites/curve.lua --submission scripts/student

Each failed test says what differs (a missing point, weights the wrong way round...).]]
end)
