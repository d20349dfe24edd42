-- The course's letters for an edge flip, found on a real mesh: the CS184 handout flips the edge b-c between the
-- triangles (a, b, c) and (c, b, d) into (a, d, c) and (a, b, d). This builds that diamond with the course's
-- letters, names its elements the way engine/core/mesh_ops.h does (walking from h0 = e.halfedge, which lies in
-- the course's (a, b, c)), flips it with the reference flip and prints, for conventions_test.cpp:
--   ours for course a b c d: c a b d      our name of each of the course's vertices
--   course after: (a, b, d), (a, d, c)    the triangles after our flip (f0, f1) in the course's letters, each
--                                          from its first letter
-- Anything that does not hold (the flip refused, a triangle the course does not have) is an error.

local course = { a = {-1, 0, 0}, b = {0, -1, 0}, c = {0, 1, 0}, d = {1, 0, 0} }  -- both faces face +z
local mesh = meshedit.from_polygons({ course.a, course.b, course.c, course.d }, { {1, 2, 3}, {3, 2, 4} })
local letter_of = { v0 = "a", v1 = "b", v2 = "c", v3 = "d" }

local e  -- the course's edge b-c
for edge in mesh:edges() do
  local ends = letter_of[tostring(edge.halfedge.vertex)] .. letter_of[tostring(edge.halfedge.twin.vertex)]
  if ends == "bc" or ends == "cb" then e = edge end
end
local h0 = e.halfedge
if tostring(h0.face) ~= "f0" then error("e.halfedge is not in the course's triangle (a, b, c)") end

local ours = {
  [tostring(h0.vertex)] = "a", [tostring(h0.twin.vertex)] = "b",
  [tostring(h0.next.next.vertex)] = "c", [tostring(h0.twin.next.next.vertex)] = "d",
}
local row = {}
for i, name in ipairs({ "v0", "v1", "v2", "v3" }) do row[i] = ours[name] end
print("ours for course a b c d: " .. table.concat(row, " "))

assert(mesh:flip(e))
local after = {}
for f in mesh:faces() do
  -- Each triangle written from its lowest course letter, keeping its cyclic order.
  local corners = {}
  for v in f:vertices() do corners[#corners + 1] = letter_of[tostring(v)] end
  local first = 1
  for i = 2, 3 do if corners[i] < corners[first] then first = i end end
  local text = {}
  for k = 0, 2 do text[#text + 1] = corners[(first - 1 + k) % 3 + 1] end
  after[#after + 1] = "(" .. table.concat(text, ", ") .. ")"
end
print("course after: " .. table.concat(after, ", "))
