-- A buggy student normals.lua (test fixture): averages the faces' UNIT normals, so big and small faces count
-- the same (the exercise asks for area weights).
function vertex_normal(v)
  local total = meshedit.vec3(0, 0, 0)
  local h = v.halfedge
  repeat
    if not h.face:is_boundary() then
      local a, b, c = h.vertex.position, h.next.vertex.position, h.next.next.vertex.position
      total = total + (b - a):cross(c - a):normalized()
    end
    h = h.twin.next
  until h == v.halfedge
  return total:normalized()
end
