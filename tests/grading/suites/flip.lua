-- Grading suite for part 4, flip_edge(mesh, e) in flip.lua (returns e, or nil when e cannot be flipped). Every
-- flip is checked by expect.exercise, the window's own check: the core's flip as the reference, validate(), the
-- comparison up to renumbering, and the window's diagnosis (the pointer that breaks a face cycle, a vertex or face
-- left pointing at a moved halfedge, a boundary edge flipped, and on a big mesh a flip that touches far more than the
-- two triangles at its edge); a refusal must change nothing and return nil.
suite{ name = "flip_edge", files = {"flip.lua"}, time_limit = 5, memory_mb = 64 }

-- The edge of `mesh` from the vertex at (x, y) to the one at (x + 1, y + 1): a grid's diagonal, found by where it is.
local function diagonal_at(mesh, x, y)
  for e in mesh:edges() do
    local p, q = e.halfedge.vertex.position, e.halfedge.twin.vertex.position
    if p.x > q.x then p, q = q, p end
    if p.x == x and p.y == y and q.x == x + 1 and q.y == y + 1 then return e end
  end
end

-- 11200 triangles: a flip_edge that loops over the mesh touches thousands of elements there, where a flip changes a
-- handful (the window's locality bound, engine/exercise/exercise_locality.h).
local big = meshedit.grid(80, 70)
local big_edge = diagonal_at(big, 40, 35)

-- Flips edge `id` of a copy of `mesh` with the student's code and checks it as the window does.
local function check_flip(student, expect, mesh, id, what)
  local mine = mesh:copy()
  local result = student.flip_edge(mine, mine:edge(id))
  return expect.exercise("flip_edge", {mesh = mesh, edge = id}, result, mine, what)
end

-- Flips edge `id` of `mine` in place, checking this one flip against the reference on the mesh as it was.
local function flip_in_place(student, expect, mine, id, what)
  local before = mine:copy()
  local result = student.flip_edge(mine, mine:edge(id))
  return expect.exercise("flip_edge", {mesh = before, edge = id}, result, mine, what)
end

test{ number = "4.1", name = "flip the middle edge of two triangles, then one amid 11200", points = 2,
  run = function(student, expect)
    if check_flip(student, expect, meshedit.grid(1, 1), 2, "flip_edge(e2) of a 1x1 grid") then
      check_flip(student, expect, big, big_edge.id,
                 "flip_edge(" .. tostring(big_edge) .. ") in the middle of an 80x70 grid (11200 triangles)")
    end
  end }

test{ number = "4.2", name = "flip each edge of a cube (one at a time)", points = 3, partial = true,
  run = function(student, expect)
    local cube = meshedit.cube()
    for e in cube:edges() do check_flip(student, expect, cube, e.id, "flip_edge(" .. tostring(e) .. ") of a cube") end
  end }

test{ number = "4.3", name = "boundary edges are refused and nothing changes", points = 1,
  run = function(student, expect)
    local grid = meshedit.grid(2, 2)
    for e in grid:edges() do
      if e:is_boundary() then
        check_flip(student, expect, grid, e.id, "flip_edge(" .. tostring(e) .. ") on the boundary of a 2x2 grid")
      end
    end
  end }

test{ number = "4.4", name = "flipping an edge twice gives back the same triangles", points = 2,
  visibility = "after_due_date",
  run = function(student, expect)
    local ico = meshedit.icosahedron()
    for _, id in ipairs({0, 7, 13, 29}) do
      local mine = ico:copy()
      for k = 1, 2 do
        if not flip_in_place(student, expect, mine, id, "flip " .. k .. " of e" .. id) then return end
      end
      expect.mesh_equal(mine, ico, 1e-12, "after flipping e" .. id .. " twice")
    end
  end }

test{ number = "4.5", name = "forty flips in a row on an icosahedron", points = 2, visibility = "after_published",
  run = function(student, expect)
    local mine, reference = meshedit.icosahedron(), meshedit.icosahedron()
    for step = 1, 40 do
      local id = (step * 7) % 30
      -- Only flips the reference makes: a flip that would duplicate an edge is not part of the exercise. A flip
      -- keeps every id, so e<id> is the same edge in both meshes.
      if reference:flip(reference:edge(id)) then
        if not flip_in_place(student, expect, mine, id, "flip " .. step .. " (e" .. id .. ")") then return end
      end
    end
    expect.mesh_equal(mine, reference, 1e-12, "after forty flips")
  end }
