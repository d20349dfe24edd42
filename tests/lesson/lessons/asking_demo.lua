-- A demo of the lesson primitives that ask and show (scripts/api/README.md, "Asking the student"): choose, pick,
-- answer with a number and with a point, live text, arrows and a plot. Used by the runner, headless and window tests
-- (asking_demo_answers.lua answers it, naming one mistake per question), and to look at in the window:
--   build/meshedit tests/lesson/lessons/asking_demo.lua
lesson { title = "Asking the student", summary = "Every way a lesson can ask, and answer each wrong answer." }

local grid = meshedit.grid(1, 1)  -- two triangles; e2 is the diagonal from v3 to v0

step("Choose", function()
  show(grid)
  camera "fit"
  highlight(grid:edge(2), "orange")
  highlight(grid:halfedge(1), "blue")
  say "The orange diagonal **e2** is about to be flipped. The blue arrow is **h1**."
  choose {
    "Which halfedge is h1.next after the flip?",
    options = { "h2", "h6", "h4" },
    answer = "h4",
    feedback = {
      h2 = "h2 is h1.next now, before the flip: h2 lies along e2, and the flip moves e2.",
      h6 = "h6 is h0's twin on the boundary: it is in no face, and h1 keeps its face.",
      h4 = "After the flip h1 goes on to h4, the outer halfedge of the other triangle.",
    },
    hint = "After a flip each face is one old outer halfedge, one more outer halfedge and the new diagonal.",
  }
  say "So the flip hands h1 the other triangle's outer halfedge."
end)

step("Pick", function()
  show(grid)
  view { halfedges = true, labels = true }
  local picked = pick {
    "Click the halfedge that will be h1.next after the flip.",
    answer = "h4",
    feedback = function(element)
      if element.kind ~= "halfedge" then
        return "That is a " .. element.kind .. ": click one of the arrows inside the faces."
      end
      if tostring(element) == "h2" then return "h2 is h1.next before the flip." end
      return tostring(element) .. " is not in the triangle h1 will be in after the flip."
    end,
    hint = "Look in the triangle that does not hold h1 now.",
  }
  say("You clicked **" .. tostring(picked) .. "**.")
end)

step("Normals", function()
  local cube = meshedit.cube()
  show(cube)
  camera { yaw = 30, pitch = 25 }
  for f in cube:faces() do
    local centre, n = meshedit.vec3(), 0
    for v in f:vertices() do
      centre = centre + v.position
      n = n + 1
    end
    centre = centre / n
    local h = f.halfedge
    local a, b, c = h.vertex.position, h.next.vertex.position, h.next.next.vertex.position
    arrow(centre, centre + (b - a):cross(c - a):normalized() * 0.5, "blue")
  end
  live(function()
    local s = selection()
    return "Selected: " .. (s and tostring(s) or "nothing") .. ". Each blue arrow is a face normal."
  end)
  wait_for { button = "Continue" }
end)

local cubic = { {0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0} }

local function bernstein(i)
  local binomial = ({ 1, 3, 3, 1 })[i + 1]
  return function(t) return binomial * t ^ i * (1 - t) ^ (3 - i) end
end

step("Weights", function()
  show(cubic)
  live(function()
    local t = curve_t()
    local p = meshedit.curve(curve_points()):evaluate(t)
    return string.format("t = %.2f, C(t) = (%.3f, %.3f)", t, p.x, p.y)
  end)
  local curves = {}
  for i = 0, 3 do
    local colour = ({ "blue", "orange", "green", "purple" })[i + 1]
    curves[#curves + 1] = { label = "B" .. i, fn = bernstein(i), colour = colour }
  end
  plot {
    title = "Bernstein weights", x = { 0, 1 }, y = { 0, 1 }, curves = curves,
    marker = function() return curve_t() end,
  }
  local weight = answer {
    "What is B1(0.5), the weight of the second control point at t = 0.5?",
    number = 0.375,
    tolerance = 1e-3,
    feedback = function(value)
      if math.abs(value - 0.125) < 1e-3 then return "0.125 is B0(0.5) or B3(0.5): an end point's weight." end
      return string.format("%g is not it: B1(t) = 3 t (1 - t)^2.", value)
    end,
    hint = "B1(t) = 3 t (1 - t)^2: put in t = 0.5.",
  }
  say(string.format("Yes: B1(0.5) = %g.", weight))
  local point = answer {
    "Where is C(0.5)? Give x, y.",
    point = { 2, 1.5 },
    tolerance = 1e-2,
    hint = "C(0.5) = (P0 + 3 P1 + 3 P2 + P3) / 8.",
  }
  say("C(0.5) is " .. tostring(point) .. ".")
end)
