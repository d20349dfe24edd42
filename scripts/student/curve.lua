-- Part 1: one step of de Casteljau's algorithm (Bézier curves).
--
-- YOUR TASK
--   Write evaluate_step(points, t). `points` is a list of n control points (vec3 values; the curves of this
--   part are flat, so z = 0) and `t` is a number, usually in [0, 1]. Return a NEW list of n - 1 points:
--
--       result[i] = (1 - t) * points[i] + t * points[i + 1]        for i = 1, ..., n - 1
--
--   (Lua lists start at 1.) Do ONE step only: the app calls your function again on what you return until a
--   single point is left; that point is the curve point at t. A list of one point (or none) has nothing to
--   interpolate: return an empty list {}. Do not change `points` itself.
--
-- THE PICTURE (4 control points, one step at t = 1/3; each new point is a third of the way along its segment)
--
--        p2 ---------------- p3               level 0:  p1 p2 p3 p4      (the control points)
--       /    q2                \              level 1:  q1 q2 q3         (what evaluate_step returns)
--      q1                       q3            level 2:  r1 r2            (evaluate_step of level 1)
--     /                           \           level 3:  the curve point  (evaluate_step of level 2)
--   p1                             p4
--
-- WHAT YOU MAY USE
--   #points, points[i], a for loop; vec3 arithmetic: a + b, a - b, a * 2, 2 * a, a / 2, -a, tostring(a);
--   meshedit.vec3(x, y, z) makes a point. Fields p.x, p.y, p.z.
--   To see the reference, in the Lua console (hidden from your code): local c = meshedit.curve(points);
--   c:evaluate(t), and c:levels(t), the list of every level: Lua lists start at 1, so c:levels(t)[1] is level 0
--   (the control points) and [k + 1] is level k.
--
-- CHECKING
--   In the app's curve view, tick "mine" (or press M) and press E: each level comes from this function, run on
--   the level before, and is compared point by point with the reference step. Its table numbers the levels as
--   the picture above does. A level that differs is drawn in vermillion over the reference's, and the view
--   names the level, the point and both values; an error shows its curve.lua:LINE. The view reloads this file
--   when you save it. From a terminal:
--   meshedit grade --suite tests/grading/suites/curve.lua --submission scripts/student

function evaluate_step(points, t)
  -- TODO: build and return the list of the n - 1 interpolated points.
  return nil
end

return { evaluate_step = evaluate_step }
