-- Part 4: edge flip, on the smallest mesh where a flip means something: two triangles sharing one edge (the
-- "diamond"). Every element gets the name the core's diagram gives it (engine/core/mesh_ops.h); the student
-- flips the middle edge with F and the lesson checks the result on the mesh on screen.
-- CI runs it headless:
--   meshedit lesson lessons/4_edge_flip.lua --headless --answers tests/script/lessons/4_edge_flip_answers.lua
-- Invariant: every name is found by walking from h0 = e0.halfedge, never assumed from storage order, so the
-- labels stay right whatever order the builder numbers halfedges in.

lesson {
  title = "Part 4: Edge flip",
  summary = "Two triangles, every element named; what a flip rewrites, then you flip the edge yourself.",
}

-- a, b, c, d as in the diagram: a-b is the shared edge, c above it, d below it.
local function diamond()
  return meshedit.from_polygons(
    { {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0} },
    { {1, 2, 3}, {2, 1, 4} })
end

-- The diagram's names, by walking from e's halfedge h0.
local function names_of(mesh, e)
  local n = {}
  n.e = e
  n.h0 = e.halfedge
  n.h1 = n.h0.twin
  n.h2 = n.h0.next
  n.h3 = n.h2.next
  n.h4 = n.h1.next
  n.h5 = n.h4.next
  -- The four outer halfedges run along the boundary loop, opposite h2..h5.
  n.h6, n.h7, n.h8, n.h9 = n.h2.twin, n.h3.twin, n.h4.twin, n.h5.twin
  n.a, n.b = n.h0.vertex, n.h1.vertex
  n.c, n.d = n.h3.vertex, n.h5.vertex
  n.f0, n.f1 = n.h0.face, n.h1.face
  return n
end

local order = { "a", "b", "c", "d", "f0", "f1", "h0", "h1", "h2", "h3", "h4", "h5", "h6", "h7", "h8", "h9" }

local function label_all(n)
  for _, name in ipairs(order) do label(n[name], name) end
end

