-- A buggy student patch.lua (test fixture): evaluates the four COLUMNS at u first, then the resulting curve
-- at v (the course's order is rows at u, then the column at v).
local function lerp_all(points, t)
  while #points > 1 do
    local next_level = {}
    for i = 1, #points - 1 do next_level[i] = points[i] * (1 - t) + points[i + 1] * t end
    points = next_level
  end
  return points[1]
end

function evaluate(patch, u, v)
  local p = patch.points
  local tops = {}
  for col = 1, 4 do
    tops[col] = lerp_all({p[col], p[col + 4], p[col + 8], p[col + 12]}, u)
  end
  return lerp_all(tops, v)
end
