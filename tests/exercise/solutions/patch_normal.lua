-- A correct solution of scripts/student/patch_normal.lua: S_u x S_v at (u, v), normalised.

local function evaluate_1d(points, t)
  while #points > 1 do
    local step = {}
    for i = 1, #points - 1 do
      step[i] = (1 - t) * points[i] + t * points[i + 1]
    end
    points = step
  end
  return points[1]
end

local function derivative(points)
  local n, result = #points - 1, {}
  for i = 1, n do
    result[i] = n * (points[i + 1] - points[i])
  end
  return result
end

function patch_normal(patch, u, v)
  local p = patch.points
  local column, column_of_tangents = {}, {}
  for row = 0, 3 do
    local b = 4 * row
    local points = { p[b + 1], p[b + 2], p[b + 3], p[b + 4] }
    column[row + 1] = evaluate_1d(points, u)
    column_of_tangents[row + 1] = evaluate_1d(derivative(points), u)
  end
  local su = evaluate_1d(column_of_tangents, v)
  local sv = evaluate_1d(derivative(column), v)
  return su:cross(sv):normalized()
end

return { patch_normal = patch_normal }
