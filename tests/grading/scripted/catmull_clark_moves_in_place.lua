-- A buggy catmull_clark_level (test fixture): the rules are right, but each vertex is moved as soon as its new
-- position is known, so the edge vertices and the old vertices read neighbours that have already moved.
function catmull_clark_level(mesh)
  for f in mesh:faces() do
    if f:degree() == 3 then return nil end
  end
  local old = {}
  for v in mesh:vertices() do old[v.id] = true end
  assert(mesh:linear_subdivide())
  for v in mesh:vertices() do
    local p = v.position
    local neighbours, sum, old_neighbour = 0, meshedit.vec3(0, 0, 0), false
    for w in v:neighbors() do
      neighbours, sum = neighbours + 1, sum + w.position
      old_neighbour = old_neighbour or old[w.id] == true
    end
    if old[v.id] and v:is_boundary() then
      local along = meshedit.vec3(0, 0, 0)
      for h in v:halfedges() do
        if h.face:is_boundary() or h.twin.face:is_boundary() then along = along + h.twin.vertex.position end
      end
      v.position = p * 0.5 + along * 0.25
    elseif old[v.id] then
      local faces = meshedit.vec3(0, 0, 0)
      for h in v:halfedges() do faces = faces + h.next.next.vertex.position end
      local n = neighbours
      v.position = (faces / n + (sum / n) * 2 + p * (n - 3)) / n
    elseif old_neighbour and not v:is_boundary() then
      v.position = sum / neighbours
    end
  end
end
