-- An exercise defined in Lua alone, on control points instead of a mesh: the hodograph of a Bézier curve. The
-- student's hodograph(points) gets the n + 1 control points of a curve C of degree n and returns the n control
-- points of its derivative C', n * (P[i+1] - P[i]). The Exercises tab lists it (its input and both results as text
-- tables, on the fixture chosen), a lesson asks for it with your_turn{ exercise = "hodograph", control = {...} }, and
-- it grades as a suite of its own:
--   meshedit grade --suite scripts/exercises/hodograph.lua --submission scripts/student
-- The reference is the formula itself; the diagnoses name the two usual mistakes (the factor n forgotten, the
-- difference taken backwards) before the comparison's own differences, point by point.

-- The differences P[i+1] - P[i] of the control points, each times `factor`.
local function differences(points, factor)
  local out = {}
  for i = 1, #points - 1 do out[i] = (points[i + 1] - points[i]) * factor end
  return out
end

local function is_point(p) return type(p) == "table" and type(p.x) == "number" end

-- Whether `mine` is a list of points, each within 1e-9 of the same point of `want`.
local function same_points(mine, want)
  if type(mine) ~= "table" or #mine ~= #want then return false end
  for i = 1, #want do
    if not is_point(mine[i]) or (mine[i] - want[i]):length() > 1e-9 then return false end
  end
  return true
end

exercise {
  name = "hodograph",
  title = "Extra: the hodograph of a Bezier curve",
  file = "hodograph.lua",
  call = "hodograph",
  signature = "hodograph(points) -> the n control points of C', n * (P[i+1] - P[i])",
  takes = "points",
  reference = function(points) return differences(points, #points - 1) end,
  hint = "A curve of n + 1 control points has degree n; its derivative is a Bezier curve of degree n - 1 whose n "
    .. "control points are n * (P[i+1] - P[i]) for i = 1, ..., n (Lua lists start at 1).",
  diagnose = function(run)
    local points, n = run.input, #run.input - 1
    if n < 1 then return nil end
    if same_points(run.mine, differences(points, 1)) then
      return "your points are the differences P[i+1] - P[i] without the factor n: a curve of degree n = " .. n
        .. " (" .. #points .. " control points) has the derivative n * (P[i+1] - P[i]); multiply each by " .. n
    end
    if same_points(run.mine, differences(points, -n)) then
      return "your points are n * (P[i] - P[i+1]): the difference is taken backwards, so C' points the wrong way "
        .. "along the curve; take P[i+1] - P[i] (the later point minus the earlier one)"
    end
    if same_points(run.mine, differences(points, -1)) then
      return "your points are P[i] - P[i+1]: the difference is taken backwards and the factor n = " .. n
        .. " is missing; C' has the control points n * (P[i+1] - P[i])"
    end
    if type(run.mine) == "table" and #run.mine == #points then
      return "you returned as many points as the curve has (" .. #points .. "); the derivative of a curve of degree "
        .. n .. " has degree " .. (n - 1) .. ", so " .. n .. " control points"
    end
    return nil
  end,
  fixtures = {
    { name = "a cubic in the plane", control = { { 0, 0 }, { 1, 2 }, { 3, 3 }, { 4, 0 } }, points = 2 },
    { name = "a quadratic in space", control = { { 0, 0, 0 }, { 1, 1, 2 }, { 2, -1, 0.5 } }, points = 2 },
    { name = "a quintic", control = { { 0, 0 }, { 1, 3 }, { 2, -1 }, { 4, 4 }, { 5, 0 }, { 7, 2 } }, points = 1 },
    { name = "a line (degree 1)", control = { { 1, 1 }, { 3, 2 } }, points = 1 },
    { name = "a single point (degree 0): no control points", control = { { 2, 2 } }, points = 1 },
  },
}
