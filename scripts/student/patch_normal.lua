-- Extra: the normal of a Bézier patch (an exercise defined in Lua alone: scripts/exercises/patch_normal.lua).
--
-- YOUR TASK
--   Write patch_normal(patch, u, v). `patch.points` is the list of the patch's 16 control points (vec3), row by
--   row, as in patch.lua: the point in row r, column c (both counted from 0) is patch.points[4 * r + c + 1]. Each
--   row is a cubic in u; the column of the rows' results is a cubic in v. Return the UNIT normal at (u, v):
--
--       n = S_u x S_v, divided by its length
--
--   where S_u and S_v are the tangents (the partial derivatives) of the surface S(u, v):
--     S_u: differentiate each row (a cubic's derivative has the control points 3 (P[i+1] - P[i])), evaluate the
--          derivative at u, then evaluate the column of those four vectors at v;
--     S_v: evaluate each row at u (four points), differentiate that column, evaluate it at v.
--   The order of the cross product matters: S_u first.
--
-- THE PICTURE
--
--   row 3:  P12 P13 P14 P15    u runs along each row (P12 to P15)    S_v
--   row 2:  P8  P9  P10 P11    v runs from row 0 to row 3             ^   n = S_u x S_v (out of the page
--   row 1:  P4  P5  P6  P7                                            |   for a patch laid out like this)
--   row 0:  P0  P1  P2  P3                                            +---> S_u
--   (Pk is patch.points[k + 1].)
--
-- WHAT YOU MAY USE
--   patch.points, vec3 arithmetic (a + b, a - b, a * 2, 2 * a, a / 2), a:cross(b), a:length(), a:normalized(),
--   meshedit.vec3(x, y, z). Local helpers (de Casteljau to one point, a curve's derivative) make this short.
--
-- CHECKING
--   In the app's Exercises tab, choose "Extra: the normal of a Bezier patch", an input, and press Run mine: your
--   normal and the reference's, side by side. From a terminal:
--   meshedit grade --suite scripts/exercises/patch_normal.lua --submission scripts/student

function patch_normal(patch, u, v)
  -- TODO: the two tangents at (u, v), their cross product, normalised.
  return nil
end

return { patch_normal = patch_normal }
