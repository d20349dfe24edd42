-- Hostile fixture (split.lua): returns a value that would run student code inside the grader (metamethods)
-- or never finish being read (a cycle).
function split_edge(mesh, e)
  local cycle = {}
  cycle.again = cycle
  return setmetatable(cycle, {
    __eq = function() return true end,
    __index = function() while true do end end,
    __tostring = function() while true do end end,
  })
end
