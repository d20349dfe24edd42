-- Grading suite for part 3, vertex_normal(v) in normals.lua: the area-weighted unit normal (the normalised sum of
-- the cross products (p1 - p0) x (p2 - p0) of the faces around v, boundary loops skipped). Each normal is checked
-- by expect.exercise, the window's own check: the core's vertex_normal as the reference, and the window's
-- diagnosis (what a wrong normal is made of: an average of unit normals or angle-weighted normals, a face left out
-- or counted alone, a cross product taken the wrong way round, a missing normalisation, a boundary loop counted as
-- a face, each naming the faces it concerns).
suite{ name = "vertex_normal", files = {"normals.lua"}, time_limit = 5, memory_mb = 64 }

local vec3 = meshedit.vec3
math.randomseed(184)

-- A fan around v0 whose triangles have very different areas: averaging unit normals is visibly wrong here.
local fan = meshedit.from_polygons(
  {vec3(0, 0, 0), vec3(4, 0, 1), vec3(0, 1, 0.2), vec3(-1, 0, 0.1), vec3(0, -3, 2)},
  {{1, 2, 3}, {1, 3, 4}, {1, 4, 5}, {1, 5, 2}})

local bumpy = meshedit.icosahedron()
for v in bumpy:vertices() do v.position = v.position * (0.8 + 0.4 * math.random()) end

-- The student's normal of vertex `id` of a copy of `mesh`, checked as the window checks it.
local function check(student, expect, mesh, id, what)
  local mine = mesh:copy()
  return expect.exercise("vertex_normal", {mesh = mesh, vertex = id}, student.vertex_normal(mine:vertex(id)), mine,
                         what)
end

local function check_all(student, expect, mesh, what)
  for v in mesh:vertices() do check(student, expect, mesh, v.id, what .. ", vertex " .. tostring(v)) end
end

test{ number = "3.1", name = "the vertices of a cube", points = 2, partial = true,
  run = function(student, expect) check_all(student, expect, meshedit.cube(), "cube") end }

test{ number = "3.2", name = "a fan of triangles of very different areas (area weighting)", points = 3,
  run = function(student, expect) check(student, expect, fan, 0, "the centre of the fan v0") end }

test{ number = "3.3", name = "the mesh is not changed", points = 1,
  run = function(student, expect)
    local mesh = meshedit.cube()
    local before = mesh:copy()
    for v in mesh:vertices() do student.vertex_normal(v) end
    expect.same_pointers(mesh, before, 0, "after vertex_normal on every vertex")
  end }

test{ number = "3.4", name = "boundary vertices skip the boundary loop", points = 1, visibility = "after_due_date",
  run = function(student, expect) check_all(student, expect, fan, "the fan (with a boundary)") end }

test{ number = "3.5", name = "a bumpy icosahedron", points = 2, partial = true, visibility = "after_published",
  run = function(student, expect) check_all(student, expect, bumpy, "bumpy icosahedron") end }
