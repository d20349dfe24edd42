-- Part 4: edge flip, on the smallest mesh where a flip means something: two triangles sharing one edge (the
-- "diamond"). Every element gets the name the core's diagram gives it (engine/core/mesh_ops.h). Each step asks
-- before it tells: the student clicks h0.next, finds the course's edge, predicts the pointers a flip sets (on a
-- diamond whose faces and vertices point at the halfedges the flip moves, so the classic "forgot f0.halfedge" bug
-- shows), predicts how many fields a flip changes in an 80x70 grid of 11200 triangles (then sees the count the core's
-- flip gives, by m:diff, against the 3 x 11200 corners a rebuild of the face list writes), flips the edge with F, and
-- the lesson checks every answer on the mesh on screen. The last step runs the student's own flip_edge
-- (scripts/student/flip.lua) with your_turn on that diamond, on its boundary edge and on the big grid's edge (where
-- the Exercises tab's locality check applies), and waits until each is right.
-- CI runs it headless, with the correct solutions and with buggy ones (tests/lesson/lesson_student_test.cpp):
--   meshedit lesson lessons/4_edge_flip.lua --headless --answers tests/lesson/lessons/4_edge_flip_answers.lua \
--     --student tests/exercise/solutions
-- Invariants: every name is found by walking from h0 = e0.halfedge, never assumed from storage order, so the
-- labels stay right whatever order the builder numbers halfedges in; the big grid's edge is found by where it is;
-- every count the text gives is counted at run time (the question asks before the count is said).

lesson {
  title = "Part 4: Edge flip",
  summary = "Two triangles, every element named; predict what a flip rewrites, then flip the edge yourself.",
}

-- a, b, c, d as in the diagram: a-b is the shared edge, c above it, d below it.
local function diamond()
  return meshedit.from_polygons(
    { {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0} },
    { {1, 2, 3}, {2, 1, 4} })
end

-- The diagram's names, by walking from e's halfedge h0.
local function names_of(e)
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
local names = names_of(shape:edge(0))
local name = name_by_id(names)

-- The same diamond with the faces and a, b pointing at the halfedges a flip takes away from them: f0.halfedge =
-- h2 (which the flip moves into f1), f1.halfedge = h4 (moves into f0), a.halfedge = h0 (will leave d),
-- b.halfedge = h1 (will leave c). Every one of these is allowed (any halfedge of the face, any halfedge leaving
-- the vertex); the flip has to change all four. Same ids as `shape`, so `names` and `name` hold for it too.
local function rigged_diamond()
  local m = diamond()
  local n = names_of(m:edge(0))
  n.f0.halfedge, n.f1.halfedge = n.h2, n.h4
  n.a.halfedge, n.b.halfedge = n.h0, n.h1
  return m
end
local rigged = rigged_diamond()

-- A grid of 80 x 70 squares, each cut in two by a diagonal: 11200 triangles. `big_edge` is the diagonal from the
-- vertex at (40, 35) to the one at (41, 36), found by where it is.
local function diagonal_at(mesh, x, y)
  for edge in mesh:edges() do
    local p, q = edge.halfedge.vertex.position, edge.halfedge.twin.vertex.position
    if p.x > q.x then p, q = q, p end
    if p.x == x and p.y == y and q.x == x + 1 and q.y == y + 1 then return edge end
  end
end
local big = meshedit.grid(80, 70)
local big_edge = diagonal_at(big, 40, 35)

-- The clicked element in the diagram's words, for feedback: "h4 (id h4)", "the edge b-c".
local function what(element)
  if element.kind == "edge" then
    local h = element.halfedge
    return "an edge (" .. name(tostring(h.vertex)) .. "-" .. name(tostring(h.twin.vertex)) .. ")"
  end
  return "a " .. element.kind .. " (" .. name(tostring(element)) .. ")"
end

