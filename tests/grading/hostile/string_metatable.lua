-- Hostile fixture (split.lua): patches the shared string methods so the grader's string.format and
-- ("abc"):upper() answer what the student wants.
pcall(function()
  local methods = getmetatable("").__index
  methods.upper = function() return "pwned" end
  methods.format = function() return "pwned" end
end)
string.format = function() return "pwned" end
function split_edge(mesh, e)
  getmetatable("").__index.rep = function() return "pwned" end
  return mesh:vertex(0)
end
