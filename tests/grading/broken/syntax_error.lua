-- A student flip.lua that does not compile (a missing `then`).
function flip_edge(mesh, e)
  local h0 = e.halfedge
  if h0:is_boundary() return nil end
  return e
end
