-- Extra: the hodograph of a Bézier curve (an exercise defined in Lua alone: scripts/exercises/hodograph.lua).
--
-- YOUR TASK
--   Write hodograph(points). `points` is the list of the n + 1 control points P[1], ..., P[n+1] (vec3 values) of a
--   Bézier curve C of degree n. Return a NEW list of the n control points of its derivative C', itself a Bézier
--   curve of degree n - 1:
--
--       result[i] = n * (points[i + 1] - points[i])        for i = 1, ..., n
--
--   (Lua lists start at 1; n = #points - 1.) A single point (degree 0) has a derivative of no control points:
--   return an empty list {}. Do not change `points` itself.
--
-- THE PICTURE (a cubic, n = 3: each control point of C' is 3 times a leg of the control polygon)
--
--        P2 -------- P3                 C'(t) has the control points
--       /              \                  3 (P2 - P1), 3 (P3 - P2), 3 (P4 - P3)
--     P1                P4              so C'(0) = 3 (P2 - P1), the tangent where C starts.
--
-- WHAT YOU MAY USE
--   #points, points[i], a for loop; vec3 arithmetic: a + b, a - b, a * 2, 2 * a, a / 2; meshedit.vec3(x, y, z).
--
-- CHECKING
--   In the app's Exercises tab, choose "Extra: the hodograph of a Bezier curve", an input, and press Run mine: your
--   points and the reference's, side by side. From a terminal:
--   meshedit grade --suite scripts/exercises/hodograph.lua --submission scripts/student

function hodograph(points)
  -- TODO: build and return the list of the n control points of the derivative.
  return nil
end

return { hodograph = hodograph }
