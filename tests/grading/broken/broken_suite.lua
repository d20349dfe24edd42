-- A small suite for submissions that do not load, hang or run out of memory while loading
-- (tests/grade/cli_grade_test.cpp): whatever happens, every test gets a result and results.json is written.
suite{ name = "broken", files = {"flip.lua"}, time_limit = 0.5, memory_mb = 32 }

test{ number = "1", name = "flip_edge exists", points = 1,
  run = function(student, expect) expect.truthy(student.has("flip_edge"), "flip.lua defines flip_edge") end }

test{ number = "2", name = "flip the middle edge of two triangles", points = 2,
  run = function(student, expect)
    local grid = meshedit.grid(1, 1)
    expect.equal(student.flip_edge(grid, grid:edge(2)), grid:edge(2))
    expect.valid(grid)
  end }
