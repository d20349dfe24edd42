-- A buggy hodograph (test fixture for scripts/exercises/hodograph.lua): the differences of the control points,
-- without the factor n.
function hodograph(points)
  local result = {}
  for i = 1, #points - 1 do
    result[i] = points[i + 1] - points[i]
  end
  return result
end

return { hodograph = hodograph }
