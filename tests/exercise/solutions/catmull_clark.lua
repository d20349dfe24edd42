-- A correct catmull_clark_level (scripts/exercises/catmull_clark.lua): linear subdivision makes the quads, then
-- every vertex moves by Catmull-Clark's rules read from its neighbours in the refined mesh, all computed first.
function catmull_clark_level(mesh)
  for f in mesh:faces() do
    if f:degree() == 3 then return nil end
  end
  local old = {}
  for v in mesh:vertices() do old[v.id] = true end
  assert(mesh:linear_subdivide())

  local new_position = {}
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
      new_position[v.id] = p * 0.5 + along * 0.25
    elseif old[v.id] then
      local faces = meshedit.vec3(0, 0, 0)
      for h in v:halfedges() do faces = faces + h.next.next.vertex.position end
      local n = neighbours
      new_position[v.id] = (faces / n + (sum / n) * 2 + p * (n - 3)) / n
    elseif old_neighbour and not v:is_boundary() then
      new_position[v.id] = sum / neighbours
    else
      new_position[v.id] = p
    end
  end
  for v in mesh:vertices() do v.position = new_position[v.id] end
end

return { catmull_clark_level = catmull_clark_level }
