-- Part 3: walking the half-edge structure (around a face with h.next, why a face list cannot find a vertex's
-- neighbours without reading every face, around a vertex with h.twin.next, along a boundary loop), then
-- area-weighted vertex normals (on a fan where the weighting changes the answer) and flat vs smooth shading.
-- Each step asks or has the student act before it tells: the student clicks h.next or h.twin.next, counts, walks
-- a boundary loop, predicts the normal or switches the shading, and every wrong answer is told what it is. Every
-- walk is done on the mesh on screen and every highlight and label marks the element the walk reached, so what the
-- student sees is what the pointers say. The last step runs the student's own vertex_normal (your_turn) on the fan.
-- CI runs it headless:
--   meshedit lesson lessons/3_halfedge_walks.lua --headless \
--     --answers tests/lesson/lessons/3_halfedge_walks_answers.lua --student tests/exercise/solutions

lesson {
  title = "Walking the half-edge mesh",
  summary = "Around a face, why half-edges, around a vertex, along a boundary; then vertex normals and shading.",
}

local cube = meshedit.cube()

local function vec(p)
  local function r(x) return math.abs(x) < 5e-4 and 0 or x end  -- no "-0.000"
  return string.format("(%.3f, %.3f, %.3f)", r(p.x), r(p.y), r(p.z))
end

-- What a clicked element is, for feedback that names it: "a vertex (v3)".
local function kind_of(element)
  return "a " .. element.kind .. " (" .. tostring(element) .. ")"
end

-- A pick returns a handle on a copy of the mesh on screen: compare elements by id.
local function same(a, b) return tostring(a) == tostring(b) end

