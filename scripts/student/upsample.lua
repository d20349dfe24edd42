-- Part 6: Loop subdivision.
--
-- YOUR TASK
--   Write upsample(mesh): subdivide the triangle mesh in place, each triangle into four, the way the course
--   does it, in five steps:
--     1. For every ORIGINAL vertex compute its new position (do not move it yet):
--          interior vertex of degree n with neighbours q1..qn:   (1 - n * u) * p + u * (q1 + ... + qn),
--          u = 3/16 if n == 3, else 3 / (8 * n)
--          boundary vertex (extra credit; the reference does it): 3/4 * p + 1/8 * (r1 + r2), where r1 and r2
--          are its two neighbours along the boundary.
--     2. For every ORIGINAL edge a-b compute the position of the vertex that will split it:
--          interior edge with opposite corners c and d:  3/8 * (a + b) + 1/8 * (c + d)
--          boundary edge:                                 (a + b) / 2
--     3. Split every original edge (and ONLY those: remember them before you start; splitting edges made by
--        a split never ends). Mark the new vertex as new and remember its position from step 2. Mark the two
--        edges that cut across the old faces (m-c and m-d) as new; the two halves of the split edge are not.
--     4. Flip every new edge that joins an old vertex and a new vertex (one endpoint new, the other old).
--     5. Move every vertex to the position computed in steps 1 and 2.
--   Keep your marks in Lua tables indexed by id (is_new[v.id] = true): handles are made fresh at every read,
--   so two handles of the same vertex are == but are different table keys.
--   Use numbers like 3 / 16 or 3.0 / 16: in Lua, 3 // 16 is an integer division (0).
--
-- THE NAMES
--   After mesh:split(e) returns m, m.halfedge runs along the split edge (m->a); the halfedges leaving m are
--   m.halfedge, m.halfedge.twin.next, ..., and the walk turns clockwise around m seen from outside (four of
--   them for an interior edge: to a, c, b, d; on a boundary edge three: to a, c, b). a, b, c, d are the names
--   of split.lua and engine/core/mesh_ops.h: a-b the edge, c and d the corners across it.
--
-- WHAT YOU MAY USE
--   Everything from the earlier parts. Splits and flips: mesh:split(e) and mesh:flip(e) (the reference
--   operations, so a mistake in your own flip or split does not count twice), or your split_edge and
--   flip_edge. Iteration: for v in mesh:vertices() do ... end, mesh:edges(), mesh:faces(); the end of each
--   loop is fixed when the loop starts, so elements created inside the loop are not visited.
--   mesh:num_vertices() etc. mesh:loop_subdivide() is the reference (not for use in your answer).
--
-- CHECKING
--   "mine" runs on a copy of the mesh, validates it, counts its elements (V + E vertices, 4 F faces) and
--   compares it with the reference up to renumbering: every vertex at the right place, every face present.
--   The checker says which vertices moved to the wrong place and which edges were flipped wrongly.

function upsample(mesh)
  -- TODO: the five steps above.
end

return { upsample = upsample }
