-- Part 5: edge split. First an interior edge (the diamond of part 4, with the same names), then an edge on the
-- boundary of a grid. After each split the lesson names the new elements, as engine/core/mesh_ops.h documents
-- them, and checks the mesh on screen: validation, counts, where the new vertex is and how it is connected.
-- CI runs it headless:
--   meshedit lesson lessons/5_edge_split.lua --headless --answers tests/script/lessons/5_edge_split_answers.lua
-- Invariant: the checks read the student's mesh through current_mesh() only; the new vertex is found as the
-- one vertex id the mesh did not have before (ids are appended, never reused).

lesson {
  title = "Part 5: Edge split",
  summary = "Split an edge inside a mesh and one on its boundary; name every new element and check the result.",
}

local function diamond()
  return meshedit.from_polygons(
    { {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0} },
    { {1, 2, 3}, {2, 1, 4} })
end

local shape = diamond()
local e = shape:edge(0)
local a, b = e.halfedge.vertex, e.halfedge.twin.vertex
local c, d = e.halfedge.next.next.vertex, e.halfedge.twin.next.next.vertex

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
  for element, text in pairs({ [a] = "a", [b] = "b", [c] = "c", [d] = "d" }) do label(element, text) end
  label(shape:face(0), "f0")
  label(shape:face(1), "f1")
  highlight(e, "yellow")
  say [[
# Edge split

A split puts a new vertex **m** in the middle of an edge and joins it to the corners across the edge. Each of
the two triangles beside the edge becomes two: the mesh gains detail exactly where you ask for it.]]
  say [[
Here is the diamond from part 4 again: the yellow edge **e** joins a and b, c is above it and d below.
Splitting e gives:

- a new vertex **m** at the midpoint (a + b) / 2
- three new edges: **ea** (a to m), **ec** (m to c) and **ed** (m to d); e itself keeps its id as the half m to b
- two new faces: **g0** = (a, m, c) and **g1** = (m, a, d); f0 becomes (m, b, c) and f1 becomes (b, m, d)
- six new halfedges, **n0** to **n5**: a to m and back, m to c and back, m to d and back]]
  say("Counts go from " .. counts(shape) .. " to one more vertex, three more edges and two more faces.")
end)

step("Split the middle edge", function()
  show(shape)
  for element, text in pairs({ [a] = "a", [b] = "b", [c] = "c", [d] = "d" }) do label(element, text) end
  highlight(e, "yellow")
  say("Click the yellow edge (`" .. tostring(e) .. "`) to select it.")
  wait_for { selection = tostring(e), hint = "Click the edge between a and b" }
  say "Now press **S** to split it."
  local mesh = wait_for { condition = function() return split_done(shape) end, hint = "Select the edge, press S" }
  local m = mesh:vertex(shape:num_vertices())
  local p = m.position
  local mid = (a.position + b.position) / 2
  if (p - mid):length() > 1e-9 then
    say("Hmm: the new vertex is at " .. tostring(p) .. ", not at the midpoint " .. tostring(mid) .. ".")
    return
  end
  label(m, "m")
  highlight(m, "yellow")
  local E, F, H = shape:num_edges(), shape:num_faces(), shape:num_halfedges()
  local ea, ec, ed = mesh:edge(E), mesh:edge(E + 1), mesh:edge(E + 2)
  highlight({ ea, ec, ed }, "orange")
  label(ea, "ea")
  label(ec, "ec")
  label(ed, "ed")
  label(mesh:face(F), "g0")
  label(mesh:face(F + 1), "g1")
  say("Split. The new vertex **m** is `" .. tostring(m) .. "` at " .. tostring(p) .. ", the midpoint of a and b. "
    .. "It has " .. m:degree() .. " neighbours: a, b, c and d.")
  say("New ids are appended after the old ones: edges ea = `" .. tostring(ea) .. "`, ec = `" .. tostring(ec)
    .. "`, ed = `" .. tostring(ed) .. "`; faces g0 = `" .. tostring(mesh:face(F)) .. "` and g1 = `"
    .. tostring(mesh:face(F + 1)) .. "`; halfedges n0 to n5 = `" .. tostring(mesh:halfedge(H)) .. "` to `"
    .. tostring(mesh:halfedge(H + 5)) .. "`. "
    .. "The mesh now has " .. counts(mesh) .. ", and it passes validation.")
  local h = mesh:element(tostring(e)).halfedge
  say("The old edge e kept its id and now runs from " .. tostring(h.vertex) .. " (m) to "
    .. tostring(h.twin.vertex) .. " (b).")
end)

step("Split a boundary edge", function()
  show(grid)
  camera "fit"
  highlight(rim, "yellow")
  local p, q = rim.halfedge.vertex, rim.halfedge.twin.vertex
  label(p, "a")
  label(q, "b")
  say [[
On the **boundary** of a mesh an edge has a face on one side only; on the other side is the boundary loop
(drawn blue). A split there makes only half the new elements: one new vertex, two new edges (ea and ec),
one new face (g0) and four halfedges. The boundary loop gets one halfedge longer, and **m** lies on it.]]
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
      .. "keeps a boundary vertex's halfedge on the boundary loop, but the course does not require it: any halfedge "
      .. "leaving m will do, and neither the checker nor the grader asks for more.")
  else
    say("That split changed more than one boundary edge would. Press **Back** to try again.")
  end
end)

step("Flip and split together", function()
  say [[
Split and flip are the two moves of Loop subdivision (part 6): split every edge, then flip the new edges that
join an old vertex to a new one. Ctrl+Z undoes a split; try splitting and flipping on the grid until the
counts make sense to you: every interior split adds 1 vertex, 3 edges and 2 faces, so V - E + F stays the same.]]
end)
