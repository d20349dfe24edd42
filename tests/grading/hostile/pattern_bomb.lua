-- Hostile fixture (split.lua): a string pattern that backtracks for hours inside one C call, where no Lua
-- hook runs; only killing the process stops it.
function split_edge(mesh, e)
  local text = string.rep("a", 5000)
  return text:find(".-.-.-.-.-b")
end
