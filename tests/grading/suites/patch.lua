-- Grading suite for part 2, evaluate(patch, u, v) in patch.lua: rows at u, then the column at v. Each point is
-- checked by expect.exercise, the window's own check (the core's evaluation as the reference; u and v swapped is
-- named as such).
-- The patches are not symmetric in u and v, so evaluating in the wrong order gives a different point.
suite{ name = "evaluate", files = {"patch.lua"}, time_limit = 5, memory_mb = 64 }

local vec3 = meshedit.vec3
math.randomseed(184)

-- Row r, column c (from 0) at points[4 * r + c + 1]; a bent sheet, higher along the rows than the columns.
local sheet = {}
for r = 0, 3 do
  for c = 0, 3 do sheet[4 * r + c + 1] = vec3(c, r, 0.3 * c * c - 0.1 * r + 0.05 * r * c) end
end
local random_patches = {}
for k = 1, 3 do
  local points = {}
  for i = 1, 16 do points[i] = vec3(math.random() * 4 - 2, math.random() * 4 - 2, math.random() * 4 - 2) end
  random_patches[k] = meshedit.patch(points)
end

local function check(student, expect, patch, u, v, what)
  local mine = student.evaluate(patch, u, v)
  return expect.exercise("evaluate", {patch = patch, u = u, v = v}, mine, nil,
                         string.format("%s at (u, v) = (%g, %g)", what, u, v))
end

test{ number = "2.1", name = "the four corners are control points", points = 2,
  run = function(student, expect)
    local patch = meshedit.patch(sheet)
    for _, uv in ipairs({{0, 0}, {1, 0}, {0, 1}, {1, 1}}) do check(student, expect, patch, uv[1], uv[2], "corner") end
  end }

test{ number = "2.2", name = "points inside a bent sheet", points = 3, partial = true,
  run = function(student, expect)
    local patch = meshedit.patch(sheet)
    for _, u in ipairs({0.2, 0.5, 0.9}) do
      for _, v in ipairs({0.1, 0.5, 0.7}) do check(student, expect, patch, u, v, "the sheet") end
    end
  end }

test{ number = "2.3", name = "random patches at 25 parameter pairs", points = 2, partial = true,
  visibility = "after_published",
  run = function(student, expect)
    for k, patch in ipairs(random_patches) do
      for i = 0, 4 do
        for j = 0, 4 do check(student, expect, patch, i / 4, j / 4, "random patch " .. k) end
      end
    end
  end }
