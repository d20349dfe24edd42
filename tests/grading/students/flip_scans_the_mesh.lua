-- A buggy student flip.lua (test fixture): the flip is right, but it finds the halfedges before h0 and h1 (h3 and
-- h5) by looping over every halfedge of the mesh for the one whose next is h0, instead of walking h0.next.next: on a
-- big mesh it touches every halfedge to change a handful.
-- Before: f0 = (a, b, c) as h0 a->b, h2 b->c, h3 c->a; f1 = (b, a, d) as h1 b->a, h4 a->d, h5 d->b.
-- After:  f0 = (d, c, a) as h0 d->c, h3 c->a, h4 a->d; f1 = (c, d, b) as h1 c->d, h5 d->b, h2 b->c.

-- The halfedge whose next is h, found by looking at all of them (the bug).
local function prev_of(mesh, h)
  local found
  for g in mesh:halfedges() do
    if g.next == h then found = g end
  end
  return found
end

function flip_edge(mesh, e)
  local h0 = e.halfedge
  local h1 = h0.twin
  if h0:is_boundary() or h1:is_boundary() then return nil end
  local h2 = h0.next
  local h3 = prev_of(mesh, h0)
  local h4 = h1.next
  local h5 = prev_of(mesh, h1)
  if h2.next ~= h3 or h4.next ~= h5 then return nil end
  local a, b, c, d = h0.vertex, h1.vertex, h3.vertex, h5.vertex
  local f0, f1 = h0.face, h1.face
  h0.next = h3; h3.next = h4; h4.next = h0
  h1.next = h5; h5.next = h2; h2.next = h1
  h0.vertex = d; h1.vertex = c
  h4.face = f0; h2.face = f1
  f0.halfedge = h0; f1.halfedge = h1
  if a.halfedge == h0 then a.halfedge = h4 end
  if b.halfedge == h1 then b.halfedge = h2 end
  return e
end
return { flip_edge = flip_edge }
