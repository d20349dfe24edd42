-- Part 1: Bézier curves by de Casteljau's algorithm: the levels at a parameter t (level 0 is the control points,
-- level k comes after k steps), the curve traced as t moves, a curve of six control points at every level (the
-- write-up's figure), splitting a curve in two, the Bernstein weights and the derivative. Each step asks the
-- student to predict or to act before it shows; the numbers the lesson prints are computed by the project's own
-- Bézier code (meshedit.curve), so the text never drifts from what the curve view draws, except a few worked values
-- of this curve written in its text (3/8, t = 1/3, the polygon's length 6.47 and quarter point (0.72, 1.45),
-- C'(0.5) = (4.5, 0)), each checked against the core by tests/lesson/lessons_a_test.cpp.
-- The last step runs the student's own evaluate_step (your_turn) at t = 0.25, where swapped weights show.
-- CI runs it headless:
--   meshedit lesson lessons/1_de_casteljau.lua --headless --answers tests/lesson/lessons/1_de_casteljau_answers.lua \
--     --student tests/exercise/solutions

lesson {
  title = "de Casteljau's algorithm",
  summary = "How four points make a curve: the levels at t, the point they end in, splitting, weights and tangents.",
}

-- A cubic: four control points, drawn in the z = 0 plane.
local curve = meshedit.curve { {0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0} }
local degree = #curve.points - 1

-- "(1.25, 1.5)": a point as the panel prints it (2D, short numbers).
local function pt(p)
  return string.format("(%g, %g)", p.x, p.y)
end

local function list(points)
  local parts = {}
  for i, p in ipairs(points) do parts[i] = pt(p) end
  return table.concat(parts, ", ")
end

local function near(p, x, y, tolerance)
  return math.abs(p.x - x) < (tolerance or 1e-3) and math.abs(p.y - y) < (tolerance or 1e-3)
end

-- The curve the view shows now, as the student left it (dragged points, added points), or the lesson's.
local function on_screen()
  local points = curve_points()
  if points and #points >= 2 then return meshedit.curve(points) end
  return curve
end

-- The levels at t, one line each, level 0 first.
local function level_lines(c, t)
  local lines = {}
  for k, level in ipairs(c:levels(t)) do
    lines[k] = string.format("- level %d: %s", k - 1, list(level))
  end
  return table.concat(lines, "\n")
end

-- |C'(t)|: the degree times the distance between the two points of the next-to-last level.
local function speed(c, t)
  local levels = c:levels(t)
  local two = levels[#levels - 1]
  return ((two[2] - two[1]) * (#c.points - 1)):length()
end

-- The hodograph: the control points of C'(t), n times the differences of neighbouring control points.
local function hodograph_points(points)
  local n, out = #points - 1, {}
  for i = 1, n do out[i] = (points[i + 1] - points[i]) * n end
  return out
end

step("Four points, one curve", function()
  show(curve)
  camera "fit"
  say [[
# Bézier curves

A **Bézier curve** is drawn from a few **control points**. On screen is a *cubic*: four control points,
joined by the **control polygon**. The curve itself is hidden for now.]]
  say("The control points are " .. list(curve.points) .. ".")
  choose {
    "Before you see it: which control points will the curve pass through?",
    options = { "all four", "the first and the last", "the two middle ones", "none of them" },
    answer = "the first and the last",
    feedback = {
      ["all four"] = "A curve through all four would be an interpolating curve. A Bézier curve only passes "
        .. "through some of its control points; the others pull it without being reached.",
      ["the two middle ones"] = "The middle points are the ones that pull the curve; think of where t = 0 and "
        .. "t = 1 must put the point.",
      ["none of them"] = "The curve has to start and end somewhere: where is it at t = 0, before any mixing?",
      ["the first and the last"] = "Yes: it starts at the first point and ends at the last one.",
    },
    hint = "At t = 0 every step of the algorithm keeps the first point of each pair.",
  }
  say [[
Press **C** to draw the curve, then drag a control point in the view and watch the curve follow.]]
  wait_for { key = "C", hint = "Press C to show the curve" }
  say [[
The curve starts at the first point and ends at the last one. It does not pass through the two middle
points: they *pull* the curve towards them.]]
end)

step("One step: level 1", function()
  show(curve)
  say [[
To find the point of the curve at a parameter **t** between 0 and 1, de Casteljau's algorithm only ever
does one thing: it takes two neighbouring points and goes the fraction **t** of the way from the first to
the second, `(1 - t) * a + t * b`. Done to every neighbouring pair of the control points (**level 0**), it
gives the points of **level 1**.]]
  answer {
    "At t = 0.25, where is the first point of level 1, between (0, 0) and (1, 2)? Give x, y.",
    point = { 0.25, 0.5 },
    feedback = function(p)
      if near(p, 0.75, 1.5) then
        return "(0.75, 1.5) is three quarters of the way: t and 1 - t swapped. At t = 0.25 the point stays "
          .. "close to the first point, (1 - t) * a + t * b with a = (0, 0)."
      elseif near(p, 0.5, 1) then
        return "(0.5, 1) is the midpoint, the average of the two points: that is t = 0.5, not t = 0.25."
      elseif near(p, 1.5, 2) or near(p, 3.25, 1.5) then
        return pt(p) .. " is a level-1 point of another pair: the first point of level 1 comes from the first "
          .. "two control points."
      elseif near(p, 0, 0) or near(p, 1, 2) then
        return pt(p) .. " is a control point itself: level 1 lies between the two, t of the way along."
      end
    end,
    hint = "Go a quarter of the way from (0, 0) towards (1, 2).",
  }
  say [[
Now see it: drag the **t** slider of the curve view to **0.25** (or scroll over the view: one notch moves t
by 0.01), then press **E** to draw level 1.]]
  wait_for {
    condition = function() local t = curve_t() return t and math.abs(t - 0.25) < 0.005 end,
    hint = "Move t to 0.25: the slider shows its value",
  }
  wait_for { key = "E", hint = "Press E to draw level 1" }
  live(function()
    local c = on_screen()
    local t = curve_t() or 0.25
    return string.format("At t = %.2f level 1 is %s.", t, list(c:levels(t)[2]))
  end)
  say [[
Three points, one fewer than level 0: each lies on a side of the control polygon, t of the way along it.]]
end)

step("Counting levels", function()
  show(curve)
  say [[
Each step turns the points of one level into the next, one point fewer. Level 0 is the control points, and
**level k** is what you have after **k** steps.]]
  choose {
    "A quartic curve has 5 control points. How many points are in its level 2?",
    options = { "5", "4", "3", "2" },
    answer = "3",
    feedback = {
      ["5"] = "5 is level 0, the control points themselves, before any step.",
      ["4"] = "4 is level 1, after one step: off by one. Level 2 comes after two steps.",
      ["2"] = "2 is level 3, after three steps: one step too many. Level k is not k points; it is what is left "
        .. "after k steps, each removing one point.",
      ["3"] = "Yes: 5, then 4 after one step, then 3 after two.",
    },
    hint = "Each step removes one point. Level 0 has 5.",
  }
  say [[
Check it in the view: press **Add point** to make the curve a quartic and press **E** until the table below the
curve shows level 2. A curve with n control points needs n - 1 steps to reach its single point, the last level,
which **is on the curve**.]]
  wait_for { key = "E", hint = "Press E to draw the next level" }
end)

step("Moving t", function()
  show(curve)
  view { curve = true }
  say [[
For each t the levels end in one point, and together those points are the curve, drawn now in the view. Before
you compute one, guess.]]
  pick {
    "Click the point of the curve you think is C(0.25), the point at t = 0.25.",
    on = "curve",
    answer = 0.25,
    tolerance = 0.03,
    feedback = function(t)
      if t < 0.25 then
        return string.format("That is C(%.2f), short of C(0.25): t = 0.25 is a quarter of the way in t, and this "
          .. "curve moves a little faster near its ends, so C(0.25) is a bit more than a quarter of its length.", t)
      end
      return string.format("That is C(%.2f), past C(0.25): t = 0.25 is a quarter of the way from P0 in t, so "
        .. "C(0.25) is near the first end.", t)
    end,
    hint = "t runs from 0 at P0 to 1 at P3 along the curve.",
  }
  say [[
Near enough: now compute it. Press **E** three times to draw every level, then drag **t** from 0 to 1 (the slider,
or the wheel over the view): the last level's point, C(t), runs along the curve. The levels below are those of the
curve on screen at the view's t, and follow it.]]
  live(function()
    local t = curve_t()
    if not t then return "(the curve view is not on screen)" end
    return string.format("**t = %.2f**\n\n%s", t, level_lines(on_screen(), t))
  end)
  local quarter = curve:evaluate(0.25)
  answer {
    "Move t to 0.25 and read the curve's point C(0.25) off the levels. Give it as x, y.",
    point = { quarter.x, quarter.y },
    tolerance = 1e-3,
    feedback = function(p)
      if near(p, 0.5625, 0.875) or near(p, 1.9375, 1.875) then
        return pt(p) .. " is a level-2 point: one more step, between the two level-2 points, gives the curve's point."
      elseif near(p, 0.25, 0.5) or near(p, 1.5, 2) or near(p, 3.25, 1.5) then
        return pt(p) .. " is a level-1 point: two more steps to the curve."
      elseif near(p, 3.09375, 1.125) then
        return "(3.094, 1.125) is C(0.75): t and 1 - t swapped."
      elseif near(p, 2, 1) then
        return "(2, 1) is the average of the four control points: the curve's point weights them, it does not "
          .. "average them."
      end
    end,
    hint = "The live text lists every level at the view's t: the last level is the curve's point.",
  }
  say("Yes, C(0.25) = " .. pt(quarter) .. ". That is not a quarter of the way along the control polygon (6.47 long:"
    .. " a quarter of it is still on its first side, near (0.72, 1.45)): the curve moves at its own speed.")
end)

-- A curve of six control points, as the assignment's write-up asks for one: a wave that crosses its own chord.
local six = meshedit.curve { {0, 0, 0}, {1, 3, 0}, {2.5, -1, 0}, {3.5, 3.5, 0}, {5, -0.5, 0}, {6, 1.5, 0} }

step("Six points, every level", function()
  show(six)
  say [[
The write-up asks for a curve of **six** control points with every level of de Casteljau drawn. Here is one: a
quintic, degree 5.]]
  answer {
    "How many times must you press E, from the control points alone, until the view shows the curve's point?",
    number = #six.points - 1,
    tolerance = 0,
    feedback = function(value)
      if value == #six.points then
        return "Six would be one step past the point: each step removes one point, and six points reach one after "
          .. "five steps."
      end
      if value == 3 then return "Three steps take a cubic, four points, to its point; this curve has six." end
      if value == 1 then return "One step gives level 1, five points: each step removes only one." end
    end,
    hint = "Level k has 6 - k points. Which k leaves one?",
  }
  local presses = 0
  live(function()
    local t = curve_t()
    if not t then return "(the curve view is not on screen)" end
    return string.format("**t = %.2f**\n\n%s", t, level_lines(on_screen(), t))
  end)
  say "Now press **E** five times, one level at a time, and watch each level's points slide along the last one's sides."
  while presses < #six.points - 1 do
    wait_for { key = "E", hint = "Press E: level " .. (presses + 1) .. " of " .. (#six.points - 1) }
    presses = presses + 1
  end
  local t = curve_t() or 0.5
  say("Every level at t = " .. string.format("%.2f", t) .. ": " .. #six:levels(t) .. " levels from the 6 control "
    .. "points down to C(t) = " .. pt(six:evaluate(t)) .. ". Drag t and the whole pyramid follows; press **C** to "
    .. "draw the curve through all its points. That picture, at two or three values of t, is the write-up's.")
end)

step("Splitting a curve", function()
  show(curve)
  choose {
    "The curve cut at t gives two cubics, the part from 0 to t and the part from t to 1. Which points are the "
      .. "control points of the part from 0 to t?",
    options = { "the first point of every level", "the last point of every level", "the points of level 1",
                "the midpoints of the control polygon" },
    answer = "the first point of every level",
    feedback = {
      ["the last point of every level"] = "The last points, read backwards, control the other part, from t to 1.",
      ["the points of level 1"] = "Level 1 has 3 points and a cubic needs 4: one from each level, 0 to 3.",
      ["the midpoints of the control polygon"] = "Midpoints are level 1 at t = 0.5 only; the cut can be at any t.",
      ["the first point of every level"] = "Yes: the first point of level 0 (the curve's start) down to the "
        .. "last level (the point at t).",
    },
    hint = "The part from 0 to t starts where the curve starts and ends at C(t).",
  }
  say [[
See it: tick **Split at t** in the curve view. The two halves are drawn in two colours, their control points
ringed; the table lists them as **left** and **right**. Now drag **t** and watch both halves change.]]
  live(function()
    local t = curve_t()
    if not t then return "(the curve view is not on screen)" end
    local c = on_screen()
    local left, right = c:split(t)
    local levels = c:levels(t)
    local firsts, lasts = {}, {}
    for k = 1, #levels do
      firsts[k] = levels[k][1]
      lasts[k] = levels[#levels - k + 1][#levels[#levels - k + 1]]
    end
    local agree = true
    for k = 1, #levels do
      if left.points[k] ~= firsts[k] or right.points[k] ~= lasts[k] then agree = false end
    end
    return string.format("At t = %.2f: left %s; right %s. The first points of the levels %s the left half.",
      t, list(left.points), list(right.points), agree and "are" or "are NOT")
  end)
  wait_for {
    condition = function() local t = curve_t() return t and math.abs(t - 0.5) > 0.1 end,
    hint = "Drag t away from 0.5 (below 0.4 or above 0.6)",
  }
  say [[
Splitting costs nothing more than evaluating. Splitting again and again gives control polygons that hug the
curve ever closer, which is how curves are drawn and intersected fast.]]
end)

local function bernstein(i)
  local binomial = ({ 1, 3, 3, 1 })[i + 1]
  return function(t) return binomial * t ^ i * (1 - t) ^ (3 - i) end
end

step("The weights", function()
  show(curve)
  say [[
Every level mixes the points of the level before, so the last point is a mix of the control points:
`C(t) = B0(t) P0 + B1(t) P1 + B2(t) P2 + B3(t) P3`. The **B**s are the **Bernstein weights**.]]
  answer {
    "What is B1(0.5), the weight of P1 = (1, 2) in C(0.5)?",
    number = 0.375,
    feedback = function(value)
      if math.abs(value - 0.25) < 1e-3 then
        return "1/4 would make C(0.5) the average of the four points. The curve's point weights them: the middle "
          .. "points get more."
      elseif math.abs(value - 0.125) < 1e-3 then
        return "1/8 is the weight of an end point, P0 or P3, at t = 0.5."
      elseif math.abs(value - 0.5) < 1e-3 then
        return "0.5 is the weight P1 gets in the first level-1 point only; two more steps mix it again."
      end
    end,
    hint = "Run the steps at t = 0.5 with the number 1 in place of P1 and 0 for the others.",
  }
  say "Yes: 3/8. Here are all four weights as t goes from 0 to 1; the line is the view's t. Drag t and watch it."
  local curves = {}
  for i = 0, degree do
    local colour = ({ "blue", "orange", "green", "purple" })[i + 1]
    curves[#curves + 1] = { label = "B" .. i, fn = bernstein(i), colour = colour }
  end
  plot {
    title = "Bernstein weights", x = { 0, 1 }, y = { 0, 1 }, curves = curves,
    marker = function() return curve_t() end,
  }
  answer {
    "Drag t and watch B1. At which t is B1 largest, so that P1 pulls hardest?",
    number = 1 / 3,
    tolerance = 0.02,
    feedback = function(value)
      if math.abs(value - 0.5) < 0.02 then
        return "At 0.5 B1 and B2 are equal: it is where they cross, not where B1 is at its top."
      elseif math.abs(value - 2 / 3) < 0.02 then
        return "Around 2/3 is where B2 is largest: B1 is the weight of P1, nearer the start."
      elseif value < 0.02 then
        return "At t = 0 all the weight is B0: the curve is at P0."
      end
    end,
    hint = "Put the marker on the top of the orange curve: the legend gives each weight at the marker.",
  }
  say [[
Yes, t = 1/3. The weights are never negative and add up to 1 at every t, so the curve stays inside the
control polygon's convex hull.]]
end)

step("The tangent", function()
  show(curve)
  say [[
The curve's **derivative** C'(t) is its velocity: the direction the point moves as t grows, and how fast.]]
  answer {
    "At t = 0 the curve leaves P0 = (0, 0) towards P1 = (1, 2). What is C'(0)? Give x, y.",
    point = { 3, 6 },
    feedback = function(p)
      if near(p, 1, 2) then
        return "(1, 2) = P1 - P0 has the right direction, but the speed is n times it, and a cubic has n = 3."
      elseif near(p, 2, 4) then
        return "(2, 4) takes the factor as 2: the factor is the degree n, the number of steps, 3 for a cubic."
      elseif near(p, 4, 8) then
        return "(4, 8) takes the factor as 4, the number of control points: the factor is the degree, 3."
      elseif near(p, -3, -6) or near(p, -1, -2) then
        return pt(p) .. " points from P1 back to P0: the curve moves away from P0, towards P1."
      end
    end,
    hint = "The direction is along the first side of the control polygon; the length is a multiple of it.",
  }
  say [[
Yes: **C'(0) = 3 (P1 - P0)**. At any t the levels give it too: the last step goes from the first level-2 point to
the second, so **C'(t) = 3 (second - first level-2 point)**, and the segment between them **touches the curve at
C(t)**: it is the tangent. The view now draws it as an arrow from C(t), **C'(t) / 3**, as long as that segment
(**Tangent** in the curve view shows or hides it).]]
  view { curve = true, tangent = true }
  local ends, middle = speed(curve, 0), speed(curve, 0.5)
  choose {
    "Before you drag t: where is the arrow longest, where the point moves fastest?",
    options = { "at the ends, t = 0 and 1", "in the middle, t = 0.5", "the same length everywhere" },
    answer = "at the ends, t = 0 and 1",
    feedback = {
      ["in the middle, t = 0.5"] = string.format("At t = 0.5 the arrow is shortest: |C'(0.5)| = %.2f against %.2f "
        .. "at the ends, the level-2 points %.2f apart there against %.2f at t = 0.", middle, ends, middle / degree,
        ends / degree),
      ["the same length everywhere"] = "Only a curve whose control points are evenly spaced on a line moves at one "
        .. "speed. Drag t and watch the arrow: it shrinks towards the middle.",
      ["at the ends, t = 0 and 1"] = string.format("Yes: |C'(0)| = 3 |P1 - P0| = %.2f, and |C'(0.5)| = %.2f only.",
        ends, middle),
    },
    hint = "The arrow is C'(t) / 3, the last step's segment. At t = 0 it is P1 - P0.",
  }
  say "Drag t and watch the arrow; press **E** twice to draw level 2 and see the arrow lie on its segment."
  live(function()
    local t = curve_t()
    if not t then return "(the curve view is not on screen)" end
    local c = on_screen()
    local levels = c:levels(t)
    if #levels < 3 then return "(the curve needs 3 control points or more)" end
    local two = levels[#levels - 1]
    local d = (two[2] - two[1]) * (#c.points - 1)
    return string.format("At t = %.2f the level-%d points are %s and %s: C'(t) = %d x their difference = %s.",
      t, #levels - 2, pt(two[1]), pt(two[2]), #c.points - 1, pt(d))
  end)
  wait_for { key = "E", hint = "Press E to draw the next level" }
end)

step("The hodograph", function()
  local hodo = meshedit.curve(hodograph_points(curve.points))
  show(hodo)
  camera "fit"
  say("The derivative of a cubic is itself a Bézier curve, the **hodograph**, of degree 2. Its control points are "
    .. "3 times the differences of the cubic's: 3 (P1 - P0), 3 (P2 - P1), 3 (P3 - P2) = **" .. list(hodo.points)
    .. "**. They are on screen now (the view calls its point C(t): here that is the hodograph's point, C'(t)).")
  local at = hodo:evaluate(0.25)
  local swapped = hodo:evaluate(0.75)
  local level1 = hodo:levels(0.25)[2]
  answer {
    "What is C'(0.25), the hodograph's point at t = 0.25? Give x, y.",
    point = { at.x, at.y },
    feedback = function(p)
      if near(p, 6, 0) then
        return "(6, 0) is the hodograph's middle control point: its curve only passes through the first and last."
      elseif near(p, swapped.x, swapped.y) then
        return pt(p) .. " is C'(0.75): t and 1 - t swapped."
      elseif near(p, level1[1].x, level1[1].y) or near(p, level1[2].x, level1[2].y) then
        return pt(p) .. " is a level-1 point of the hodograph: one more step gives its point."
      elseif near(p, at.x / 3, at.y / 3) then
        return pt(p) .. " is the difference of the cubic's level-2 points, without the factor 3."
      elseif near(p, 4, 0) then
        return "(4, 0) = P3 - P0 is the average velocity over the whole curve, not the velocity at t = 0.25."
      end
    end,
    hint = "de Casteljau on the three hodograph points at t = 0.25: two steps.",
  }
  say("Yes: C'(0.25) = " .. pt(at) .. ", up and to the right, as the curve climbs. Press **E** twice to see the "
    .. "hodograph's own levels end in it, and drag t: the live line is C'(t) at the view's t. At t = 0.5 it is "
    .. "horizontal, (4.5, 0): the top of the arch.")
  live(function()
    local t = curve_t()
    if not t then return "(the curve view is not on screen)" end
    return string.format("t = %.2f: C'(t) = %s", t, pt(on_screen():evaluate(t)))
  end)
  wait_for { key = "E", hint = "Press E to draw the next level" }
end)

step("Your turn", function()
  show(curve)
  say [[
# Your code

Open `scripts/student/curve.lua` and write `evaluate_step(points, t)`: given the points of one level, return
the next level, one point fewer. The lesson runs it on this curve's control points at t = 0.25 each time you
save the file, and compares it with the reference's level 1. A point that is missing or in the wrong place is
named, and a Lua error shows its `curve.lua:LINE`.]]
  your_turn {
    exercise = "curve",
    points = curve.points,
    t = 0.25,
    hint = "Point i of the next level is (1 - t) * points[i] + t * points[i + 1], for i = 1 .. #points - 1.",
  }
  say [[
Your `evaluate_step` gives the reference's level 1. Now watch it make every level: tick **mine** in the curve
view (or press **M**) and press **E**. Each level is made by your function from the level before and checked
against the reference; drag the points or move t to try other inputs. A level that differs is drawn in
vermillion over the reference's.

The grading suite runs the same checks from a terminal:

    meshedit grade --suite tests/grading/suites/curve.lua --submission scripts/student]]
  wait_for { key = "M", hint = "Press M to draw your evaluate_step's levels in the curve view" }
end)
