-- A correct solution of scripts/student/split.lua, boundary edges included, creating elements in the
-- reference's order so that ids match too.

function split_edge(mesh, e)
  local h0 = e.halfedge
  if h0.face:is_boundary() then h0 = h0.twin end
  local h1 = h0.twin
  local f0, f1 = h0.face, h1.face
  if f0:is_boundary() then return nil end
  local boundary = f1:is_boundary()
  if f0:degree() ~= 3 or (not boundary and f1:degree() ~= 3) then return nil end

  local h2 = h0.next
  local h3 = h2.next
  local a, b, c = h0.vertex, h1.vertex, h3.vertex
  local h4, h5, d
  if boundary then
    h4 = h1.next  -- the halfedge after h1 on the boundary loop
  else
    h4 = h1.next
    h5 = h4.next
    d = h5.vertex
    if c == d then return nil end
  end

  local m = mesh:new_vertex((a.position + b.position) * 0.5)
  local ea, ec = mesh:new_edge(), mesh:new_edge()
  local ed = (not boundary) and mesh:new_edge() or nil
  local g0 = mesh:new_face()
  local g1 = (not boundary) and mesh:new_face() or nil
  local n0, n1, n2, n3 = mesh:new_halfedge(), mesh:new_halfedge(), mesh:new_halfedge(), mesh:new_halfedge()
  local n4, n5
  if not boundary then n4, n5 = mesh:new_halfedge(), mesh:new_halfedge() end

  -- f0 = (m, b, c): h0 -> h2 -> n3;  g0 = (a, m, c): n0 -> n2 -> h3
  h0.vertex = m
  h2.next = n3
  n3:set_neighbors(h0, n2, c, ec, f0)
  n0:set_neighbors(n2, n1, a, ea, g0)
  n2:set_neighbors(h3, n3, m, ec, g0)
  h3.next = n0
  h3.face = g0
  if boundary then
    -- the loop: ... h1 (b->m) -> n1 (m->a) -> h4 ...
    h1.next = n1
    n1:set_neighbors(h4, n0, m, ea, f1)
  else
    -- f1 = (b, m, d): h1 -> n4 -> h5;  g1 = (m, a, d): n1 -> h4 -> n5
    h1.next = n4
    n4:set_neighbors(h5, n5, m, ed, f1)
    n1:set_neighbors(h4, n0, m, ea, g1)
    h4.next = n5
    h4.face = g1
    n5:set_neighbors(n1, n4, d, ed, g1)
    ed.halfedge = n4
    g1.halfedge = n1
    f1.halfedge = h1
  end
  ea.halfedge = n0
  ec.halfedge = n2
  f0.halfedge = h0
  g0.halfedge = n0
  m.halfedge = n1
  if a.halfedge == h0 then a.halfedge = n0 end
  return m
end

return { split_edge = split_edge }
