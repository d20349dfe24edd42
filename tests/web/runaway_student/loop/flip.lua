-- A student's flip.lua whose flip_edge never returns: Run mine must stop it at the window's deadline, with the
-- line it was on, and the window (or the page) must answer afterwards. tests/web/student_runaway_loop.txt.
function flip_edge(mesh, e)
  while true do end
end

return { flip_edge = flip_edge }
