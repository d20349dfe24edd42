-- A buggy student upsample.lua (test fixture): the edge weights use integer division (3 // 8 and 1 // 8 are 0 in
-- Lua), so every new vertex of an interior edge goes to (0, 0, 0).
local vec3 = meshedit.vec3

-- The new position of an original vertex (step 1).
local function even_position(v)
  local sum, count, rim = vec3(0, 0, 0), 0, {}
  for q in v:neighbors() do
    sum = sum + q.position
    count = count + 1
  end
  for h in v:halfedges() do
    if h.face:is_boundary() or h.twin.face:is_boundary() then rim[#rim + 1] = h.twin.vertex.position end
  end
  if #rim == 2 then return v.position * 0.75 + (rim[1] + rim[2]) * 0.125 end
  if #rim > 0 then return v.position end
  local u = count == 3 and 3 / 16 or 3 / (8 * count)
  return v.position * (1 - count * u) + sum * u
end

-- The position of the vertex that will split edge e (step 2).
local function odd_position(e)
  local h = e.halfedge
  local a, b = h.vertex.position, h.twin.vertex.position
  if h.face:is_boundary() or h.twin.face:is_boundary() then return (a + b) * 0.5 end
  local c, d = h.next.next.vertex.position, h.twin.next.next.vertex.position
  return (a + b) * (3 // 8) + (c + d) * (1 // 8)
end

function upsample(mesh)
  local position, fresh_vertex, fresh_edge = {}, {}, {}
  for v in mesh:vertices() do position[v.id] = even_position(v) end
  local originals = {}
  for e in mesh:edges() do
    originals[#originals + 1] = {edge = e, at = odd_position(e), a = e.halfedge.vertex.id, b = e.halfedge.twin.vertex.id}
  end
  for _, o in ipairs(originals) do
    local m = mesh:split(o.edge)
    fresh_vertex[m.id] = true
    position[m.id] = o.at
    for h in m:halfedges() do
      local far = h.twin.vertex.id
      if far ~= o.a and far ~= o.b then fresh_edge[h.edge.id] = true end
    end
  end
  for e in mesh:edges() do
    local x, y = e.halfedge.vertex.id, e.halfedge.twin.vertex.id
    if fresh_edge[e.id] and (fresh_vertex[x] == true) ~= (fresh_vertex[y] == true) then mesh:flip(e) end
  end
  for v in mesh:vertices() do v.position = position[v.id] end
end

return { upsample = upsample }
