-- Hostile fixture (split.lua): fills memory with big strings, catching each out-of-memory error.
function split_edge(mesh, e)
  local hoard = {}
  while true do
    pcall(function() hoard[#hoard + 1] = string.rep("x", 1 << 22) .. #hoard end)
  end
end
