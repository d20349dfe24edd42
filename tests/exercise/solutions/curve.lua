-- A correct solution of scripts/student/curve.lua, written the way a careful student would (tests use it to
-- check that the checker accepts right answers bit for bit).

function evaluate_step(points, t)
  local result = {}
  for i = 1, #points - 1 do
    result[i] = (1 - t) * points[i] + t * points[i + 1]
  end
  return result
end

return { evaluate_step = evaluate_step }
