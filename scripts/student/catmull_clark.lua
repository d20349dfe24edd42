-- Extra: Catmull-Clark subdivision (an exercise defined in Lua alone: scripts/exercises/catmull_clark.lua).
--
-- YOUR TASK
--   Write catmull_clark_level(mesh): one level of Catmull-Clark subdivision, in place, on a mesh whose faces all
--   have 4 or more corners. If a face is a triangle, change NOTHING and return nil (the reference refuses it: the
--   way below cuts a triangle into four triangles instead of three quads).
--
-- THE WAY (lesson 7's rules, in three steps)
--   1. Remember which vertex ids are old: old[v.id] = true for every v in mesh:vertices().
--   2. mesh:linear_subdivide() makes the new mesh's quads: every face of n corners becomes n quads (corner, edge
--      vertex, face vertex, edge vertex). Old vertices keep their ids and places; each edge's new vertex sits at
--      its midpoint and each face's new vertex at its centroid. Nothing has moved yet.
--   3. Move every vertex by the rules, reading its neighbours in this refined mesh. Compute EVERY new position
--      first (in a table by id), and only then write them all: a vertex moved early would spoil its neighbours'.
--        face vertex (joined to no old vertex)   stays: it is the face point, the face's centroid.
--        edge vertex (joined to old vertices)    inside: the mean of its 4 neighbours, (a + b + f0 + f1) / 4;
--                                                on the boundary (v:is_boundary()): stays at the midpoint.
--        old vertex P, inside, of degree n       (F + 2R + (n - 3) P) / n, where R is the mean of its n neighbours
--                                                (the edges' midpoints) and F the mean of the face vertices of
--                                                the n quads around it (for h leaving P: h.next.next.vertex).
--        old vertex P on the boundary            1/2 P + 1/4 (its two neighbours along the boundary), which is
--                                                3/4 P + 1/8 (the old boundary neighbours) in lesson 7's terms.
--
-- WHAT YOU MAY USE
--   Everything from flip.lua for reading (h.next, h.twin, h.vertex, v.halfedge, v:neighbors(), v:halfedges(),
--   v:degree(), v:is_boundary(), f:degree(), v.position and vec3 arithmetic), mesh:linear_subdivide().
--   mesh:catmull_clark() is the reference (hidden from your code).
--
-- CHECKING
--   The Exercises tab (X): choose "catmull_clark", Run mine on a mesh of quads (lesson 7's cube, or File > Open
--   any quad mesh). It compares your vertices with the reference's and names the kind that is misplaced. From a
--   terminal: meshedit grade --suite scripts/exercises/catmull_clark.lua --submission scripts/student

function catmull_clark_level(mesh)
  -- TODO: refuse triangles; remember the old ids; linear_subdivide; compute every new position; move them all.
  return nil
end

return { catmull_clark_level = catmull_clark_level }
