-- Grading suite for part 5, split_edge(mesh, e) in split.lua: returns the new vertex at the midpoint, or nil for
-- an edge beside a non-triangle. Every split is checked by expect.exercise, the window's own check: the core's split
-- as the reference, validate(), the comparison up to renumbering (the ids a split allocates are the student's
-- choice), and the window's diagnosis, which on a big mesh includes a split that touches far more than the two
-- triangles at its edge. Splitting boundary edges is extra credit in the course: test 5.4 adds its point on top of
-- the base points.
suite{ name = "split_edge", files = {"split.lua"}, time_limit = 5, memory_mb = 64 }

local vec3 = meshedit.vec3

-- Splits edge `id` of a copy of `mesh` with the student's code and checks it as the window does.
local function check_split(student, expect, mesh, id, what)
  local mine = mesh:copy()
  local m = student.split_edge(mine, mine:edge(id))
  return expect.exercise("split_edge", {mesh = mesh, edge = id}, m, mine, what), mine
end

local function midpoint(e)
  return (e.halfedge.vertex.position + e.halfedge.twin.vertex.position) * 0.5
end

-- The edge of `mesh` whose midpoint is `p`: edges are chosen by where they are, never by the ids earlier splits
-- happened to allocate.
local function edge_at(mesh, p)
  for e in mesh:edges() do
    if (midpoint(e) - p):length() <= 1e-12 then return e end
  end
end

-- 11200 triangles: a split_edge that loops over the mesh touches thousands of elements there, where a split changes a
-- handful (the window's locality bound, exercise/exercise_locality.h). Its middle diagonal, found by where it is.
local big = meshedit.grid(80, 70)
local big_edge = edge_at(big, vec3(40.5, 35.5, 0))

test{ number = "5.1", name = "split the middle edge of two triangles, then one amid 11200", points = 2,
  run = function(student, expect)
    local right, mine = check_split(student, expect, meshedit.grid(1, 1), 2, "split_edge(e2) of a 1x1 grid")
    expect.counts(mine, {vertices = 5, edges = 8, faces = 4, halfedges = 16}, "after split_edge(e2)")
    if right then
      check_split(student, expect, big, big_edge.id,
                  "split_edge(" .. tostring(big_edge) .. ") in the middle of an 80x70 grid (11200 triangles)")
    end
  end }

test{ number = "5.2", name = "split each edge of a cube (one at a time)", points = 3, partial = true,
  run = function(student, expect)
    local cube = meshedit.cube()
    for e in cube:edges() do check_split(student, expect, cube, e.id, "split_edge(" .. tostring(e) .. ") of a cube") end
  end }

test{ number = "5.3", name = "the new vertex's halfedge runs along the split edge", points = 1,
  visibility = "after_due_date",
  run = function(student, expect)
    local grid = meshedit.grid(1, 1)
    local ends = {grid:edge(2).halfedge.vertex.position, grid:edge(2).halfedge.twin.vertex.position}
    local m = student.split_edge(grid, grid:edge(2))
    if not expect.truthy(m, "split_edge returns the new vertex") then return end
    local far = m.halfedge.twin.vertex.position
    expect.truthy(far == ends[1] or far == ends[2],
      "m.halfedge leads to an end of the split edge, not to " .. tostring(far))
  end }

test{ number = "5.4", name = "boundary edges split only the triangle side", points = 1, partial = true,
  extra_credit = true, visibility = "after_due_date",
  run = function(student, expect)
    local grid = meshedit.grid(2, 2)
    for e in grid:edges() do
      if e:is_boundary() then
        check_split(student, expect, grid, e.id, "split_edge(" .. tostring(e) .. ") on the boundary")
      end
    end
  end }

test{ number = "5.5", name = "twenty splits in a row on an icosahedron", points = 2, visibility = "after_published",
  run = function(student, expect)
    local mine, reference = meshedit.icosahedron(), meshedit.icosahedron()
    for step = 1, 20 do
      -- The reference's edge picks the place; the student's edge there is found by its midpoint.
      local target = reference:edge((step * 11) % reference:num_edges())
      local at = midpoint(target)
      local e = edge_at(mine, at)
      if not expect(e, "split " .. step .. ": your mesh has an edge with its midpoint at " .. tostring(at)) then
        return
      end
      local before = mine:copy()
      local m = student.split_edge(mine, e)
      if not expect.exercise("split_edge", {mesh = before, edge = e.id}, m, mine,
                             "split " .. step .. " (the edge with its midpoint at " .. tostring(at) .. ")") then
        return
      end
      reference:split(target)
    end
    expect.mesh_equal(mine, reference, 1e-12, "after twenty splits")
  end }

test{ number = "5.6", name = "an edge beside a quad is refused", points = 1, visibility = "after_published",
  run = function(student, expect)
    local quads = meshedit.from_polygons({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0), vec3(2, 0, 0),
                                          vec3(2, 1, 0)}, {{1, 2, 3, 4}, {2, 5, 6, 3}})
    for e in quads:edges() do
      if not e:is_boundary() then
        check_split(student, expect, quads, e.id, "split_edge(" .. tostring(e) .. ") between two quads")
      end
    end
  end }
