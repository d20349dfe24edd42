-- A student's flip.lua whose flip_edge calls itself without end: Run mine must stop it when Lua's stack is full, with
-- the line it was on, and the window (or the page) must answer afterwards. tests/web/student_runaway_recursion.txt.
function flip_edge(mesh, e)
  return 1 + flip_edge(mesh, e)
end

return { flip_edge = flip_edge }
