-- Grading suite for part 1, evaluate_step(points, t) in curve.lua: one de Casteljau step, n points -> n - 1.
-- Each step is checked by expect.exercise, the window's own check (the core's step as the reference, and the
-- window's diagnosis: a dropped last point, swapped weights).
suite{ name = "evaluate_step", files = {"curve.lua"}, time_limit = 5, memory_mb = 64 }

local vec3 = meshedit.vec3
math.randomseed(184)

-- One step of the student's on `points` at t, checked as the window checks it; returns the step.
local function check_step(student, expect, points, t, what)
  local step = student.evaluate_step(points, t)
  return expect.exercise("evaluate_step", {points = points, t = t}, step, nil, what), step
end

local cubic = {vec3(0, 0, 0), vec3(1, 2, 0), vec3(3, 2, 0), vec3(4, 0, 0)}
local shapes = {
  {vec3(0, 0, 0), vec3(2, 1, 0)},
  {vec3(-1, 0, 0), vec3(0, 3, 0), vec3(1, 0, 0)},
  cubic,
  {vec3(0, 0, 0), vec3(0.5, 1, 0), vec3(2, 1.5, 0), vec3(3, -1, 0), vec3(4, 0.5, 0), vec3(5, 2, 0)},
}
local random_curves = {}
for c = 1, 5 do
  local points = {}
  for i = 1, c + 2 do points[i] = vec3(math.random() * 10 - 5, math.random() * 10 - 5, math.random() * 2 - 1) end
  random_curves[c] = points
end

test{ number = "1.1", name = "one step of a cubic at t = 0.5", points = 2,
  run = function(student, expect)
    check_step(student, expect, cubic, 0.5, "evaluate_step(cubic, 0.5)")
  end }

test{ number = "1.2", name = "one step of curves with 2 to 6 points at t = 0, 0.25, 1/3 and 1", points = 3,
  partial = true,
  run = function(student, expect)
    for _, points in ipairs(shapes) do
      for _, t in ipairs({0, 0.25, 1 / 3, 1}) do
        check_step(student, expect, points, t, string.format("evaluate_step of %d points at t = %g", #points, t))
      end
    end
  end }

test{ number = "1.3", name = "a single point gives an empty list", points = 1, visibility = "after_due_date",
  run = function(student, expect)
    check_step(student, expect, {vec3(1, 2, 0)}, 0.5, "evaluate_step of one point")
  end }

test{ number = "1.4", name = "repeated steps reach the curve point (3D curves)", points = 2, partial = true,
  visibility = "after_published",
  run = function(student, expect)
    for c, points in ipairs(random_curves) do
      for _, t in ipairs({0.1, 0.5, 0.77}) do
        local what = string.format("curve %d (%d points) at t = %g", c, #points, t)
        local level, right = points, true
        for k = 1, #points - 1 do
          right, level = check_step(student, expect, level, t, what .. ", step " .. k)
          if not right then break end
        end
        if right then expect.near(level, {meshedit.curve(points):evaluate(t)}, 1e-9, what .. ": the curve point") end
      end
    end
  end }

test{ number = "1.5", name = "t outside [0, 1] extrapolates along the same lines", points = 1,
  visibility = "after_published",
  run = function(student, expect)
    for _, t in ipairs({-0.5, 1.5}) do
      check_step(student, expect, cubic, t, "evaluate_step(cubic, " .. t .. ")")
    end
  end }
