-- Part 5: edge split.
--
-- YOUR TASK
--   Write split_edge(mesh, e). Put a new vertex m at the midpoint of e, join it to the opposite corners c and
--   d, and return m. An interior edge between two triangles gains 1 vertex, 3 edges, 2 faces and 6 halfedges.
--   m.halfedge must run along the edge that was split (the reference uses n1, m->a), not along a new edge.
--   Boundary edge (extra credit in the course; the reference does it): when one side of e is a boundary
--   loop, only the triangle side is split (+1 vertex, 2 edges, 1 face, 4 halfedges) and the loop gains n1.
--   Refuse (return nil, change nothing) when a face beside e is not a triangle.
--
-- THE NAMES (the same as in the lessons and the reference, engine/core/mesh_ops.h)
--   h0 is e's halfedge inside a face: e.halfedge, or its twin if e.halfedge lies on a boundary loop.
--   h1 = h0.twin; a = h0.vertex, b = h1.vertex; f0 = h0.face = (a, b, c): h0 a->b, h2 = h0.next b->c,
--   h3 = h2.next c->a; f1 = h1.face = (b, a, d): h1 b->a, h4 = h1.next a->d, h5 = h4.next d->b.
--
--                  c                                    c
--                 / \                                 / | \
--             h3 /   \ h2                         h3 /  |  \ h2
--               /  f0 \                             / g0 | f0\
--              /  h0-> \          split(e)         /   ec|   \
--             a ------- b        --------->       a ---- m ---- b      a-m is ea, m-b is e
--              \ <-h1  /                           \   ed|   /
--             h4\  f1 / h5                       h4 \ g1 | f1/ h5
--                \   /                               \  |  /
--                 \ /                                 \ | /
--                  d                                    d
--
--   New elements, made in this order (the reference's order, so its ids and yours agree):
--     m = mesh:new_vertex((a.position + b.position) * 0.5)
--     edges  ea (a-m), ec (m-c), ed (m-d)                      mesh:new_edge()
--     faces  g0 = (a, m, c), g1 = (m, a, d)                    mesh:new_face()
--     halfedges n0 a->m, n1 m->a, n2 m->c, n3 c->m, n4 m->d, n5 d->m   mesh:new_halfedge()
--   Pointers afterwards (each face's halfedge first; twins h0/h1, n0/n1, n2/n3, n4/n5):
--     f0 = (m, b, c): h0 -> h2 -> n3        g0 = (a, m, c): n0 -> n2 -> h3
--     f1 = (b, m, d): h1 -> n4 -> h5        g1 = (m, a, d): n1 -> h4 -> n5
--     h0.vertex = m (h0 now runs m->b); e keeps h0 and h1 as the half m-b; ea.halfedge = n0,
--     ec.halfedge = n2, ed.halfedge = n4; m.halfedge = n1; a.halfedge = n0 if it was h0.
--   Boundary edge (f1 a boundary loop): no ed, g1, n4, n5; the loop runs ... h1 (b->m) -> n1 (m->a) -> the
--   halfedge that followed h1 before; n1.face = f1 (the loop).
--
-- WHAT YOU MAY USE
--   Everything from flip.lua, plus mesh:new_vertex(position), mesh:new_edge(), mesh:new_face(),
--   mesh:new_halfedge() (each returns the new element, all its pointers nil) and mesh:delete(element).
--   vec3 arithmetic for the midpoint. mesh:split(e) is the reference (not for use in your answer).
--
-- CHECKING
--   "mine" runs on a copy of the mesh, validates it, and compares it with the reference split: the same
--   surface (elements matched by position, so your new ids may differ), the new vertex at the midpoint, and
--   the vertex's halfedge along the split edge.

function split_edge(mesh, e)
  -- TODO: read the old elements, create the new ones, set every pointer listed above, return m.
  return nil
end

return { split_edge = split_edge }
