-- A buggy hodograph (test fixture for scripts/exercises/hodograph.lua): the factor n is there, but each difference is
-- taken backwards, P[i] - P[i+1].
function hodograph(points)
  local n = #points - 1
  local result = {}
  for i = 1, n do
    result[i] = n * (points[i] - points[i + 1])
  end
  return result
end

return { hodograph = hodograph }
