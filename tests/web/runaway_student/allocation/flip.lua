-- A student's flip.lua whose flip_edge allocates without end: Run mine must stop it at the memory limit, with the
-- line it was on, and the window (or the page) must answer afterwards. tests/web/student_runaway_allocation.txt.
function flip_edge(mesh, e)
  local kept = {}
  while true do kept[#kept + 1] = {} end
end

return { flip_edge = flip_edge }
