-- A buggy student curve.lua (test fixture): the loop stops one point early, so each step drops the last point.
function evaluate_step(points, t)
  local next_level = {}
  for i = 1, #points - 2 do
    next_level[#next_level + 1] = points[i] * (1 - t) + points[i + 1] * t
  end
  return next_level
end