-- The fan of the normals step: an interior vertex (v0, at the origin) with six triangles around it, a roof
-- whose ridge runs along y, away from the front view (z is up). The triangles on the right (+x) are large and slope
-- down to the right, those on the left small and slope down to the left: their unit normals cancel sideways, their
-- areas do not.
local function fan()
  local points = { { 0, 0, 0 } }
  for k = 0, 5 do
    local t = math.rad(60 * k)
    local x, y = math.cos(t), math.sin(t)
    local r = x > 0.1 and 2.4 or (x < -0.1 and 0.8 or 1.4)
    points[#points + 1] = { r * x, r * y, -0.6 * math.abs(r * x) }
  end
  local faces = {}
  for k = 0, 5 do faces[#faces + 1] = { 1, 2 + k, 2 + (k + 1) % 6 } end
  return meshedit.from_polygons(points, faces)
end

-- The cube's faces and vertex the walks use: f5 is on the front and v5 the front top right corner, so in the
-- three-quarter view (camera "reset") every halfedge a student may click for them is in sight.
local FACE, VERTEX = 5, 5

step("Around a face", function()
  show(cube)
  camera "fit"
  camera "reset"
  view { halfedges = true, labels = true }
  local f = cube:face(FACE)
  local h = f.halfedge
  highlight(f, "yellow")
  highlight(h, "red")
  label(h, "h")
  say("# Around a face\n\nEvery face knows **one** of its halfedges, `f.halfedge`. The yellow face is **"
    .. tostring(f) .. "**, and the red arrow is its halfedge **h** = " .. tostring(h)
    .. ". Each halfedge knows the one after it in its face, `h.next`.")
  pick {
    "Click the halfedge that is h.next.",
    answer = h.next,
    feedback = function(e)
      if e.kind ~= "halfedge" then
        return "That is " .. kind_of(e) .. ", not a halfedge: click one of the arrows inside the faces."
      end
      if same(e, h) then return "That is h itself; h.next is the one after it." end
      if same(e, h.twin) then
        return "That is h.twin: the same edge the other way, in the face next door (" .. tostring(e.face)
          .. "). next stays in h's face."
      end
      if same(e, h.next.next) then
        return "That is h.next.next, the halfedge before h (it ends where h starts): next starts where h ends, "
          .. "at the tip of h's arrow."
      end
      return tostring(e) .. " is in " .. tostring(e.face) .. ", not in the yellow face: h.next stays in h's face."
    end,
    hint = "h.next starts at the tip of h's arrow, inside the yellow face.",
  }
  local names = { "h", "h.next", "h.next.next" }
  local walked, count = h, 0
  repeat
    count = count + 1
    highlight(walked, count == 1 and "red" or "orange")
    label(walked, names[count] or ("step " .. count))
    walked = walked.next
  until walked == h or count > 16
  say [[
From any halfedge, `h.next` is the following halfedge around the same face, counter-clockwise. Keep following
`next` and you come back to where you started.]]
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

step("Why half-edges at all", function()
  show(cube)
  camera "fit"
  camera "reset"
  view { halfedges = true, labels = true }
  local v = cube:vertex(VERTEX)
  local touching = 0
  for f in cube:faces() do
    for w in f:vertices() do
      if w == v then touching = touching + 1 end
    end
  end
  highlight(v, "red")
  label(v, tostring(v))
  say([[
# What a face list cannot answer

The simplest way to store a mesh is a **face list**, as an OBJ file does: each triangle is the numbers of its
three corners, `{1, 2, 3}`, `{1, 3, 4}`, ... This cube has 12 triangles. Drawing them is easy. Now a question
every mesh operation asks: which vertices are the **neighbours of ]] .. tostring(v) .. [[** (red)?]])
  answer {
    "With only the face list, how many of the 12 triangles must you read to be sure you found every neighbour of "
      .. tostring(v) .. "?",
    number = 12,
    tolerance = 0,
    feedback = function(value)
      if value == touching then
        return touching .. " triangles touch " .. tostring(v) .. ", but the list does not say which " .. touching
          .. ": they could be anywhere in it."
      end
      if value == 3 then
        return "3 square sides meet at " .. tostring(v) .. ", but nothing in the list says where their triangles are."
      end
      if value < 12 then
        return "Nothing in a face list says where " .. tostring(v) .. "'s triangles are stored: which could you skip?"
      end
      if value > 12 then return "The list has only 12 triangles." end
    end,
    hint = "Could a triangle near the end of the list use " .. tostring(v)
      .. "? How would you know without reading it?",
  }
  local count, h = 0, v.halfedge
  repeat
    count = count + 1
    highlight(h, "cyan")
    h = h.twin.next
  until h == v.halfedge or count > 64
  say("All 12: a face list answers in time that grows with the **whole mesh**, and a mesh operation asks this for "
    .. "every vertex it touches. A half-edge mesh stores, with each element, the pointers to its neighbours: from "
    .. "`v.halfedge` the walk `h = h.twin.next` reaches the " .. count .. " halfedges leaving " .. tostring(v)
    .. " (sky blue), one per neighbour, and nothing else: time that grows with its degree only. The next step walks "
    .. "it.")
end)

step("Around a vertex", function()
  show(cube)
  camera "fit"
  camera "reset"
  view { halfedges = true, labels = true }
  local v = cube:vertex(VERTEX)
  local start = v.halfedge
  highlight(v, "red")
  label(v, tostring(v))
  highlight(start, "cyan")
  label(start, "h")
  say(string.gsub([[
# Around a vertex

A vertex knows one halfedge that **starts** at it, `v.halfedge`: the sky-blue arrow **h**, leaving **V**. To reach
the next one around V, go across with `h.twin` (it ends at V) and then take `.next` (it starts at V again, in
the neighbouring face).]], "V", tostring(v)))
  -- The walk's order, to tell a student who clicked a later halfedge of the walk how far round it is.
  local order, g, k = {}, start, 0
  repeat
    k = k + 1
    order[tostring(g)] = k
    g = g.twin.next
  until g == start or k > 64
  pick {
    "Click the halfedge that is h.twin.next.",
    answer = start.twin.next,
    feedback = function(e)
      if e.kind ~= "halfedge" then
        return "That is " .. kind_of(e) .. ", not a halfedge: click one of the arrows."
      end
      if same(e, start) then return "That is h itself." end
      if same(e, start.twin) then
        return "That is h.twin: it ends at " .. tostring(v) .. ". Take one more step: its next."
      end
      if same(e, start.next) then
        return "That is h.next: it goes on around h's own face, away from " .. tostring(v) .. "."
      end
      if order[tostring(e)] then
        return tostring(e) .. " leaves " .. tostring(v) .. " too, but it is " .. (order[tostring(e)] - 1)
          .. " steps round the walk, not one."
      end
      return tostring(e) .. " does not start at " .. tostring(v) .. ": every halfedge of this walk leaves it."
    end,
    hint = "h.twin runs along the same edge as h, back into " .. tostring(v) .. ", inside the face on the other side.",
  }
  local h, count = start, 0
  repeat
    count = count + 1
    highlight(h, "cyan")
    label(h, tostring(count))
    h = h.twin.next
  until h == start or count > 64
  say [[
So the walk around a vertex is `h = h.twin.next`, and seen from outside it turns clockwise around the
vertex: the opposite way to `next` around a face.]]
  say("The halfedges numbered on screen are the ones that walk visits around **" .. tostring(v) .. "**: " .. count
    .. " of them, so " .. tostring(v) .. " has degree " .. count .. " (the mesh agrees: `v:degree()` is "
    .. v:degree() .. ").")
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
  view { halfedges = true, labels = true }  -- the boundary walk is drawn on the arrows
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
side of its edges, in no face. MeshEdit keeps them in a **boundary loop** (`b0`), so `h.next` still works
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
  local mesh = fan()
  show(mesh)
  camera "fit"
  camera { yaw = 0, pitch = 30 }  -- the front view, from a little above: x to the right, z up
  view { labels = false, halfedges = false }
  local v = mesh:vertex(0)
  local weighted, plain = meshedit.vec3(0, 0, 0), meshedit.vec3(0, 0, 0)
  local faces = 0
  for h in v:halfedges() do
    if not h:is_boundary() then
      local a = h.vertex.position
      local b = h.next.vertex.position
      local c = h.next.next.vertex.position
      local n = (b - a):cross(c - a)
      weighted = weighted + n
      plain = plain + n:normalized()
      faces = faces + 1
    end
  end
  weighted, plain = weighted:normalized(), plain:normalized()
  highlight(v, "red")
  label(v, "v")
  local p = v.position
  arrow(p, p + plain * 1.6, "blue")
  say [[
# Vertex normals

A vertex has no surface of its own, so its normal is made from the faces around it: walk around the vertex
and add up the faces' normals. For each face, the cross product of two of its edges points out of the face, and
its **length is twice the face's area**.]]
  say("The vertex **v** has " .. faces .. " triangles around it: big ones on the right sloping down to the right, "
    .. "small ones on the left sloping down to the left. The **blue** arrow is the plain average: each face's "
    .. "cross product normalized first, so every face counts the same. It points straight up, " .. vec(plain) .. ".")
  choose {
    "Now add the cross products as they are, so each face counts by its area, and normalize the sum. "
      .. "Where does that normal point?",
    options = {
      "Leaning right, towards the big faces", "Leaning left, towards the small faces", "Straight up, as the blue one",
    },
    answer = "Leaning right, towards the big faces",
    feedback = {
      ["Leaning left, towards the small faces"] =
        "The other way: a small face has a short cross product, so it counts for less.",
      ["Straight up, as the blue one"] =
        "Only when all the faces have the same area, as on a cube's corner. Here the right-hand faces are bigger.",
      ["Leaning right, towards the big faces"] = "The big faces' long cross products outweigh the small ones'.",
    },
    hint = "Which faces have the longest cross products, and which way do their normals lean?",
  }
  arrow(p, p + weighted * 1.6, "orange")
  say("The **orange** arrow is the area-weighted normal, " .. vec(weighted) .. ": it leans towards the big faces. "
    .. "That is the normal your `vertex_normal` returns. Area weighting lets a big face count for more than a thin "
    .. "sliver, which keeps the normal steady when the mesh has badly shaped triangles.")
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
  local mesh = fan()
  show(mesh)
  camera "fit"
  camera { yaw = 0, pitch = 30 }
  view { labels = false, halfedges = false }
  highlight(mesh:vertex(0), "red")
  label(mesh:vertex(0), "v")
  say [[
# Your code

Open `scripts/student/normals.lua` and write `vertex_normal(v)`: walk around `v` with `h = h.twin.next`,
add the cross products of the faces you meet (skip boundary halfedges: their `h.face` is a boundary loop,
`h.face:is_boundary()`, not a face) and return the sum normalized. The lesson runs it on the fan's vertex **v**
each time you save the file and compares it with the reference's area-weighted normal: the plain average of unit
normals, a face left out or counted alone, a cross product taken the wrong way round are named as such, with the
faces they concern, and a Lua error shows its `normals.lua:LINE`.]]
  your_turn {
    exercise = "normals",
    mesh = mesh,
    element = mesh:vertex(0),
    hint = "Add (b - a):cross(c - a) for each face as it is: its length is twice the face's area, so normalize "
      .. "only the sum.",
  }
  say [[
Your `vertex_normal` gives the reference's normal at **v**. In the window you can run it on any vertex of any
mesh: select a vertex, open the **Exercises** tab (X), choose the vertex normal and press **Run mine**.]]
end)
