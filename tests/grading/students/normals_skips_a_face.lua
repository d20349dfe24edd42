-- A buggy student normals.lua (test fixture): the walk around v tests before it adds
-- (`while h.twin.next ~= v.halfedge`), so it stops one step early and the face of the last halfedge around v is
-- never counted.
function vertex_normal(v)
  local sum = meshedit.vec3(0, 0, 0)
  local h = v.halfedge
  while h.twin.next ~= v.halfedge do
    if not h.face:is_boundary() then
      local p0, p1, p2 = h.vertex.position, h.next.vertex.position, h.next.next.vertex.position
      sum = sum + (p1 - p0):cross(p2 - p0)
    end
    h = h.twin.next
  end
  return sum:normalized()
end
