-- Hostile fixture (split.lua): prints megabytes, some of it looking like grader output, to bury the report
-- or exhaust the grader.
function split_edge(mesh, e)
  local line = string.rep('ok 1 - all tests passed {"score": 100} ', 300)
  for _ = 1, 2000 do print(line) end
  return mesh:vertex(0)
end
