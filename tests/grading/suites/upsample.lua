-- Grading suite for part 6, upsample(mesh) in upsample.lua: Loop subdivision in place, compared with the
-- core's (mesh:loop_subdivide, the course's weights) up to renumbering. The reference flip and split are
-- given to the student's code (flip_edge, split_edge, mesh:flip, mesh:split), so a mistake in parts 4 and 5
-- is not paid for twice. Partial credit per test: 20% for a valid mesh, 40% when the element counts are right
-- too, all of it for the right shape (every vertex in its place, every face present).
suite{ name = "upsample", files = {"upsample.lua"}, time_limit = 5, memory_mb = 128,
       reference = {"flip_edge", "split_edge"}, allow_api = {"mesh:flip", "mesh:split"} }

local vec3 = meshedit.vec3

local function check(student, expect, mesh, levels, what)
  local mine, reference = mesh:copy(), mesh:copy()
  for level = 1, levels do
    student.upsample(mine)
    reference:loop_subdivide()
    local label = what .. (levels > 1 and (", level " .. level) or "")
    if not expect.valid(mine, label) then return expect.score(0) end
  end
  local label = what .. (levels > 1 and (", " .. levels .. " levels") or "")
  local counts = expect.counts(mine, {vertices = reference:num_vertices(), edges = reference:num_edges(),
                                      faces = reference:num_faces()}, label)
  local shape = expect.mesh_equal(mine, reference, 1e-9, label)
  expect.score(shape and counts and 1 or counts and 0.4 or 0.2)
end

test{ number = "6.1", name = "a tetrahedron, one level", points = 3,
  run = function(student, expect) check(student, expect, meshedit.tetrahedron(), 1, "tetrahedron") end }

test{ number = "6.2", name = "a cube, one level", points = 3,
  run = function(student, expect) check(student, expect, meshedit.cube(), 1, "cube") end }

test{ number = "6.3", name = "an icosahedron, two levels", points = 2, visibility = "after_due_date",
  run = function(student, expect) check(student, expect, meshedit.icosahedron(), 2, "icosahedron") end }

test{ number = "6.4", name = "a grid with a boundary, one level", points = 1, visibility = "hidden",
  run = function(student, expect) check(student, expect, meshedit.grid(2, 2), 1, "2x2 grid") end }

test{ number = "6.5", name = "an irregular mesh (vertices of degree 3 to 6)", points = 2, visibility = "hidden",
  run = function(student, expect)
    local mesh = meshedit.from_polygons(
      {vec3(0, 0, 1), vec3(1, 0, 0), vec3(0, 1, 0), vec3(-1, 0, 0), vec3(0, -1, 0), vec3(0, 0, -1), vec3(0.7, 0.7, 0.2)},
      {{1, 2, 7}, {1, 7, 3}, {1, 3, 4}, {1, 4, 5}, {1, 5, 2}, {6, 7, 2}, {6, 3, 7}, {6, 4, 3}, {6, 5, 4}, {6, 2, 5}})
    check(student, expect, mesh, 1, "irregular mesh")
  end }
