-- A student flip.lua that runs out of memory while it loads (a precomputed table far too big).
local cache = {}
for i = 1, 1e9 do cache[i] = {i, i, i} end
function flip_edge(mesh, e) return e end
