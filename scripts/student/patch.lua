-- Part 2: evaluating a bicubic Bézier patch with separable de Casteljau.
--
-- YOUR TASK
--   Write evaluate(patch, u, v). `patch.points` is the list of the patch's 16 control points (vec3), row by
--   row: the point in row r, column c (both counted from 0) is patch.points[4 * r + c + 1]. Return the
--   surface point at (u, v), the way the course does it:
--
--     1. each ROW is a cubic Bézier curve in u: evaluate all four rows at u (full de Casteljau, three steps
--        each), which gives four points q1 q2 q3 q4;
--     2. those four points are a cubic Bézier curve in v (the "column"): evaluate it at v.
--
--   Rows at u first, then the column at v: swapping u and v gives a different point on the surface.
--   A helper like evaluate_step(points, t) from curve.lua (one step: n points -> n - 1) and
--   evaluate_1d(points, t) (steps until one point is left) makes this short; write them here as local
--   functions.
--
-- THE PICTURE
--
--   row 0:  P0  P1  P2  P3    --(at u)-->  q1  \
--   row 1:  P4  P5  P6  P7    --(at u)-->  q2   |  the column q1 q2 q3 q4 --(at v)--> the surface point
--   row 2:  P8  P9  P10 P11   --(at u)-->  q3   |
--   row 3:  P12 P13 P14 P15   --(at u)-->  q4  /
--   (Pk is patch.points[k + 1].)   Corners: (u, v) = (0, 0) -> P0, (1, 0) -> P3, (0, 1) -> P12, (1, 1) -> P15.
--
-- WHAT YOU MAY USE
--   patch.points (a fresh list each time you read it: read it once), vec3 arithmetic (a + b, a * 2, 2 * a,
--   a - b, a / 2), meshedit.vec3(x, y, z). Console only (hidden in your code): meshedit.patch(points):evaluation(u, v)
--   returns {rows = {q1..q4}, column_levels = {...}, point = ...}.
--
-- CHECKING
--   In the app's patch view, tick "mine" (or press M): the probe point at (u, v) comes from this function too,
--   and is compared with the reference at the same (u, v); the checker tells you when your answer is the
--   reference at (v, u), which means rows and columns were swapped. The view reloads this file when you save
--   it. From a terminal: meshedit grade --suite tests/grading/suites/patch.lua --submission scripts/student

function evaluate(patch, u, v)
  -- TODO: evaluate the four rows at u, then the column of their results at v.
  return nil
end

return { evaluate = evaluate }
