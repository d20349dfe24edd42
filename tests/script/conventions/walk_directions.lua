-- The walk directions of the half-edge mesh, measured on real meshes through the scripting API, printed one
-- fact a line for conventions_test.cpp to hold the templates, lessons and docs to:
--   vertex walk: clockwise            h = h.twin.next around every vertex of meshedit.cube(), seen from outside
--   face walk: counter-clockwise      h = h.next around every face of the cube, seen from outside
--   split interior: a, c, b, d        the far ends of m.halfedge, m.halfedge.twin.next, ... after m = split(e)
--   split boundary: a, c, b           the same on a boundary edge of meshedit.grid(1, 1)
-- a, b, c, d are the names of engine/core/mesh_ops.h. Any vertex or face that turns the other way, or turns
-- both ways, is an error (exit status 1).

-- "clockwise" or "counter-clockwise": the sense of the turn from direction u to direction w, seen from the
-- side `outward` points to. A turn with no sense (parallel directions) is an error.
local function turn(u, w, outward, where)
  local s = u:cross(w):dot(outward)
  if s == 0 then error(where .. ": two directions in a row are parallel") end
  return s > 0 and "counter-clockwise" or "clockwise"
end

-- The one sense every step of `senses` has, or an error naming `what`.
local function single(senses, what)
  for _, s in ipairs(senses) do
    if s ~= senses[1] then error(what .. " turns both ways: " .. table.concat(senses, ", ")) end
  end
  return senses[1]
end

local cube = meshedit.cube()  -- centred at the origin: a point's position points outwards

local vertex_sense
for v in cube:vertices() do
  local p, directions = v.position, {}
  local h = v.halfedge
  repeat
    directions[#directions + 1] = h.twin.vertex.position - p
    h = h.twin.next
  until h == v.halfedge
  local senses = {}
  for i = 1, #directions do
    senses[i] = turn(directions[i], directions[i % #directions + 1], p, tostring(v))
  end
  local sense = single(senses, "the walk around " .. tostring(v))
  if vertex_sense and sense ~= vertex_sense then
    error(tostring(v) .. " turns " .. sense .. ", others " .. vertex_sense)
  end
  vertex_sense = sense
end
print("vertex walk: " .. vertex_sense)

local face_sense
for f in cube:faces() do
  local corners = {}
  for w in f:vertices() do corners[#corners + 1] = w.position end
  local centre = (corners[1] + corners[2] + corners[3]) / 3
  local senses = {}
  for i = 1, #corners do
    local j, k = i % #corners + 1, (i + 1) % #corners + 1
    senses[i] = turn(corners[j] - corners[i], corners[k] - corners[j], centre, tostring(f))
  end
  local sense = single(senses, "the walk around " .. tostring(f))
  if face_sense and sense ~= face_sense then error(tostring(f) .. " turns " .. sense .. ", others " .. face_sense) end
  face_sense = sense
end
print("face walk: " .. face_sense)

-- The far ends of the halfedges leaving the new vertex of split(e), in walk order, by mesh_ops.h's names.
local function split_order(mesh, e)
  local h0 = e.halfedge
  if h0.face:is_boundary() then h0 = h0.twin end
  local names = {
    [tostring(h0.vertex)] = "a", [tostring(h0.twin.vertex)] = "b", [tostring(h0.next.next.vertex)] = "c",
  }
  if not h0.twin.face:is_boundary() then names[tostring(h0.twin.next.next.vertex)] = "d" end
  local m = assert(mesh:split(e))
  local order, h = {}, m.halfedge
  repeat
    order[#order + 1] = names[tostring(h.twin.vertex)] or tostring(h.twin.vertex)
    h = h.twin.next
  until h == m.halfedge
  return table.concat(order, ", ")
end

print("split interior: " .. split_order(cube, cube:edge(0)))

local grid = meshedit.grid(1, 1)
local rim
for e in grid:edges() do
  if not rim and e:is_boundary() then rim = e end
end
print("split boundary: " .. split_order(grid, rim))
