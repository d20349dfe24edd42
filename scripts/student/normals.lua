-- Part 3: area-weighted vertex normals (for smooth shading).
--
-- YOUR TASK
--   Write vertex_normal(v). `v` is a vertex handle. Return the unit normal at v: the sum, over the faces
--   around v, of (face area) x (face unit normal), normalised. For a triangle with corners p0, p1, p2 (in the
--   face's order) the vector (p1 - p0):cross(p2 - p0) is exactly 2 x area x unit normal, so you can add those
--   cross products and normalise the sum at the end (the common factor 2 does not change the direction).
--   Skip boundary loops (h.face:is_boundary() is true for them): they are holes, not faces.
--   Averaging the UNIT normals of the faces (without their areas) is a different, wrong answer here.
--   Do not change the mesh.
--
-- WALKING AROUND A VERTEX (names as in the lessons)
--
--              p2
--             /  \            h = v.halfedge leaves v; the face on its left is h.face, whose corners are
--            /    \               h.vertex (= v), h.next.vertex, h.next.next.vertex (for a triangle).
--           / h.face\         The next outgoing halfedge around v is h.twin.next: h.twin comes back to v
--          v ---h---> p1          along h's edge, and its next leaves v inside the face on h's right. The
--                                 walk turns clockwise around v seen from outside (each face's own next goes
--                                 counter-clockwise); you are back at the start when h equals v.halfedge again.
--
--     local h = v.halfedge
--     repeat
--       ... use h and h.face ...
--       h = h.twin.next
--     until h == v.halfedge
--
-- WHAT YOU MAY USE
--   Handles: h.next h.twin h.vertex h.edge h.face; v.halfedge v.position (a vec3); f:is_boundary();
--   f:degree(); for h in v:halfedges() do ... end (the outgoing halfedges). vec3: + - * / , a:cross(b),
--   a:dot(b), a:length(), a:normalized(), meshedit.vec3(x, y, z).
--
-- CHECKING
--   "mine" compares your vector with the reference normal of the same vertex; the checker recognises an
--   unweighted average, a normal pointing inwards and a vector that is not unit length.

function vertex_normal(v)
  -- TODO: add up (area x unit normal) of the faces around v, then return the normalised sum.
  return nil
end

return { vertex_normal = vertex_normal }
