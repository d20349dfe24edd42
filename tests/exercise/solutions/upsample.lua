-- A correct solution of scripts/student/upsample.lua: the course's five steps, with the boundary rules, using
-- the reference split and flip.

function upsample(mesh)
  local new_position = {}  -- by vertex id
  local is_new = {}        -- by vertex id
  local new_edge = {}      -- by edge id: edges that cut across an original face

  -- 1. original vertices
  for v in mesh:vertices() do
    local p = v.position
    local n, sum, rim = 0, meshedit.vec3(0, 0, 0), {}
    local h = v.halfedge
    repeat
      local q = h.twin.vertex.position
      sum = sum + q
      n = n + 1
      if h.face:is_boundary() or h.twin.face:is_boundary() then rim[#rim + 1] = q end
      h = h.twin.next
    until h == v.halfedge
    if #rim == 0 then
      local u = (n == 3) and 3 / 16 or 3 / (8 * n)
      new_position[v.id] = (1 - n * u) * p + u * sum
    elseif #rim == 2 then
      new_position[v.id] = 0.75 * p + 0.125 * (rim[1] + rim[2])
    else
      new_position[v.id] = p
    end
  end

  -- 2. original edges
  local originals, edge_position = {}, {}
  for e in mesh:edges() do
    originals[#originals + 1] = e
    local h = e.halfedge
    local t = h.twin
    local a, b = h.vertex.position, t.vertex.position
    if h.face:is_boundary() or t.face:is_boundary() then
      edge_position[e.id] = 0.5 * (a + b)
    else
      local c = h.next.next.vertex.position
      local d = t.next.next.vertex.position
      edge_position[e.id] = 3 / 8 * (a + b) + 1 / 8 * (c + d)
    end
  end

  -- 3. split the original edges only
  for _, e in ipairs(originals) do
    local a, b = e.halfedge.vertex, e.halfedge.twin.vertex
    local m = mesh:split(e)
    is_new[m.id] = true
    new_position[m.id] = edge_position[e.id]
    local h = m.halfedge
    repeat
      local other = h.twin.vertex
      if other ~= a and other ~= b then new_edge[h.edge.id] = true end
      h = h.twin.next
    until h == m.halfedge
  end

  -- 4. flip new edges between an old and a new vertex
  for e in mesh:edges() do
    if new_edge[e.id] then
      local x, y = e.halfedge.vertex, e.halfedge.twin.vertex
      if (is_new[x.id] == true) ~= (is_new[y.id] == true) then mesh:flip(e) end
    end
  end

  -- 5. move everything
  for v in mesh:vertices() do
    v.position = new_position[v.id]
  end
end

return { upsample = upsample }
