-- A buggy student normals.lua (test fixture): assigns each face's cross product to the sum instead of adding it
-- (`sum = (p1 - p0):cross(p2 - p0)`), so only the last face of the walk counts.
function vertex_normal(v)
  local sum = meshedit.vec3(0, 0, 0)
  local h = v.halfedge
  repeat
    if not h.face:is_boundary() then
      local p0, p1, p2 = h.vertex.position, h.next.vertex.position, h.next.next.vertex.position
      sum = (p1 - p0):cross(p2 - p0)
    end
    h = h.twin.next
  until h == v.halfedge
  return sum:normalized()
end
