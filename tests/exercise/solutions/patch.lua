-- A correct solution of scripts/student/patch.lua: rows at u, then the column at v.

local function evaluate_step(points, t)
  local result = {}
  for i = 1, #points - 1 do
    result[i] = (1 - t) * points[i] + t * points[i + 1]
  end
  return result
end

local function evaluate_1d(points, t)
  while #points > 1 do
    points = evaluate_step(points, t)
  end
  return points[1]
end

function evaluate(patch, u, v)
  local p = patch.points
  local column = {}
  for row = 0, 3 do
    local base = 4 * row
    column[row + 1] = evaluate_1d({ p[base + 1], p[base + 2], p[base + 3], p[base + 4] }, u)
  end
  return evaluate_1d(column, v)
end

return { evaluate = evaluate }
