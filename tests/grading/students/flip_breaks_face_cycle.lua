-- A buggy student flip.lua (test fixture): it never sets h5.next = h2, so h5 still leads back to h1 and the new
-- face f1 = (c, d, b) does not close through h2: the pointer that breaks the face cycle.
-- Before: f0 = (a, b, c) as h0 a->b, h2 b->c, h3 c->a; f1 = (b, a, d) as h1 b->a, h4 a->d, h5 d->b.
-- After:  f0 = (d, c, a) as h0 d->c, h3 c->a, h4 a->d; f1 = (c, d, b) as h1 c->d, h5 d->b, h2 b->c.
function flip_edge(mesh, e)
  local h0 = e.halfedge
  local h1 = h0.twin
  if h0:is_boundary() or h1:is_boundary() then return nil end
  local h2 = h0.next
  local h3 = h2.next
  local h4 = h1.next
  local h5 = h4.next
  if h3.next ~= h0 or h5.next ~= h1 then return nil end
  local a, b, c, d = h0.vertex, h1.vertex, h3.vertex, h5.vertex
  local f0, f1 = h0.face, h1.face
  h0.next = h3; h3.next = h4; h4.next = h0
  h1.next = h5; h2.next = h1  -- (the bug: h5.next is not set to h2)
  h0.vertex = d; h1.vertex = c
  h4.face = f0; h2.face = f1
  f0.halfedge = h0; f1.halfedge = h1
  if a.halfedge == h0 then a.halfedge = h4 end
  if b.halfedge == h1 then b.halfedge = h2 end
  return e
end
return { flip_edge = flip_edge }
