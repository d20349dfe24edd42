-- A correct collapse_edge (scripts/exercises/collapse.lua) for an edge between two triangles: b merges into a,
-- which moves to the midpoint; the two triangles, their halfedges and the edges b-c and b-d go. (Boundary edges and
-- the checks that refuse a collapse are left out: the exercise's fixtures are interior edges the core collapses.)
function collapse_edge(mesh, e)
  local h0 = e.halfedge
  if h0.face:is_boundary() then h0 = h0.twin end
  local h1 = h0.twin
  if h1.face:is_boundary() then return nil end
  local h2, h3 = h0.next, h0.next.next
  local h4, h5 = h1.next, h1.next.next
  local a, b, c, d = h0.vertex, h1.vertex, h3.vertex, h5.vertex
  local f0, f1 = h0.face, h1.face
  local t2, t3, t4, t5 = h2.twin, h3.twin, h4.twin, h5.twin
  local e2, e3, e4, e5 = h2.edge, h3.edge, h4.edge, h5.edge

  -- Every halfedge that leaves b (collected before any write) will leave a.
  local leaving_b, h = {}, b.halfedge
  repeat
    leaving_b[#leaving_b + 1] = h
    h = h.twin.next
  until h == b.halfedge

  local middle = (a.position + b.position) / 2
  for _, out in ipairs(leaving_b) do out.vertex = a end
  -- Across each vanished triangle the two outer halfedges become twins, on the edge that stays.
  t2.twin, t3.twin, t2.edge, e3.halfedge = t3, t2, e3, t3
  t4.twin, t5.twin, t5.edge, e4.halfedge = t5, t4, e4, t4
  a.halfedge, c.halfedge, d.halfedge = t3, t2, t4
  a.position = middle
  for _, dead in ipairs({ b, e, e2, e5, f0, f1, h0, h1, h2, h3, h4, h5 }) do mesh:delete(dead) end
  return a
end

return { collapse_edge = collapse_edge }
