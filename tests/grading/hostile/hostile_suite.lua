-- The suite every hostile submission is graded with (tests/grade/hostile_test.cpp). Each submission is a
-- correct flip.lua (../students/flip_correct.lua) plus one hostile split.lua from this folder; both files load
-- for every test, so whatever a hostile file does when it loads happens before every test.
-- Tests 1 and 3 must keep their full points whatever split.lua does; test 2 (calling split_edge, where
-- each attack lives) must score 0 and say what happened. Limits are small so the whole file runs quickly.
suite{ name = "hostile", files = {"flip.lua", "split.lua"}, time_limit = 0.5, memory_mb = 32, output_kb = 4 }

-- Not readable by student code: it would be the proof an attack read this file.
local SECRET = "the suite's secret: 7c1e9b"

test{ number = "1", name = "flip every edge of a cube", points = 2,
  run = function(student, expect)
    local cube = meshedit.cube()
    for e in cube:edges() do
      local mine, reference = cube:copy(), cube:copy()
      expect.equal(student.flip_edge(mine, mine:edge(e.id)), mine:edge(e.id), "flip_edge returns the edge")
      reference:flip(reference:edge(e.id))
      expect.mesh_equal(mine, reference, 1e-12, "flip " .. tostring(e))
    end
    -- Nothing the submission did reaches the suite's own libraries.
    expect.equal(("abc"):upper(), "ABC", "string methods in the suite")
    expect.equal(string.format("%d-%s", 7, SECRET:sub(1, 3)), "7-the", "string.format in the suite")
    expect.equal(type(expect.equal), "function", "expect in the suite")
  end }

test{ number = "2", name = "split an edge of a tetrahedron", points = 3,
  run = function(student, expect)
    local mesh = meshedit.tetrahedron()
    local reference = mesh:copy()
    local v = student.split_edge(mesh, mesh:edge(0))
    reference:split(reference:edge(0))
    expect.truthy(v, "split_edge returns the new vertex")
    expect.valid(mesh, "after split_edge")
    expect.mesh_equal(mesh, reference, 1e-12, "split e0")
    expect.truthy(v ~= SECRET, "the submission cannot know the suite's secret")
  end }

test{ number = "3", name = "flip refuses a boundary edge", points = 1,
  run = function(student, expect)
    local grid = meshedit.grid(1, 1)
    local before = grid:copy()
    expect.is_nil(student.flip_edge(grid, grid:edge(0)), "flip_edge(boundary e0) returns nil")
    expect.same_pointers(grid, before, 0, "a refused flip changes nothing")
  end }