-- Feedback for a click that should have been a halfedge inside a face; nil when it is one.
local function not_a_halfedge(element)
  if element.kind ~= "halfedge" then
    return "That is " .. what(element) .. ", not a halfedge: click one of the arrows beside the edges."
  end
  local n = name(tostring(element))
  if n == "h6" or n == "h7" or n == "h8" or n == "h9" then
    return n .. " runs around the outside, on the boundary loop: it is in no face."
  end
end

step("The diamond", function()
  show(shape)
  camera { fit = true, pitch = 55 }  -- a flat mesh: seen from above, its faces and arrows have room
  view { labels = true, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  say [[
# Edge flip

A flip works on two triangles that share an edge. On screen is exactly that: the **diamond**, four
vertices and two faces. The yellow edge in the middle is the one we will flip; call it **e**.]]
  say("Two kinds of label are on screen. The **names** (a to d, f0, f1, h0 to h9) are the core's diagram's "
    .. "(engine/core/mesh_ops.h), found by walking from h0 = e.halfedge; this lesson uses them. The **ids** "
    .. "(v0, e0, h3...) are the mesh's storage numbers, which the inspector and the pointer tables show; they "
    .. "need not match: " .. id_list(names, { "h0", "h1", "h2", "h3", "h4", "h5" })
    .. ". From the next step on only the names are drawn.")
  say [[
**h0** runs from a to b inside face **f0**; **h1** is its twin, b to a, inside **f1**.]]
  pick {
    "Click the halfedge that is h0.next.",
    answer = function(element)
      if tostring(element) == tostring(names.h2) then
        return true, "The arrow named h2 (its id is " .. tostring(names.h2) .. ") runs b to c, after h0 in f0."
      end
      return false
    end,
    feedback = function(element)
      local wrong = not_a_halfedge(element)
      if wrong then return wrong end
      local n = name(tostring(element))
      if n == "h0" then return "That is h0 itself; h0.next is the halfedge after it." end
      if n == "h1" then
        return "That is h1 = h0.twin: the same edge the other way, in the other face. next stays in h0's face."
      end
      if n == "h3" then return "That is h3, the halfedge before h0 (h3.next = h0): next starts where h0 ends, at b." end
      if n == "h4" or n == "h5" then return n .. " is in f1, the other face; h0.next stays in f0 with h0." end
    end,
    hint = "h0 ends at b. Its next starts at b and stays in f0.",
  }
  say [[
Yes: h0.next is **h2**. The rest of the names follow the same walk:

- **a** and **b** are the ends of e, **c** is the corner above it, **d** the corner below
- around f0 = (a, b, c): h0, then **h2** (b to c), then **h3** (c to a), back to h0
- around f1 = (b, a, d): h1, then **h4** (a to d), then **h5** (d to b), back to h1
- **h6** to **h9** are the twins of h2 to h5: they run around the outside, on the boundary loop]]
  say [[
Click any element and press **I**: the inspector shows every field it stores (for a halfedge: next, twin, vertex,
edge and face).]]
end)

step("The course's letters", function()
  show(shape)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = false }  -- no arrows: a click on an edge's line picks the edge
  local course = { a = "b", b = "c", c = "a", d = "d" }  -- ours -> the handout's (flip.lua's table)
  for _, v in ipairs { "a", "b", "c", "d" } do label(names[v], v .. ", course " .. course[v]) end
  label(names.f0, "f0")
  label(names.f1, "f1")
  for edge in shape:edges() do highlight(edge, "grey") end  -- the lines to click, all alike
  say [[
The CS184 handout draws the same diamond with other letters. Each corner is labelled with our name, then the
handout's. The handout flips the edge **b-c** between its triangles (a, b, c) and (c, b, d).]]
  pick {
    "Click the edge the handout calls b-c.",
    answer = names.e,
    feedback = function(element)
      if element.kind == "halfedge" then
        return "That is a halfedge, not an edge: click the middle of an edge's line."
      end
      if element.kind ~= "edge" then return "That is " .. what(element) .. ": click an edge's line." end
      local h = element.halfedge
      local p, q = name(tostring(h.vertex)), name(tostring(h.twin.vertex))
      return "That edge joins our " .. p .. " and " .. q .. ", which the handout calls " .. course[p] .. "-"
        .. course[q] .. ". Read the second letter of each label."
    end,
    hint = "Find the corners labelled course b and course c.",
  }
  choose {
    "After the flip the handout has the triangles (a, d, c) and (a, b, d). Which of our faces is its (a, d, c)?",
    options = { "f0", "f1" },
    answer = "f1",
    feedback = {
      f0 = "Our f0 ends up as (d, c, a), which is the handout's (d, a, b): its (a, b, d), not (a, d, c).",
      f1 = "Its (a, d, c) is our (c, d, b): f1 after the flip.",
    },
    hint = "Turn each of the handout's letters into ours first: its a is our c, its d our d, its c our b.",
  }
  say [[
Letter by letter:

- course a, b, c, d = our c, a, b, d
- course edge b-c = our e, a-b; after the flip, course a-d = our c-d
- course (a, b, c), (c, b, d) = our f0, f1; after the flip, course (a, d, c), (a, b, d) = our f1, f0

Your template scripts/student/flip.lua has the same table.]]
end)

step("Predict the flip", function()
  show(shape)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  say [[
Flipping e turns it inside the quad a, d, b, c, so that it joins **d** and **c** instead of a and b. No element
is created or deleted: the same two faces, the same six inner halfedges, only their pointers change. After
the flip h0 runs from **d to c** inside f0, and h1 from c to d inside f1. Predict the rest.]]
  choose {
    "After the flip, which halfedge is h0.next?",
    options = { "h1", "h2", "h3", "h4", "h5" },
    answer = "h3",
    feedback = {
      h1 = "h1 is h0's twin, and a flip changes no twin: next is a different pointer.",
      h2 = "h2 is h0.next now, before the flip. After it h2 runs b to c inside f1, and h0 is in f0.",
      h4 = "h4 runs a to d, but h0 will end at c: its next must start at c.",
      h5 = "h5 stays in f1 (it runs d to b); h0.next is in f0, with h0.",
      h3 = "h0 ends at c, and h3 runs c to a inside f0.",
    },
    hint = "After the flip h0 ends at c. Which halfedge of f0 starts at c?",
  }
  pick {
    "One halfedge of f1 moves into f0. Click it.",
    answer = function(element)
      if tostring(element) == tostring(names.h4) then return true, "h4 (a to d) becomes a side of f0 = (d, c, a)." end
      return false
    end,
    feedback = function(element)
      local wrong = not_a_halfedge(element)
      if wrong then return wrong end
      local n = name(tostring(element))
      if n == "h2" then return "h2 moves the other way: out of f0 into f1." end
      if n == "h0" or n == "h1" then return n .. " is a halfedge of e: it keeps its face, only its ends change." end
      if n == "h3" then return "h3 is in f0 already, and stays there." end
      if n == "h5" then return "h5 stays in f1: f1 becomes (c, d, b) = h1, h5, h2." end
    end,
    hint = "f0 becomes the triangle (d, c, a). Which of its sides is in f1 now?",
  }
  say [[
The whole *after* list:

- f0 = (d, c, a): h0.next = h3, h3.next = h4, h4.next = h0
- f1 = (c, d, b): h1.next = h5, h5.next = h2, h2.next = h1
- h0.vertex = d, h1.vertex = c
- **h4** moves into f0 and **h2** into f1 (h4.face = f0, h2.face = f1)

Twins, edges and everything outside the two triangles stay as they were. A flip is refused on a boundary
edge (there is only one triangle) and when c and d are already joined (the flip would duplicate an edge).]]
  highlight({ names.h2, names.h4 }, "orange")
end)

step("The pointers that are easy to forget", function()
  show(rigged)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  highlight({ names.f0, names.h2 }, "orange")
  highlight({ names.a, names.h0 }, "cyan")
  say [[
The list above is not all. This is the same diamond, but its faces and vertices store other halfedges, as
they may (any halfedge of the face, any halfedge leaving the vertex): **f0.halfedge = h2** (orange),
f1.halfedge = h4, **a.halfedge = h0** (sky blue) and b.halfedge = h1. The flip moves exactly those halfedges away.]]
  pick {
    "After the flip h2 is in f1. Click a halfedge f0.halfedge may point to after the flip.",
    answer = function(element)
      local n = element.kind == "halfedge" and name(tostring(element))
      if n == "h0" or n == "h3" or n == "h4" then
        return true, "The arrow named " .. n .. " (its id is " .. tostring(element) .. ") is in f0 after the flip."
      end
      return false
    end,
    feedback = function(element)
      local wrong = not_a_halfedge(element)
      if wrong then return wrong end
      local n = name(tostring(element))
      if n == "h2" then
        return "h2 is what f0.halfedge holds now; after the flip h2 is in f1. Leaving it is the classic bug."
      end
      if n == "h1" or n == "h5" then return n .. " is in f1 after the flip, not f0." end
    end,
    hint = "After the flip f0 = (d, c, a) is made of h0, h3 and h4.",
  }
  choose {
    "a.halfedge is h0, which after the flip runs d to c. Which halfedge must a.halfedge become?",
    options = { "h0", "h3", "h4" },
    answer = "h4",
    feedback = {
      h0 = "After the flip h0 leaves d, not a: the validator says 'a.halfedge is h0, but h0 leaves d'.",
      h3 = "h3 runs c to a: it ends at a. A vertex's halfedge must leave the vertex.",
      h4 = "h4 runs a to d inside f0: it leaves a. (b likewise takes h2.)",
    },
    hint = "v.halfedge must start at v. Which of these starts at a after the flip?",
  }
  -- A flip that rewrites only the list of the previous step, run on a copy: what validation says of it.
  local broken = rigged:copy()
  local n = names_of(broken:edge(0))
  n.h0.next, n.h3.next, n.h4.next = n.h3, n.h4, n.h0
  n.h1.next, n.h5.next, n.h2.next = n.h5, n.h2, n.h1
  n.h0.vertex, n.h1.vertex = n.d, n.c
  n.h4.face, n.h2.face = n.f0, n.f1
  local ok, report = broken:validate()
  local lines = {}
  for _, v in ipairs(ok and {} or report.violations) do
    local named = v.message:gsub("%a%d+", function(id) return name(id) end)
    lines[#lines + 1] = "- " .. named
  end
  say("A flip that sets only the next, vertex and face pointers leaves this diamond broken. The validator "
    .. "finds " .. #lines .. " problems (in the diagram's names):\n\n" .. table.concat(lines, "\n"))
  say [[
On the first diamond none of the four pointed at a moved halfedge, so a flip that forgets them looks right
there and breaks on the next edge. So: after the next, vertex and face pointers, set **f0.halfedge = h0**,
**f1.halfedge = h1**, and a.halfedge = h4 if it was h0, b.halfedge = h2 if it was h1.]]
end)

step("One flip in a big mesh", function()
  local faces, halfedges = big:num_faces(), big:num_halfedges()
  -- The flip, on a copy, before asking: every field whose value differs afterwards, by m:diff.
  local flipped = big:copy()
  assert(flipped:flip(flipped:element(tostring(big_edge))))
  local changes = flipped:diff(big)
  local count = #changes
  local corners = 3 * faces  -- what a rebuild of the face list writes
  show(big)
  view { labels = false, halfedges = false }
  local h = big_edge.halfedge
  camera { target = (h.vertex.position + h.twin.vertex.position) * 0.5, distance = 10, pitch = 55 }
  highlight(big_edge, "yellow")
  say("# A flip in a big mesh\n\nThis grid has **" .. faces .. " triangles** (80 by 70 squares, each cut in "
    .. "two), " .. halfedges .. " halfedges. The yellow edge in its middle is a diagonal like e: two triangles "
    .. "share it. A program that keeps only a list of triangles changes one by writing the list again; the "
    .. "halfedge mesh is built for the other way.")
  answer {
    "Flip the yellow edge: how many fields of the mesh change (a field is one pointer of one element, such as "
      .. "h0.next or f0.halfedge)?",
    number = count,
    tolerance = 4,
    feedback = function(value)
      if value >= faces / 4 then
        return "That is about every element: a rebuild of the face list rewrites every face's corners (3 x "
          .. faces .. " = " .. corners .. " numbers). A flip only rewires the two triangles at the edge."
      end
      if value < count then
        return "The diagonal's two halfedges change (h0.vertex and h1.vertex), but so do the next pointers of all "
          .. "six halfedges of the two triangles, and the face of the two halfedges that move."
      end
      return "Nothing outside the two triangles at the edge changes, and only some fields inside them: count the "
        .. "after-list of \"Predict the flip\" and the pointers of \"The pointers that are easy to forget\"."
    end,
    hint = "The diamond's flip changed the next, vertex and face pointers of its list, and some face and vertex "
      .. "pointers. Does the rest of the mesh matter?",
  }
  show(flipped)
  local kinds, order_of_kinds = {}, { "halfedge", "vertex", "edge", "face" }
  local plural_of = { halfedge = "halfedges", vertex = "vertices", edge = "edges", face = "faces" }
  for _, change in ipairs(changes) do
    local kind = flipped:element(change.element).kind
    kinds[kind] = kinds[kind] or {}
    kinds[kind][change.element] = true
    highlight(change.element, "orange")
  end
  local parts, elements = {}, 0
  for _, kind in ipairs(order_of_kinds) do
    local n = 0
    for _ in pairs(kinds[kind] or {}) do n = n + 1 end
    if n > 0 then parts[#parts + 1] = n .. " " .. (n == 1 and kind or plural_of[kind]) end
    elements = elements + n
  end
  say("The flip changed **" .. count .. " fields** (each a field of one element whose value differs after the "
    .. "flip, as m:diff lists them) of " .. elements .. " elements: " .. table.concat(parts, ", ")
    .. ", all in the two triangles at the edge (orange); the other " .. (faces - 2)
    .. " triangles keep every field. Writing the face list again instead writes 3 corners of each of the "
    .. faces .. " faces, **" .. corners .. " numbers**, about " .. math.floor(corners / count + 0.5)
    .. " times as many, before the halfedges are built from it again; and that grows with the mesh, where the "
    .. "flip's count does not.")
  say [[
That is why the course writes flips and splits on a halfedge mesh: each is a fixed handful of pointers, found by
walking from e.halfedge. Your `flip_edge` is held to it: on a mesh this big the Exercises tab and the grader count
the elements it touches (reads or writes), and one that loops over `mesh:halfedges()` to find a halfedge, or reads
the whole mesh with `mesh:copy()` or `mesh:validate()`, is wrong even when the mesh it leaves is right.]]
end)

step("Flip it yourself", function()
  show(rigged)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  say("This is the diamond of \"The pointers that are easy to forget\", with f0.halfedge = h2 and a.halfedge = h0. "
    .. "Click the yellow edge **e** (its id is `" .. tostring(names.e) .. "`) to select it.")
  wait_for { selection = tostring(names.e), hint = "Click the edge between a and b" }
  say [[
Now press **F** to flip it.]]
  local c, d = tostring(names.c), tostring(names.d)
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
  say("Flipped. e now runs from **" .. name(tostring(h.vertex)) .. "** to **" .. name(tostring(h.twin.vertex))
    .. "**, and the mesh still passes validation.")
  highlight(result:element(tostring(names.e)), "yellow")
end)

step("Before and after, pointer by pointer", function()
  local after = current_mesh()
  view { labels = false }
  label_all(names)
  local changes = after:diff(rigged)
  local lines = {}
  for _, change in ipairs(changes) do
    lines[#lines + 1] = "- " .. name(change.element) .. "." .. change.field .. ": " .. name(change.before) .. " to "
      .. name(change.after)
  end
  say("Here is every field the flip changed (" .. #changes .. " in all), in the diagram's names:\n\n"
    .. table.concat(lines, "\n"))
  say [[
The ten next, vertex and face fields are the *after* list; the other four are the face and vertex pointers of
the previous step. The pointer tables beside the view show the same: the changed cells are highlighted, and the
**changes** tab lists them.]]
  for _, change in ipairs(changes) do highlight(change.element, "orange") end
  answer {
    "Press F again and again: after how many flips of e in a row is every halfedge pointer back where it started?",
    number = 4,
    tolerance = 0,
    feedback = function(value)
      if value == 2 then
        return "After 2 flips e joins a and b again, but h0 runs b to a: the two triangles have traded faces."
      end
      if value == 1 then return "One flip is what you just did: e joins c and d." end
      if value == 3 then return "After 3 flips e joins c and d again, with h0 running c to d." end
    end,
    hint = "Each flip moves both ends of e one corner on around the quad a, d, b, c.",
  }
  say [[
Four: each flip moves each end of e one corner on, and the quad has four corners. The face and vertex
pointers stay as the first flip left them, which is fine: any halfedge of the face, any leaving the vertex.]]
  show(rigged)
  clear()
  label_all(names)
  say [[
**Your turn.** Write `flip_edge` in scripts/student/flip.lua: collect every element first (h0 to h5, a to d,
f0, f1), then set every pointer. Below, the lesson runs your `flip_edge` on this diamond's edge e (with
f0.halfedge = h2 and a.halfedge = h0, as in the last steps) beside the reference, and says what differs. Save
the file and it runs again; the lesson goes on when yours gives the reference's answer. The Exercises tab (**X**,
**Run mine**) runs the same check on any edge and replays your writes one by one.]]
  your_turn {
    exercise = "flip",
    mesh = rigged,
    element = names.e,
    names = names,  -- a wrong verdict lists the diagram's names of the ids it mentions
    hint = "After the flip f0 holds h0, h3, h4 and f1 holds h1, h5, h2: set each face's and each vertex's halfedge "
      .. "to one that is still in it or still leaves it.",
  }
  say [[
Your `flip_edge` gives the reference's answer, pointer for pointer up to renumbering. One more case: the edge
a-c has a face on one side only. There is no second triangle to turn the edge inside, so `flip_edge` must leave
the mesh as it is (and return nothing). The lesson runs yours on a-c next.]]
  your_turn {
    exercise = "flip",
    mesh = rigged,
    element = names.h7.edge,
    names = names,
    hint = "If the face of e.halfedge or of its twin is a boundary face (f:is_boundary()), return before any write.",
  }
  say("Your `flip_edge` leaves a boundary edge alone, as the reference does. Last, the yellow edge in the middle "
    .. "of the grid of " .. big:num_faces() .. " triangles (step \"One flip in a big mesh\"): the lesson runs "
    .. "yours there and counts the elements it touches, as the Exercises tab and the grader do.")
  your_turn {
    exercise = "flip",
    mesh = big,
    element = big_edge,
    hint = "Walk from e.halfedge: in a triangle the halfedge before h0 is h0.next.next. A loop over the mesh's "
      .. "halfedges, or a copy or a validate() of the whole mesh, touches every element of it.",
  }
  say "Your `flip_edge` changes the big grid as the reference does, touching only the elements around the edge."
end)
