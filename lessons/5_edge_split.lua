-- Part 5: edge split. First an interior edge (the diamond of part 4, with the same names and labels), then an edge
-- on the boundary of a grid. Each step asks the student to predict before it shows: how many edges a split makes,
-- which halfedge runs m to b afterwards, m's halfedge, which of h0's fields change, the boundary split's faces and
-- what a split does to V - E + F. After each split the lesson names the new elements, as engine/core/mesh_ops.h
-- documents them, lists every pointer the split wrote, and checks the mesh on screen. The last step runs the
-- student's own split_edge (your_turn) on a lopsided diamond, where the corners' average is not the midpoint, then
-- on the middle edge of an 80x70 grid (11200 triangles), where one that walks the whole mesh is told so.
-- CI runs it headless:
--   meshedit lesson lessons/5_edge_split.lua --headless --answers tests/lesson/lessons/5_edge_split_answers.lua \
--     --student tests/exercise/solutions
-- Invariants: the checks read the student's mesh through current_mesh() only; the new vertex is found as the
-- one vertex id the mesh did not have before (ids are appended, never reused), and the new edges, faces and
-- halfedges by split's documented order of new ids; the diagram's names are found by walking from h0, as in part 4.

lesson {
  title = "Part 5: Edge split",
  summary = "Split an edge inside a mesh and one on its boundary: predict what changes, name every new element, "
    .. "read every pointer the split wrote.",
}

local function diamond()
  return meshedit.from_polygons(
    { {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0} },
    { {1, 2, 3}, {2, 1, 4} })
end

-- The diagram's names, by walking from e's halfedge h0 (as in part 4).
local function names_of(e)
  local n = { e = e }
  n.h0 = e.halfedge
  n.h1 = n.h0.twin
  n.h2 = n.h0.next
  n.h3 = n.h2.next
  n.h4 = n.h1.next
  n.h5 = n.h4.next
  n.h6, n.h7, n.h8, n.h9 = n.h2.twin, n.h3.twin, n.h4.twin, n.h5.twin
  n.a, n.b = n.h0.vertex, n.h1.vertex
  n.c, n.d = n.h3.vertex, n.h5.vertex
  n.f0, n.f1 = n.h0.face, n.h1.face
  return n
end

local order = { "a", "b", "c", "d", "f0", "f1", "h0", "h1", "h2", "h3", "h4", "h5", "h6", "h7", "h8", "h9" }

local shape = diamond()
local e = shape:edge(0)
local names = names_of(e)
local a, b, c, d = names.a, names.b, names.c, names.d

local function label_all()
  for _, name in ipairs(order) do label(names[name], name) end
end

-- The new elements of a split of `before`, in split's documented order (ids appended after the old ones).
local function new_names(before, after)
  local V, E, F, H = before:num_vertices(), before:num_edges(), before:num_faces(), before:num_halfedges()
  local n = { m = after:vertex(V), ea = after:edge(E), ec = after:edge(E + 1), ed = after:edge(E + 2),
    g0 = after:face(F), g1 = after:face(F + 1) }
  for k = 0, 5 do n["n" .. k] = after:halfedge(H + k) end
  return n
end

-- Diagram name of an element id ("v3" -> "d", "h12" -> "n2"), for lists in the student's words.
local function namer(extra)
  local map = {}
  for _, name in ipairs(order) do map[tostring(names[name])] = name end
  map[tostring(e)] = "e"
  for name, element in pairs(extra or {}) do map[tostring(element)] = name end
  return function(id) return map[tostring(id)] or tostring(id) end
end

local grid = meshedit.grid(2, 2)
-- The first boundary edge along the bottom row (y = 0), in id order.
local rim
for edge in grid:edges() do
  local p, q = edge.halfedge.vertex.position, edge.halfedge.twin.vertex.position
  if not rim and edge:is_boundary() and p.y == 0 and q.y == 0 then rim = edge end
end

