-- An exercise defined in Lua alone, on a Bézier patch instead of a mesh: the unit normal of a bicubic patch. The
-- student's patch_normal(patch, u, v) gets the patch as the patch exercise does ({points = 16 vec3}, row by row:
-- patch.points[4 * row + col + 1]) and returns the unit normal at (u, v), the cross product of the u and v tangents,
-- normalised. The Exercises tab lists it (its input and both results as text tables), a lesson asks for it with
-- your_turn{ exercise = "patch_normal", patch = ..., args = {u, v} }, and it grades as a suite of its own:
--   meshedit grade --suite scripts/exercises/patch_normal.lua --submission scripts/student
-- As in the patch exercise, u runs along each row and v down the column of the rows' results. The reference works
-- with de Casteljau and the hodograph: the u tangent is the column (at v) of each row's derivative (at u), the v
-- tangent the derivative (at v) of the column of the rows (at u). The diagnoses name the unnormalised normal and the
-- cross product taken the other way round.

-- De Casteljau to the end: the point at t of the curve with these control points.
local function evaluate(points, t)
  local level = points
  while #level > 1 do
    local next_level = {}
    for i = 1, #level - 1 do next_level[i] = level[i] * (1 - t) + level[i + 1] * t end
    level = next_level
  end
  return level[1]
end

-- The control points of the derivative of the curve with these control points: n * (P[i+1] - P[i]).
local function derivative(points)
  local n, out = #points - 1, {}
  for i = 1, n do out[i] = (points[i + 1] - points[i]) * n end
  return out
end

-- The u and v tangents of the patch at (u, v).
local function tangents(patch, u, v)
  local p = patch.points
  local rows, row_tangents = {}, {}
  for r = 0, 3 do
    local row = { p[4 * r + 1], p[4 * r + 2], p[4 * r + 3], p[4 * r + 4] }
    rows[r + 1] = evaluate(row, u)
    row_tangents[r + 1] = evaluate(derivative(row), u)
  end
  return evaluate(row_tangents, v), evaluate(derivative(rows), v)
end

-- A patch over the unit square's grid, scaled by `size`, with a height per control point (16, row by row).
local function grid(size, heights)
  local points = {}
  for r = 0, 3 do
    for c = 0, 3 do points[#points + 1] = { c * size / 3, r * size / 3, heights[4 * r + c + 1] } end
  end
  return points
end

local function is_point(p) return type(p) == "table" and type(p.x) == "number" end
local function near(p, q) return (p - q):length() < 1e-9 end
local function fmt(p) return string.format("(%.4g, %.4g, %.4g)", p.x, p.y, p.z) end

exercise {
  name = "patch_normal",
  title = "Extra: the normal of a Bezier patch",
  file = "patch_normal.lua",
  call = "patch_normal",
  signature = "patch_normal(patch, u, v) -> the unit normal at (u, v), S_u x S_v normalised",
  takes = "patch",
  reference = function(patch, u, v)
    local su, sv = tangents(patch, u, v)
    return su:cross(sv):normalized()
  end,
  hint = "S_u: take each row's derivative (3 * (P[i+1] - P[i]), three points), evaluate it at u, then evaluate the "
    .. "column of the four results at v. S_v: evaluate each row at u, take the derivative of that column of four "
    .. "points, evaluate it at v. The normal is S_u:cross(S_v), divided by its length.",
  diagnose = function(run)
    local mine, want = run.mine, run.reference
    if not is_point(mine) or not is_point(want) then return nil end
    local su, sv = tangents(run.input, run.args[1], run.args[2])
    local length = mine:length()
    local out = {}
    if length > 0 and near(mine / length, -want) then
      out[#out + 1] = "your normal " .. fmt(mine) .. " points the other way: it is along S_v x S_u; the normal is "
        .. "S_u:cross(S_v), the u tangent first"
    end
    if length > 0 and math.abs(length - 1) > 1e-9 and (near(mine / length, want) or near(mine / length, -want)) then
      local hint = near(mine, su:cross(sv)) and " (it is S_u x S_v itself)" or ""
      out[#out + 1] = "your normal has length " .. string.format("%.6g", length) .. hint .. "; a normal is a unit "
        .. "vector: divide the cross product by its length (n / n:length(), or n:normalized())"
    end
    return out
  end,
  fixtures = {
    { name = "a flat patch, at its middle", patch = grid(3, { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 }),
      args = { 0.5, 0.5 }, points = 1 },
    { name = "a bump, off its middle", patch = grid(3, { 0, 0, 0, 0, 0, 2, 2, 0, 0, 2, 2, 0, 0, 0, 0, 0 }),
      args = { 0.3, 0.7 }, points = 2 },
    { name = "a saddle, near a corner", patch = grid(2, { 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 1 }),
      args = { 0.1, 0.25 }, points = 2 },
    { name = "a slanted, sheared patch", patch = {
      { 0, 0, 0 }, { 1, 0.2, 0.5 }, { 2, 0.4, 1 }, { 3, 0.6, 1.5 },
      { 0.3, 1, 0 }, { 1.3, 1.2, 0.8 }, { 2.3, 1.4, 1.2 }, { 3.3, 1.6, 1.5 },
      { 0.6, 2, 0.2 }, { 1.6, 2.2, 0.9 }, { 2.6, 2.4, 1.4 }, { 3.6, 2.6, 1.8 },
      { 0.9, 3, 0.1 }, { 1.9, 3.2, 0.6 }, { 2.9, 3.4, 1.1 }, { 3.9, 3.6, 1.6 } },
      args = { 0.6, 0.4 }, points = 1 },
  },
}