-- "h2 is `h1`": the diagram's name and the id the app shows for the same element.
local function id_list(n, names)
  local parts = {}
  for _, name in ipairs(names) do parts[#parts + 1] = name .. " is `" .. tostring(n[name]) .. "`" end
  return table.concat(parts, ", ")
end

-- Diagram name of an element id ("v3" -> "d"), for describing changes in the student's words.
local function name_by_id(n)
  local map = {}
  for _, name in ipairs(order) do map[tostring(n[name])] = name end
  map[tostring(n.e)] = "e"
  return function(id) return map[id] or id end
end

local shape = diamond()
local names = names_of(shape, shape:edge(0))

step("The diamond", function()
  show(shape)
  camera { fit = true, pitch = 55 }  -- a flat mesh: seen from above, its faces and arrows have room
  label_all(names)
  highlight(names.e, "yellow")
  say [[
# Edge flip

A flip works on two triangles that share an edge. On screen is exactly that: the **diamond**, four
vertices and two faces. The yellow edge in the middle is the one we will flip; call it **e**.]]
  say [[
The labels are the names the core's diagram uses (engine/core/mesh_ops.h):

- **a** and **b** are the ends of e, **c** is the corner above it, **d** the corner below
- **h0** runs a to b inside face **f0** = (a, b, c); **h1** is its twin, running b to a inside **f1** = (b, a, d)
- around f0: h0, then **h2** (b to c), then **h3** (c to a), back to h0
- around f1: h1, then **h4** (a to d), then **h5** (d to b), back to h1
- **h6** to **h9** are the twins of h2 to h5: they run around the outside, on the boundary loop]]
  say("Every name is found by walking from h0 = e.halfedge: h2 = h0.next, h3 = h2.next, h1 = h0.twin, "
    .. "h4 = h1.next, and so on. The ids the app shows are the mesh's storage numbers, which need not match: "
    .. id_list(names, { "h0", "h1", "h2", "h3", "h4", "h5" }) .. ".")
  say [[
The CS184 handout names the same diamond with other letters: it flips the edge b-c between the triangles
(a, b, c) and (c, b, d), and its (a, b, c) is our f0. Letter by letter:

- course a, b, c, d = our c, a, b, d
- course edge b-c = our e, a-b; after the flip, course a-d = our c-d
- course (a, b, c), (c, b, d) = our f0, f1; after the flip, course (a, d, c), (a, b, d) = our f1, f0]]
  say [[
Click any label's element and press **I**: the inspector shows its next, twin, vertex, edge and face.]]
end)

step("What a flip rewrites", function()
  label_all(names)
  highlight(names.e, "yellow")
  highlight({ names.h2, names.h4 }, "orange")
  say [[
Flipping e turns it inside the quad a, d, b, c, so that it joins **d** and **c** instead of a and b. No element
is created or deleted: the same two faces, the same six inner halfedges, only their pointers change.]]
  say [[
Before the flip:

- f0 = (a, b, c): h0.next = h2, h2.next = h3, h3.next = h0
- f1 = (b, a, d): h1.next = h4, h4.next = h5, h5.next = h1
- h0.vertex = a, h1.vertex = b]]
  say [[
After the flip:

- f0 = (d, c, a): h0.next = h3, h3.next = h4, h4.next = h0
- f1 = (c, d, b): h1.next = h5, h5.next = h2, h2.next = h1
- h0.vertex = d, h1.vertex = c
- the two orange halfedges change faces: **h4** moves into f0 and **h2** into f1
- a vertex whose halfedge was h0 (or h1) must take another one, since h0 no longer leaves it]]
  say [[
Twins, edges and everything outside the two triangles stay as they were. A flip is refused on a boundary
edge (there is only one triangle) and when c and d are already joined (the flip would duplicate an edge).]]
end)

step("Flip it yourself", function()
  label_all(names)
  highlight(names.e, "yellow")
  say("Click the yellow edge **e** (it is `" .. tostring(names.e) .. "`) to select it.")
  wait_for { selection = tostring(names.e), hint = "Click the edge between a and b" }
  say [[
Now press **F** to flip it.]]
  local a, b, c, d = tostring(names.a), tostring(names.b), tostring(names.c), tostring(names.d)
  local result = wait_for {
    hint = "Press F to flip the selected edge",
    condition = function()
      local mesh = current_mesh()
      if not mesh or not mesh:validate() then return false end
      local h = mesh:element(tostring(names.e)).halfedge
      local from, to = tostring(h.vertex), tostring(h.twin.vertex)
      if (from == d and to == c) or (from == c and to == d) then return mesh end
      return false
    end,
  }
  local h = result:element(tostring(names.e)).halfedge
  local name = name_by_id(names)
  say("Flipped. e now runs from **" .. name(tostring(h.vertex)) .. "** to **" .. name(tostring(h.twin.vertex))
    .. "**, and the mesh still passes validation.")
  highlight(result:element(tostring(names.e)), "yellow")
end)

step("Before and after, pointer by pointer", function()
  local after = current_mesh()
  local name = name_by_id(names)
  local changes = after:diff(shape)
  local lines = {}
  for _, change in ipairs(changes) do
    lines[#lines + 1] = "- " .. name(change.element) .. "." .. change.field .. ": " .. name(change.before) .. " to "
      .. name(change.after)
  end
  say("Here is every field the flip changed (" .. #changes .. " in all), in the diagram's names:\n\n"
    .. table.concat(lines, "\n"))
  say [[
Compare them with the *after* list of the previous step: that list is your specification. The pointer tables
below the view show the same thing: the changed cells are highlighted, and the **changes** tab lists them.]]
  for _, change in ipairs(changes) do highlight(change.element, "orange") end
  say [[
When you write `flip_edge` yourself, collect every element first (h0 to h5, a to d, f0, f1), then set
every pointer. Press **F** three more times in the app: after four flips every pointer is back where it
started. To run your own `flip_edge` (scripts/student/flip.lua), select an edge, press **X** and **Run
mine**: the panel puts your pointers beside the reference's and replays your writes one by one.]]
end)