-- The mesh on screen if it is `before` with one more vertex, and valid; else false.
local function split_done(before)
  local mesh = current_mesh()
  if not mesh or mesh:num_vertices() ~= before:num_vertices() + 1 then return false end
  if not mesh:validate() then return false end
  return mesh
end

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

step("What a split does", function()
  show(shape)
  camera { fit = true, pitch = 55 }  -- a flat mesh: seen from above, its faces and arrows have room
  label_all()
  highlight(e, "yellow")
  say [[
# Edge split

A split puts a new vertex **m** in the middle of an edge and joins it to the corners across the edge. Each of
the two triangles beside the edge becomes two: the mesh gains detail exactly where you ask for it.]]
  say [[
Here is the diamond from part 4 with the same names: the yellow edge **e** joins a and b, c is above it and d
below; h0 runs a to b in f0 = (a, b, c), h1 b to a in f1 = (b, a, d), h2 to h5 go round the two faces and
h6 to h9 are their twins on the boundary loop.]]
  choose {
    "Splitting e puts m at the midpoint of a and b and joins it to c and d. How many edges does the mesh gain?",
    options = { "1", "2", "3", "4" },
    answer = "3",
    feedback = {
      ["1"] = "m is joined to c and to d: that is two edges already, and the edge from a to m is a third.",
      ["2"] = "m-c and m-d are two, but e is now two edges, a-m and m-b: one of its halves is new too.",
      ["4"] = "e is not deleted: it keeps its id (and h0, h1) as the half m-b. Only a-m, m-c and m-d are new.",
      ["3"] = "Three: ea (a to m), ec (m to c) and ed (m to d). e keeps its id as the half m-b.",
    },
    hint = "Count the edges at m after the split (four), then ask which of them is the old e.",
  }
  say [[
So a split of e gives:

- a new vertex **m** at the midpoint (a + b) / 2
- three new edges: **ea** (a to m), **ec** (m to c) and **ed** (m to d); e itself keeps its id as the half m to b
- two new faces: **g0** = (a, m, c) and **g1** = (m, a, d); f0 becomes (m, b, c) and f1 becomes (b, m, d)
- six new halfedges, **n0** to **n5**: a to m and back, m to c and back, m to d and back]]
  say("Counts go from " .. counts(shape) .. " to one more vertex, three more edges and two more faces.")
end)

