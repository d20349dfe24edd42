-- A buggy student normals.lua (test fixture): weights each face's unit normal by the face's angle at v (the
-- angle-weighted normal of some renderers), where the exercise asks for area weights.
function vertex_normal(v)
  local sum = meshedit.vec3(0, 0, 0)
  local h = v.halfedge
  repeat
    if not h.face:is_boundary() then
      local p0 = h.vertex.position
      local a, b = h.next.vertex.position - p0, h.next.next.vertex.position - p0
      local angle = math.acos(a:normalized():dot(b:normalized()))
      sum = sum + a:cross(b):normalized() * angle
    end
    h = h.twin.next
  until h == v.halfedge
  return sum:normalized()
end
