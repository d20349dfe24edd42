-- A buggy student curve.lua (test fixture): the lerp weights are swapped (t goes with the left point).
function evaluate_step(points, t)
  local next_level = {}
  for i = 1, #points - 1 do
    next_level[i] = points[i] * t + points[i + 1] * (1 - t)
  end
  return next_level
end