step("Predict the pointers", function()
  show(shape)
  camera { fit = true, pitch = 55 }
  label_all()
  highlight(e, "yellow")
  say [[
Before the split (as in part 4):

- f0 = (a, b, c): h0.next = h2, h2.next = h3, h3.next = h0
- f1 = (b, a, d): h1.next = h4, h4.next = h5, h5.next = h1
- h0.vertex = a, h1.vertex = b; e.halfedge = h0]]
  local name = namer()
  pick {
    "The split keeps e as the half m-b, with its own two halfedges. Click the halfedge that will run from m to b.",
    answer = tostring(names.h0),
    feedback = function(x)
      if x.kind ~= "halfedge" then
        return "That is a " .. x.kind .. ": click one of the arrows."
      end
      local who = name(x)
      if who == "h1" then
        return "h1 is h0's twin: it runs b to a now, and b to m after the split, the other way."
      elseif who == "h2" or who == "h3" or who == "h4" or who == "h5" then
        return who .. " runs round a face from a corner that stays where it is; it does not lie along e."
      elseif who:match("^h[6-9]$") then
        return who .. " lies on the boundary loop, outside both faces; the split does not touch it."
      end
      return who .. " does not lie along e."
    end,
    hint = "e keeps its two halfedges. Which of them runs from a toward b now?",
  }
  say [[
Yes: **h0** is the half m-b's halfedge toward b, so it stays in f0 (now (m, b, c)), h1 runs b to m in f1, and
the new halfedge n0 takes h0's old place from a to m.]]
  choose {
    "m needs a halfedge leaving it. Which one does MeshEdit's split give it?",
    options = { "n0 (a to m)", "n1 (m to a)", "n2 (m to c)", "n3 (c to m)" },
    answer = "n1 (m to a)",
    feedback = {
      ["n0 (a to m)"] = "n0 runs from a to m: it arrives at m. A vertex's halfedge leaves it (h.vertex is the "
        .. "vertex h leaves).",
      ["n3 (c to m)"] = "n3 runs from c to m: it arrives at m. A vertex's halfedge leaves it.",
      ["n2 (m to c)"] = "n2 leaves m, but along ec, a new edge across f0. MeshEdit's split gives m n1, which "
        .. "runs along the edge it split, toward a; the checker accepts either halfedge leaving m along that edge "
        .. "(n1 toward a, or h0 toward b), and no other.",
      ["n1 (m to a)"] = "n1 leaves m along the split edge, toward a. That is the reference's choice; the checker "
        .. "also accepts h0, which leaves m along the same edge toward b.",
    },
    hint = "Two of the four leave m. Of those, one runs along the edge that was split.",
  }
end)

step("Split the middle edge", function()
  show(shape)
  camera { fit = true, pitch = 55 }
  for element, text in pairs({ [a] = "a", [b] = "b", [c] = "c", [d] = "d" }) do label(element, text) end
  highlight(e, "yellow")
  say("Click the yellow edge (`" .. tostring(e) .. "`) to select it.")
  wait_for { selection = tostring(e), hint = "Click the edge between a and b" }
  say "Now press **S** to split it."
  local mesh = wait_for { condition = function() return split_done(shape) end, hint = "Select the edge, press S" }
  local new = new_names(shape, mesh)
  local m = new.m
  local p = m.position
  local mid = (a.position + b.position) / 2
  if (p - mid):length() > 1e-9 then
    say("Hmm: the new vertex is at " .. tostring(p) .. ", not at the midpoint " .. tostring(mid) .. ".")
    return
  end
  label(m, "m")
  highlight(m, "yellow")
  highlight({ new.ea, new.ec, new.ed }, "orange")
  for _, n in ipairs({ "ea", "ec", "ed", "g0", "g1" }) do label(new[n], n) end
  say("Split. The new vertex **m** is `" .. tostring(m) .. "` at " .. tostring(p) .. ", the midpoint of a and b. "
    .. "It has " .. m:degree() .. " neighbours: a, b, c and d.")
  say("New ids are appended after the old ones: edges ea = `" .. tostring(new.ea) .. "`, ec = `" .. tostring(new.ec)
    .. "`, ed = `" .. tostring(new.ed) .. "`; faces g0 = `" .. tostring(new.g0) .. "` and g1 = `"
    .. tostring(new.g1) .. "`; halfedges n0 to n5 = `" .. tostring(new.n0) .. "` to `" .. tostring(new.n5) .. "`. "
    .. "The mesh now has " .. counts(mesh) .. ", and it passes validation.")
  local h = mesh:element(tostring(e)).halfedge
  say("The old edge e kept its id and now runs from " .. tostring(h.vertex) .. " (m) to "
    .. tostring(h.twin.vertex) .. " (b).")
end)

step("Before and after, pointer by pointer", function()
  local after = current_mesh()
  if not after or after:num_vertices() ~= shape:num_vertices() + 1 then
    after = shape:copy()
    after:split(after:edge(0))
    show(after)
    say "(The mesh on screen was not the split diamond, so here it is split again.)"
  end
  local new = new_names(shape, after)
  local name = namer(new)
  for _, n in ipairs({ "h0", "h1", "h2", "h3", "h4", "h5" }) do label(after:element(tostring(names[n])), n) end
  for k = 0, 5 do label(new["n" .. k], "n" .. k) end
  label(new.m, "m")
  choose {
    "Which of h0's fields did the split change?",
    options = { "next", "twin", "vertex", "face" },
    answer = "vertex",
    feedback = {
      next = "h0.next is still h2: f0 is now (m, b, c), h0 -> h2 -> n3, and h2 follows h0 as before.",
      twin = "h0's twin is still h1: e keeps both its halfedges as the half m-b.",
      face = "h0 stays in f0; it is f0's corners that change, from (a, b, c) to (m, b, c).",
      vertex = "Only h0.vertex: it was a, now it is m.",
    },
    hint = "h0 still runs toward b inside f0. What about where it starts?",
  }
  local changes = after:diff(shape)
  local old_lines = {}
  for _, change in ipairs(changes) do
    if not new[name(change.element)] then
      old_lines[#old_lines + 1] = "- " .. name(change.element) .. "." .. change.field .. ": " .. name(change.before)
        .. " to " .. name(change.after)
    end
  end
  say("Every field of an old element the split changed (" .. #old_lines .. "), in the diagram's names:\n\n"
    .. table.concat(old_lines, "\n"))
  say [[
And the new elements' pointers (twins h0/h1, n0/n1, n2/n3, n4/n5):

- f0 = (m, b, c): h0 -> h2 -> n3
- g0 = (a, m, c): n0 -> n2 -> h3
- f1 = (b, m, d): h1 -> n4 -> h5
- g1 = (m, a, d): n1 -> h4 -> n5
- ea.halfedge = n0, ec.halfedge = n2, ed.halfedge = n4, m.halfedge = n1; a.halfedge = n0 if it was h0]]
  say [[
When you write `split_edge` (scripts/student/split.lua), read every old element first (h0 to h5, a to d, f0, f1),
make the new ones in this order (m; ea, ec, ed; g0, g1; n0 to n5), then set every pointer above. Select an edge,
press **X** and **Run mine**: the panel puts your pointers beside the reference's.]]
end)

step("Split a boundary edge", function()
  show(grid)
  camera { fit = true, pitch = 55 }  -- flat too: seen from above
  highlight(rim, "yellow")
  local p, q = rim.halfedge.vertex, rim.halfedge.twin.vertex
  label(p, "a")
  label(q, "b")
  say [[
On the **boundary** of a mesh an edge has a face on one side only; on the other side is the boundary loop
(drawn blue).]]
  choose {
    "How many new faces does splitting the yellow boundary edge make?",
    options = { "0", "1", "2" },
    answer = "1",
    feedback = {
      ["0"] = "The triangle above the edge is still cut in two by the new edge m-c: one new face.",
      ["2"] = "Below the edge is the boundary loop, not a triangle: there is nothing there to cut, so only one "
        .. "face is new.",
      ["1"] = "One: only the triangle side is cut.",
    },
    hint = "Count the triangles beside the edge.",
  }
  say [[
A split there makes fewer new elements: one new vertex, two new edges (ea and ec), one new face (g0)
and four halfedges. The boundary loop gets one halfedge longer (n1, after h1), and **m** lies on it.]]
  say("This grid has " .. counts(grid) .. ". Click the yellow edge on its bottom row (`" .. tostring(rim)
    .. "`) to select it.")
  wait_for { selection = tostring(rim), hint = "Click the yellow boundary edge" }
  say "Now press **S** to split it."
  local mesh = wait_for { condition = function() return split_done(grid) end, hint = "Select the edge, press S" }
  local m = mesh:vertex(grid:num_vertices())
  label(m, "m")
  highlight(m, "yellow")
  local ok = m:is_boundary() and mesh:num_edges() == grid:num_edges() + 2 and mesh:num_faces() == grid:num_faces() + 1
    and mesh:num_boundaries() == 1
  if ok then
    say("Split. **m** = `" .. tostring(m) .. "` sits on the boundary at " .. tostring(m.position) .. " with "
      .. m:degree() .. " neighbours. The mesh has " .. counts(mesh) .. ": two more edges and one more face, "
      .. "still one boundary loop, and it passes validation.")
    say("m's halfedge is `" .. tostring(m.halfedge) .. "`, which lies on the boundary loop. MeshEdit's own split "
      .. "keeps a boundary vertex's halfedge on the boundary loop, but the course does not require it: a boundary "
      .. "vertex's halfedge may be any halfedge leaving it. For m, the checker and the grader ask only what they ask "
      .. "on an interior edge: that it run along the split edge (n1 toward a, or h0 toward b).")
  else
    say("That split changed more than one boundary edge would. Press **Back** to try again.")
  end
end)

step("Flip and split together", function()
  say [[
Split and flip are the two moves of Loop subdivision (part 6): split every edge, then flip the new edges that
join an old vertex to a new one.]]
  answer {
    "An interior split adds 1 vertex, 3 edges and 2 faces. By how much does V - E + F change?",
    number = 0,
    tolerance = 1e-9,
    feedback = function(value)
      if value == 6 then return "6 adds the three counts, but E counts with a minus sign: 1 - 3 + 2." end
      if value == -4 or value == -2 or value == 4 then
        return string.format("%g: check the signs, V - E + F changes by (+1) - (+3) + (+2).", value)
      end
    end,
    hint = "Put the changes into V - E + F: (+1) - (+3) + (+2).",
  }
  say [[
It does not change: V - E + F, the Euler characteristic, is the same before and after every split (a boundary
split adds 1 - 2 + 1 = 0 too) and every flip. Ctrl+Z undoes a split; try splitting and flipping on the grid
until the counts make sense to you.]]
end)

step("Your turn", function()
  -- A lopsided diamond: the average of a, b, c and d is not the midpoint of a-b, so a split that puts m at the
  -- corners' average is told so.
  local lopsided = meshedit.from_polygons(
    { {-1, 0, 0}, {1.2, 0.1, 0}, {0.5, 1.1, 0.1}, {-0.3, -0.9, -0.2} },
    { {1, 2, 3}, {2, 1, 4} })
  show(lopsided)
  camera "fit"
  local n = names_of(lopsided:edge(0))
  for _, name in ipairs(order) do label(n[name], name) end
  -- The names a wrong verdict lists beside the ids: the old elements, and m, the one new vertex (split makes it
  -- first, so its id is the next one); the new edges, faces and halfedges are named by what they join, since a
  -- split that makes them in another order gives them other ids.
  local diagram = { m = "v" .. lopsided:num_vertices() }
  for name, element in pairs(n) do diagram[name] = element end
  say [[
# Your code

Open `scripts/student/split.lua` and write `split_edge(mesh, e)`: collect the old elements, make m, the three
new edges, the two new faces and the six new halfedges, then set every pointer (the before-and-after list of the
last steps is the plan). The lesson runs yours on the edge e of this lopsided diamond each time you save the file,
beside the reference, and names what differs: m's position, a pointer that breaks a face cycle, a face that does
not hold its halfedge.]]
  your_turn {
    exercise = "split",
    mesh = lopsided,
    element = n.e,
    names = diagram,
    hint = "m goes at the midpoint of a and b; after the split every face is a triangle of three halfedges whose "
      .. "next pointers close the cycle, and each one's face is that triangle.",
  }
  -- A grid of 80 x 70 squares, each cut in two, and its diagonal with its midpoint at (40.5, 35.5), found by
  -- where it is.
  local big = meshedit.grid(80, 70)
  local middle
  for edge in big:edges() do
    local mid = (edge.halfedge.vertex.position + edge.halfedge.twin.vertex.position) * 0.5
    if mid == meshedit.vec3(40.5, 35.5, 0) then middle = edge end
  end
  say("Your `split_edge` gives the reference's answer, up to the order you made the new elements in. Last, the "
    .. "middle edge of a grid of " .. big:num_faces() .. " triangles: a split changes a fixed handful of elements "
    .. "whatever the mesh's size, and the lesson counts the elements yours touches (reads or writes), as the "
    .. "Exercises tab and the grader do.")
  your_turn {
    exercise = "split",
    mesh = big,
    element = middle,
    hint = "Walk from e.halfedge to the two triangles at e; a loop over the mesh, or a copy or a validate() of the "
      .. "whole mesh, touches every element of it.",
  }
  say [[
Your `split_edge` splits the big grid's edge as the reference does, touching only the elements around it.
Splitting a boundary edge is extra credit: the Exercises tab (**X**, **Run mine**) checks it on any boundary edge
you select, and the grading suite's boundary tests count as extra credit.]]
end)
