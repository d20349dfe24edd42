-- Grading suite for part 5, split_edge(mesh, e) in split.lua: returns the new vertex at the midpoint, or nil
-- for an edge beside a non-triangle. Every result is compared with the core's split (mesh:split, in the
-- suite's own state) up to renumbering, after validate().
suite{ name = "split_edge", files = {"split.lua"}, time_limit = 5, memory_mb = 64 }

local vec3 = meshedit.vec3

local function check_split(student, expect, mesh, id, what)
  local mine, reference = mesh:copy(), mesh:copy()
  local m = student.split_edge(mine, mine:edge(id))
  reference:split(reference:edge(id))
  if not expect.truthy(m, what .. ": split_edge returns the new vertex") then return false end
  if not expect.valid(mine, what) then return false end
  return expect.mesh_equal(mine, reference, 1e-12, what)
end

test{ number = "5.1", name = "split the middle edge of two triangles", points = 2,
  run = function(student, expect)
    local grid = meshedit.grid(1, 1)
    local a, b = grid:edge(2).halfedge.vertex.position, grid:edge(2).halfedge.twin.vertex.position
    local mine = grid:copy()
    local m = student.split_edge(mine, mine:edge(2))
    if not expect.truthy(m, "split_edge(e2) returns the new vertex") then return end
    expect.near(m.position, (a + b) * 0.5, 1e-12, "the new vertex is at the midpoint of e2")
    expect.counts(mine, {vertices = 5, edges = 8, faces = 4, halfedges = 16}, "after split_edge(e2)")
    check_split(student, expect, grid, 2, "split_edge(e2) of a 1x1 grid")
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
    expect.truthy(far == ends[1] or far == ends[2], "m.halfedge leads to an end of the split edge, not to " .. tostring(far))
  end }

test{ number = "5.4", name = "boundary edges split only the triangle side", points = 1, partial = true,
  visibility = "after_due_date",
  run = function(student, expect)
    local grid = meshedit.grid(2, 2)
    for e in grid:edges() do
      if e:is_boundary() then check_split(student, expect, grid, e.id, "split_edge(" .. tostring(e) .. ") on the boundary") end
    end
  end }

test{ number = "5.5", name = "twenty splits in a row on an icosahedron", points = 2, visibility = "hidden",
  run = function(student, expect)
    local mine, reference = meshedit.icosahedron(), meshedit.icosahedron()
    for step = 1, 20 do
      local id = (step * 11) % reference:num_edges()
      student.split_edge(mine, mine:edge(id))
      reference:split(reference:edge(id))
      if not expect.valid(mine, "after split " .. step .. " (e" .. id .. ")") then return end
    end
    expect.mesh_equal(mine, reference, 1e-12, "after twenty splits")
  end }

test{ number = "5.6", name = "an edge beside a quad is refused", points = 1, visibility = "hidden",
  run = function(student, expect)
    local quads = meshedit.from_polygons({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0), vec3(2, 0, 0),
                                          vec3(2, 1, 0)}, {{1, 2, 3, 4}, {2, 5, 6, 3}})
    local before = quads:copy()
    for e in quads:edges() do
      if not e:is_boundary() then
        expect.is_nil(student.split_edge(quads, quads:edge(e.id)), "split_edge(" .. tostring(e) .. ") between two quads")
      end
    end
    expect.same_pointers(quads, before, 0, "a refused split changes nothing")
  end }
