-- A correct solution of scripts/student/flip.lua, with the reference's names and conventions, so the result
-- matches the reference pointer for pointer.

function flip_edge(mesh, e)
  local h0 = e.halfedge
  local h1 = h0.twin
  local f0, f1 = h0.face, h1.face
  if f0:is_boundary() or f1:is_boundary() then return nil end
  if f0:degree() ~= 3 or f1:degree() ~= 3 then return nil end

  local h2 = h0.next
  local h3 = h2.next
  local h4 = h1.next
  local h5 = h4.next
  local a, b = h0.vertex, h1.vertex
  local c, d = h3.vertex, h5.vertex
  if c == d then return nil end
  for w in c:neighbors() do
    if w == d then return nil end  -- c-d is already an edge
  end

  -- f0 = (d, c, a): h0 d->c, h3 c->a, h4 a->d
  h0:set_neighbors(h3, h1, d, e, f0)
  h3.next = h4
  h4.next = h0
  h4.face = f0
  -- f1 = (c, d, b): h1 c->d, h5 d->b, h2 b->c
  h1:set_neighbors(h5, h0, c, e, f1)
  h5.next = h2
  h2.next = h1
  h2.face = f1

  f0.halfedge = h0
  f1.halfedge = h1
  if a.halfedge == h0 then a.halfedge = h4 end
  if b.halfedge == h1 then b.halfedge = h2 end
  return e
end

return { flip_edge = flip_edge }
