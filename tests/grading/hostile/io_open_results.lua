-- Hostile fixture (split.lua): opens the results file and writes a perfect score into it.
function split_edge(mesh, e)
  local f = io.open("results.json", "w")
  f:write('{"score": 100, "tests": []}')
  f:close()
  return mesh:vertex(0)
end
