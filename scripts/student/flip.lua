-- Part 4: edge flip.
--
-- YOUR TASK
--   Write flip_edge(mesh, e). `e` is an edge handle. If e lies between two triangles, turn it inside the quad
--   they form (a-b becomes d-c, names below) by rewriting pointers, and return e. Create nothing, delete
--   nothing: the same 6 halfedges, 5 edges (e and the 4 around the quad), 2 faces and 4 vertices are reused.
--   If e is on the boundary (h0.face or h1.face is a boundary loop) do NOTHING and return nil. The reference
--   also refuses (returns nil) when a face beside e is not a triangle or when c and d are already joined by
--   an edge (the flip would make a second edge c-d).
--
-- THE NAMES (the same as in the lessons and the reference, engine/core/mesh_ops.h)
--   h0 = e.halfedge, h1 = h0.twin; a = h0.vertex, b = h1.vertex (h0 runs a->b, h1 runs b->a).
--   f0 = h0.face holds the triangle (a, b, c): h0 (a->b), h2 = h0.next (b->c), h3 = h2.next (c->a).
--   f1 = h1.face holds the triangle (b, a, d): h1 (b->a), h4 = h1.next (a->d), h5 = h4.next (d->b).
--   Faces are counter-clockwise seen from outside.
--
--                  c                                  c
--                 / \                                /|\
--             h3 /   \ h2                        h3 / | \ h2
--               /  f0 \                            /  |  \
--              /  h0-> \                          / f0|f1 \
--             a ------- b          flip(e)       a   |   b       h0 runs d->c (in f0),
--              \ <-h1  /          -------->       \  |  /        h1 runs c->d (in f1)
--             h4\  f1 / h5                       h4\ | / h5
--                \   /                              \|/
--                 \ /                                |
--                  d                                  d
--
--   Afterwards (what the reference does; twins and edges never change):
--     f0 = (d, c, a): h0 d->c, h3 c->a, h4 a->d    h0.next = h3, h3.next = h4, h4.next = h0
--     f1 = (c, d, b): h1 c->d, h5 d->b, h2 b->c    h1.next = h5, h5.next = h2, h2.next = h1
--     h0.vertex = d, h1.vertex = c; h4.face = f0, h2.face = f1; f0.halfedge = h0, f1.halfedge = h1.
--     a and b may have pointed at h0 / h1, which no longer leave them: then a.halfedge = h4, b.halfedge = h2.
--     (Leave a vertex's halfedge alone otherwise: a boundary vertex keeps its boundary halfedge.)
--   Read every handle you need BEFORE you write any pointer: after h0.next = h3, h0.next is no longer h2.
--
-- WHAT YOU MAY USE
--   Reading: h.next h.twin h.vertex h.edge h.face, v.halfedge, e.halfedge, f.halfedge, f:is_boundary(),
--   f:degree(), v:neighbors() (for w in c:neighbors() do ... end), a == b to compare handles, tostring(h).
--   Writing: h.next = x, h.twin = x, h.vertex = v, h.edge = e, h.face = f, v.halfedge = h, f.halfedge = h,
--   e.halfedge = h, or all five of a halfedge at once: h:set_neighbors(next, twin, vertex, edge, face).
--   print(...) shows up in the console. mesh:flip(e) is the reference (not for use in your answer).
--
-- CHECKING
--   "mine" runs your function on a copy of the mesh, validates it (a pointer you forgot shows up as, e.g.,
--   "f0.halfedge is h5, but h5.face is f1"), compares it with the reference flip and lists every pointer that
--   differs. You can replay your pointer writes one by one.

function flip_edge(mesh, e)
  -- TODO: read h0..h5, a..d, f0, f1; refuse boundary edges; then rewrite the pointers listed above.
  return nil
end

return { flip_edge = flip_edge }
