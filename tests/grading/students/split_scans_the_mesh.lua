-- A buggy student split.lua (test fixture): the split is right, but it first checks the whole mesh with
-- mesh:validate(), which reads every element: on a big mesh a split that changes a handful touches them all.
function split_edge(mesh, e)
  if not mesh:validate() then return nil end
  local h0 = e.halfedge
  if h0.face:is_boundary() then h0 = h0.twin end
  local h1 = h0.twin
  local h2 = h0.next
  local h3 = h2.next
  if h3.next ~= h0 then return nil end
  local open = h1.face:is_boundary()
  local h4, h5
  if not open then
    h4 = h1.next
    h5 = h4.next
    if h5.next ~= h1 then return nil end
  end
  local a, b, c = h0.vertex, h1.vertex, h3.vertex
  local f0, f1 = h0.face, h1.face
  local after_h1 = h1.next

  local m = mesh:new_vertex((a.position + b.position) * 0.5)
  local ea, ec = mesh:new_edge(), mesh:new_edge()
  local ed = (not open) and mesh:new_edge() or nil
  local g0 = mesh:new_face()
  local g1 = (not open) and mesh:new_face() or nil
  local n0, n1, n2, n3 = mesh:new_halfedge(), mesh:new_halfedge(), mesh:new_halfedge(), mesh:new_halfedge()
  local n4, n5
  if not open then n4, n5 = mesh:new_halfedge(), mesh:new_halfedge() end

  -- f0 = (m, b, c): h0 -> h2 -> n3;  g0 = (a, m, c): n0 -> n2 -> h3
  h0.vertex = m
  h2.next = n3
  n3:set_neighbors(h0, n2, c, ec, f0)
  n0:set_neighbors(n2, n1, a, ea, g0)
  n2:set_neighbors(h3, n3, m, ec, g0)
  h3.next = n0
  h3.face = g0
  if open then
    -- the loop: ... h1 (b->m) -> n1 (m->a) -> what followed h1
    h1.next = n1
    n1:set_neighbors(after_h1, n0, m, ea, f1)
  else
    -- f1 = (b, m, d): h1 -> n4 -> h5;  g1 = (m, a, d): n1 -> h4 -> n5
    local d = h5.vertex
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
