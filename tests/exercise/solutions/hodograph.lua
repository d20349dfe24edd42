-- A correct solution of scripts/student/hodograph.lua: n * (P[i+1] - P[i]) for i = 1, ..., n.
function hodograph(points)
  local n = #points - 1
  local result = {}
  for i = 1, n do
    result[i] = n * (points[i + 1] - points[i])
  end
  return result
end

return { hodograph = hodograph }
