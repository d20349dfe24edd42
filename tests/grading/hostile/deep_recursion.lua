-- Hostile fixture (split.lua): recursion without end, in Lua and through a metamethod (the C stack).
local function down(n)
  return 1 + down(n + 1)
end
function split_edge(mesh, e)
  pcall(down, 1)
  local abyss = setmetatable({}, {__index = function(t, k) return t[k + 1] end})
  return abyss[1]
end
