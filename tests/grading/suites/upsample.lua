-- Grading suite for part 6, upsample(mesh) in upsample.lua: Loop subdivision in place. Each level is checked by
-- expect.exercise, the window's own check: the core's Loop subdivision with the course's weights as the reference,
-- the comparison up to renumbering, and the window's diagnosis (a wrong weight, named, and one that integer
-- division made 0; edges flipped that were not new, or halves of split edges; new edges left unflipped, counted
-- against the reference's flips, with their likely causes; positions written to the wrong vertices). The reference
-- flip and split are given to the student's code (flip_edge, split_edge, mesh:flip, mesh:split: the window gives
-- upsample the same), so a mistake in parts 4 and 5 is not paid for twice. Partial credit per base test: 20% for a
-- valid mesh, 40% when the element counts are right too, all of it for the right shape. The boundary rules are
-- extra credit in the course: test 6.4 adds its point on top of the base points, all or nothing.
suite{ name = "upsample", files = {"upsample.lua"}, time_limit = 5, memory_mb = 128,
       reference = {"flip_edge", "split_edge"}, allow_api = {"mesh:flip", "mesh:split"} }

local vec3 = meshedit.vec3

-- The share of the points a level that differs from the reference still earns.
local function partial_share(mine, before)
  if not mine:validate() then return 0 end
  local reference = before:copy()
  reference:loop_subdivide()
  local counts = mine:num_vertices() == reference:num_vertices() and mine:num_edges() == reference:num_edges() and
                 mine:num_faces() == reference:num_faces()
  return counts and 0.4 or 0.2
end

local function check(student, expect, mesh, levels, what, all_or_nothing)
  local mine = mesh:copy()
  for level = 1, levels do
    local before = mine:copy()
    student.upsample(mine)
    local label = what .. (levels > 1 and (", level " .. level) or "")
    if not expect.exercise("upsample", {mesh = before}, nil, mine, label) then
      return expect.score(all_or_nothing and 0 or partial_share(mine, before))
    end
  end
  expect.score(1)
end

test{ number = "6.1", name = "a tetrahedron, one level", points = 3,
  run = function(student, expect) check(student, expect, meshedit.tetrahedron(), 1, "tetrahedron") end }

test{ number = "6.2", name = "a cube, one level", points = 3,
  run = function(student, expect) check(student, expect, meshedit.cube(), 1, "cube") end }

test{ number = "6.3", name = "an icosahedron, two levels", points = 2, visibility = "after_due_date",
  run = function(student, expect) check(student, expect, meshedit.icosahedron(), 2, "icosahedron") end }

test{ number = "6.4", name = "a grid with a boundary, one level", points = 1, extra_credit = true,
  visibility = "after_published",
  run = function(student, expect) check(student, expect, meshedit.grid(2, 2), 1, "2x2 grid", true) end }

test{ number = "6.5", name = "an irregular mesh (vertices of degree 3 to 6)", points = 2,
  visibility = "after_published",
  run = function(student, expect)
    local mesh = meshedit.from_polygons(
      {vec3(0, 0, 1), vec3(1, 0, 0), vec3(0, 1, 0), vec3(-1, 0, 0), vec3(0, -1, 0), vec3(0, 0, -1),
        vec3(0.7, 0.7, 0.2)},
      {{1, 2, 7}, {1, 7, 3}, {1, 3, 4}, {1, 4, 5}, {1, 5, 2}, {6, 7, 2}, {6, 3, 7}, {6, 4, 3}, {6, 5, 4}, {6, 2, 5}})
    check(student, expect, mesh, 1, "irregular mesh")
  end }
