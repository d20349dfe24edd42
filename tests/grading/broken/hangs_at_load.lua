-- A student flip.lua whose top level never finishes (a debugging loop left in).
local count = 0
while count >= 0 do count = count + 1 end
function flip_edge(mesh, e) return e end
