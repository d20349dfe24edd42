-- Extra: edge collapse (an exercise defined in Lua alone: scripts/exercises/collapse.lua).
--
-- YOUR TASK
--   Write collapse_edge(mesh, e). `e` is an edge handle between two triangles. Merge its end b into its end a:
--   a moves to the midpoint of a and b and is returned; the two triangles beside e vanish, and of each one's two
--   other edges the one that touched b vanishes with it. When the reference refuses an edge (see
--   engine/core/mesh_ops.h: a collapse that would not leave a manifold surface), do NOTHING and return nil.
--
-- THE NAMES (as in engine/core/mesh_ops.h)
--   h0 = e.halfedge (or its twin, so that h0 is inside a face), h1 = h0.twin; a = h0.vertex, b = h1.vertex.
--   f0 = h0.face = (a, b, c): h0 a->b, h2 = h0.next b->c, h3 = h2.next c->a.
--   f1 = h1.face = (b, a, d): h1 b->a, h4 = h1.next a->d, h5 = h4.next d->b.
--   The outer halfedges: t2 = h2.twin (c->b), t3 = h3.twin (a->c), t4 = h4.twin (d->a), t5 = h5.twin (b->d).
--
--                  c                                c
--                 / \                               |
--             h3 /   \ h2                        t2 | t3       (edge e3 = h3.edge)
--               /  f0 \                             |
--              /  h0-> \      collapse_edge(e)      |
--             a ------- b     --------------->      a  (at the midpoint of a and b)
--              \ <-h1  /                            |
--             h4\  f1 / h5                       t4 | t5       (edge e4 = h4.edge)
--                \   /                              |
--                 \ /                               |
--                  d                                d
--
--   Afterwards: every halfedge that left b leaves a; t2 and t3 are twins on e3, t4 and t5 twins on e4; a, c and d
--   point at halfedges that still leave them (t3, t2, t4 will do); deleted: b, e, f0, f1, h0 to h5, h2.edge and
--   h5.edge (mesh:delete(x) for each).
--   Collect every handle (and the halfedges leaving b: h = b.halfedge, then h = h.twin.next until back at the start)
--   BEFORE you write a pointer.
--
-- WHAT YOU MAY USE
--   Reading and writing as in flip.lua (h.next, h.twin, h.vertex, h.edge, h.face, v.halfedge, e.halfedge,
--   f.halfedge, v.position, f:is_boundary()), mesh:delete(x). mesh:collapse(e) is the reference (hidden from your
--   code).
--
-- CHECKING
--   The Exercises tab (X): choose "collapse", select an edge, press Run mine. It validates your mesh, compares it
--   with the reference up to renumbering, names the likely mistake and replays your writes one by one. From a
--   terminal: meshedit grade --suite scripts/exercises/collapse.lua --submission scripts/student

function collapse_edge(mesh, e)
  -- TODO: read h0..h5, a..d, f0, f1, t2..t5; repoint, move a, delete what vanishes; return a.
  return nil
end

return { collapse_edge = collapse_edge }
