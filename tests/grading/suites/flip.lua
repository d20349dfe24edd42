-- Grading suite for part 4, flip_edge(mesh, e) in flip.lua (issue-4 contract: returns e, or nil when e cannot
-- be flipped). Every result is compared with the core's flip (mesh:flip, run in the suite's own state) up to
-- renumbering, after validate(); refusals must leave every pointer as it was.
suite{ name = "flip_edge", files = {"flip.lua"}, time_limit = 5, memory_mb = 64 }

-- Flips edge `id` of a copy with the student's code and of another copy with the reference, and checks both.
local function check_flip(student, expect, mesh, id, what)
  local mine, reference = mesh:copy(), mesh:copy()
  local result = student.flip_edge(mine, mine:edge(id))
  reference:flip(reference:edge(id))
  local ok = expect.equal(result, mine:edge(id), what .. ": flip_edge returns the edge")
  if not expect.valid(mine, what) then return false end
  return expect.mesh_equal(mine, reference, 1e-12, what) and ok
end

test{ number = "4.1", name = "flip the middle edge of two triangles", points = 2,
  run = function(student, expect)
    check_flip(student, expect, meshedit.grid(1, 1), 2, "flip_edge(e2) of a 1x1 grid")
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
        local mine = grid:copy()
        local what = "flip_edge(" .. tostring(e) .. ") on the boundary of a 2x2 grid"
        expect.is_nil(student.flip_edge(mine, mine:edge(e.id)), what .. " returns nil")
        expect.same_pointers(mine, grid, 0, what .. " changes nothing")
      end
    end
  end }

test{ number = "4.4", name = "flipping an edge twice gives back the same triangles", points = 2,
  visibility = "after_due_date",
  run = function(student, expect)
    local ico = meshedit.icosahedron()
    for _, id in ipairs({0, 7, 13, 29}) do
      local mine = ico:copy()
      student.flip_edge(mine, mine:edge(id))
      student.flip_edge(mine, mine:edge(id))
      if not expect.valid(mine, "after flipping e" .. id .. " twice") then return end
      expect.mesh_equal(mine, ico, 1e-12, "after flipping e" .. id .. " twice")
    end
  end }

test{ number = "4.5", name = "forty flips in a row on an icosahedron", points = 2, visibility = "hidden",
  run = function(student, expect)
    local mine, reference = meshedit.icosahedron(), meshedit.icosahedron()
    for step = 1, 40 do
      local id = (step * 7) % 30
      -- Only flips the reference makes: a flip that would duplicate an edge is not part of the exercise.
      if reference:flip(reference:edge(id)) then
        student.flip_edge(mine, mine:edge(id))
        if not expect.valid(mine, "after flip " .. step .. " (e" .. id .. ")") then return end
      end
    end
    expect.mesh_equal(mine, reference, 1e-12, "after forty flips")
  end }
