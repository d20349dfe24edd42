-- Part 3: walking the half-edge structure (around a face with h.next, around a vertex with h.twin.next,
-- along a boundary loop), then area-weighted vertex normals and flat vs smooth shading. Every walk is done
-- on the mesh on screen and every highlight and label marks the element the walk reached, so what the
-- student sees is what the pointers say. CI runs it headless:
--   meshedit lesson lessons/3_halfedge_walks.lua --headless --answers tests/script/lessons/3_halfedge_walks_answers.lua

lesson {
  title = "Walking the half-edge mesh",
  summary = "Around a face, around a vertex, along a boundary; then vertex normals and flat against smooth shading.",
}

local cube = meshedit.cube()

local function vec(p)
  return string.format("(%.3f, %.3f, %.3f)", p.x, p.y, p.z)
end

step("Around a face", function()
  show(cube)
  camera "fit"
  local f = cube:face(0)
  local h = f.halfedge
  local names = { "h", "h.next", "h.next.next" }
  local walked, count = h, 0
  repeat
    count = count + 1
    highlight(walked, count == 1 and "red" or "orange")
    label(walked, names[count] or ("step " .. count))
    walked = walked.next
  until walked == h or count > 16
  highlight(f, "yellow")
  say [[
# Around a face

Every face knows **one** of its halfedges, `f.halfedge`. From there, `h.next` is the following halfedge
around the same face, counter-clockwise. Keep following `next` and you come back to where you started.]]
  say("On screen: face **" .. tostring(f) .. "** and its halfedges, labelled as you reach them from `"
    .. tostring(h) .. "`. After " .. count .. " steps of `next` the walk is back at the start: " .. tostring(f)
    .. " is a triangle.")
  say [[
Now **click a face** of your own.]]
  local picked = wait_for { click = "face", hint = "Click a face" }
  if type(picked) ~= "string" then
    local n, g = 0, picked.halfedge
    repeat n = n + 1; g = g.next until g == picked.halfedge or n > 64
    say("You clicked **" .. tostring(picked) .. "**. Walking `next` from its halfedge " .. tostring(picked.halfedge)
      .. " takes " .. n .. " steps to come back: that is how `f:degree()` counts its sides.")
  end
end)

step("Around a vertex", function()
  show(cube)
  local v = cube:vertex(0)
  local start = v.halfedge
  local h, count = start, 0
  repeat
    count = count + 1
    highlight(h, "cyan")
    label(h, tostring(count))
    h = h.twin.next
  until h == start or count > 64
  highlight(v, "red")
  label(v, "v0")
  say [[
# Around a vertex

A vertex knows one halfedge that **starts** at it, `v.halfedge`. To reach the next one, go across with
`h.twin` (it ends at the vertex) and then take `.next` (it starts at the vertex again, in the neighbouring
face). So the walk around a vertex is `h = h.twin.next`, and seen from outside it turns clockwise around the
vertex: the opposite way to `next` around a face.]]
  say("The halfedges numbered on screen are the ones that walk visits around **v0**: " .. count
    .. " of them, so v0 has degree " .. count .. " (the mesh agrees: `v:degree()` is " .. v:degree() .. ").")
  say [[
Try the walk yourself. Select a halfedge, then press **T** to jump to its twin.]]
  wait_for { key = "T", hint = "Press T: go to the twin" }
  say [[
Now press **N** to take the twin's next. Together, T then N is one step of the walk around the vertex.]]
  wait_for { key = "N", hint = "Press N: go to the next halfedge" }
  say [[
Repeat **T**, **N** and you circle the vertex one face at a time.]]
end)

step("Along a boundary", function()
  local grid = meshedit.grid(3, 2)
  show(grid)
  camera "fit"
  local start
  for h in grid:halfedges() do
    if h:is_boundary() then
      start = h
      break
    end
  end
  local h, count = start, 0
  repeat
    count = count + 1
    highlight(h, "green")
    h = h.next
  until h == start or count > 256
  label(start, "start")
  say [[
# Along a boundary

A mesh with holes or edges, like this flat grid, has **boundary halfedges**: the halfedges on the outer
side of its edge, with no face. MeshEdit keeps them in a **boundary loop** (`b0`), so `h.next` still works
and walks along the boundary.]]
  say("The green halfedges are the walk along `next` from " .. tostring(start) .. ": " .. count
    .. " steps around the grid and back to the start, one per boundary edge.")
  say [[
**Select an edge on the boundary** (any of the outer edges of the grid).]]
  local picked = wait_for {
    condition = function()
      local s = selection()
      if s and type(s) ~= "string" and s.kind == "edge" and s:is_boundary() then return s end
      return false
    end,
    hint = "Select an outer edge of the grid",
  }
  say("Yes: **" .. tostring(picked) .. "** is on the boundary. One of its halfedges has a face, the other lies in "
    .. "the boundary loop. Interior edges have a face on both sides.")
end)

step("Area-weighted normals", function()
  show(cube)
  local v = cube:vertex(0)
  local sum = meshedit.vec3(0, 0, 0)
  local faces = 0
  for h in v:halfedges() do
    if not h:is_boundary() then
      local a = h.vertex.position
      local b = h.next.vertex.position
      local c = h.next.next.vertex.position
      sum = sum + (b - a):cross(c - a)
      faces = faces + 1
      highlight(h.face, "orange")
    end
  end
  highlight(v, "red")
  label(v, "v0")
  local n = sum:normalized()
  say [[
# Vertex normals

A vertex has no surface of its own, so its normal is made from the faces around it. Walk around the
vertex; for each face, the cross product of two of its edges points out of the face, and its **length is
twice the face's area**. Adding these up, without normalizing each one first, weights every face by its
area. Normalize the sum at the end.]]
  say("Around v0 that walk meets the " .. faces .. " orange triangles, and the normal comes out as "
    .. vec(n) .. ".")
  say [[
On the cube this is the corner's diagonal, divided by its length: the three square sides meet the corner with
the same area each. On a real mesh the triangles around a vertex differ in size, and area weighting lets a
big face count for more than a thin sliver, which keeps the normal steady when the mesh has badly shaped
triangles.]]
end)

step("Flat or smooth", function()
  show(meshedit.icosahedron())
  camera "fit"
  say [[
# Shading

With **flat shading** every triangle uses its own face normal: the light is constant across it and the
edges show. With **Phong shading** the vertex normals are interpolated across each triangle and lighting
is computed per pixel: the same mesh looks smooth.]]
  say [[
Press **Q** to switch between the two.]]
  wait_for { key = "Q", hint = "Press Q: flat or smooth shading" }
  say [[
Same triangles, same positions: only the normals used for lighting changed. That is why your
`vertex_normal` matters.]]
end)

step("Your turn", function()
  show(cube)
  say [[
# Your code

Open `scripts/student/normals.lua` and write `vertex_normal(v)`: walk around `v` with `h = h.twin.next`,
add the cross products of the faces you meet (skip boundary halfedges, which have no face) and return
the sum normalized. To try it, select a vertex, press **X** for the exercises panel, choose the vertex
normal and press **Run mine**: the panel compares your normal with the reference's.]]
end)
