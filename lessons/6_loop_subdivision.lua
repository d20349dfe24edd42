-- Part 6: Loop subdivision, phase by phase. The lesson runs the four phases itself in Lua (the same phases the
-- app's Shift+L steps through, engine/core/loop_subdivision.h), shows the mesh after each, and checks the
-- result against the app's own one-call subdivision. Then the student runs the app's phases with Shift+L, each
-- checked against the Lua ones, meets the cube's asymmetry and fixes it by pre-splitting, sees how corners
-- round off, and subdivides a mesh with a boundary.
-- CI runs it headless:
--   meshedit lesson lessons/6_loop_subdivision.lua --headless \
--     --answers tests/script/lessons/6_loop_subdivision_answers.lua
-- Invariants: every step rebuilds its meshes from scratch (Back runs a step again, and must not subdivide
-- twice); the Lua phases use the course weights and split edges in id order, so their ids match the core's.

lesson {
  title = "Part 6: Loop subdivision",
  summary = "Loop subdivision in four phases, the cube's asymmetry and the pre-split fix, sharp corners, and "
    .. "a mesh with a boundary.",
}

local function index(element) return tonumber(tostring(element):sub(2)) end

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

local function fmt(x) return string.format("%.4f", x) end

-- ---- the four phases, on a closed triangle mesh, course weights ----

-- Phase 1: positions from the original mesh; nothing changes yet.
local function phase1(mesh)
  local state = { V = mesh:num_vertices(), E = mesh:num_edges(), vertex = {}, edge = {}, u = {} }
  for v in mesh:vertices() do
    local n = v:degree()
    local u = n == 3 and 3 / 16 or 3 / (8 * n)
    local sum = meshedit.vec3(0, 0, 0)
    for w in v:neighbors() do sum = sum + w.position end
    state.vertex[index(v)] = v.position * (1 - n * u) + sum * u
    state.u[index(v)] = u
  end
  for e in mesh:edges() do
    local h = e.halfedge
    local a, b = h.vertex.position, h.twin.vertex.position
    local c, d = h.next.next.vertex.position, h.twin.next.next.vertex.position
    state.edge[index(e)] = (a + b) * (3 / 8) + (c + d) * (1 / 8)
  end
  return state
end

-- Phase 2: split every original edge (ids 0..E-1); remember the new vertices and the edges that cut across faces.
local function phase2(mesh, state)
  state.new_position = {}
  for i, p in pairs(state.vertex) do state.new_position[i] = p end
  state.cross = {}
  for i = 0, state.E - 1 do
    local before = mesh:num_edges()
    local m = assert(mesh:split(mesh:edge(i)))
    state.new_position[index(m)] = state.edge[i]
    -- split() appends ea, ec, ed: ec and ed cut across the old faces.
    state.cross[#state.cross + 1] = before + 1
    state.cross[#state.cross + 1] = before + 2
  end
end

-- Phase 3: flip every cross edge that joins an old vertex and a new one.
local function phase3(mesh, state)
  state.flipped = {}
  for _, i in ipairs(state.cross) do
    local h = mesh:edge(i).halfedge
    local old_a, old_b = index(h.vertex) < state.V, index(h.twin.vertex) < state.V
    if old_a ~= old_b then
      assert(mesh:flip(mesh:edge(i)))
      state.flipped[#state.flipped + 1] = i
    end
  end
end

-- Phase 4: every vertex to its computed position.
local function phase4(mesh, state)
  for v in mesh:vertices() do v.position = state.new_position[index(v)] end
end

-- A fresh cube after the first `phases` phases.
local function cube_after(phases)
  local mesh = meshedit.cube()
  local state = phase1(mesh)
  if phases >= 2 then phase2(mesh, state) end
  if phases >= 3 then phase3(mesh, state) end
  if phases >= 4 then phase4(mesh, state) end
  return mesh, state
end

-- Distances of the 8 corners (ids 0..7 survive subdivision) from the centre: smallest and largest.
local function corner_range(mesh)
  local lo, hi = math.huge, 0
  for i = 0, 7 do
    local r = mesh:vertex(i).position:length()
    lo, hi = math.min(lo, r), math.max(hi, r)
  end
  return lo, hi
end

-- The six face diagonals of the 12-triangle cube: the edges longer than 1.
local function diagonals(mesh)
  local list = {}
  for e in mesh:edges() do
    local h = e.halfedge
    if (h.vertex.position - h.twin.vertex.position):length() > 1.01 then list[#list + 1] = e end
  end
  return list
end

step("Four phases", function()
  show(meshedit.cube())
  camera "fit"
  say [[
# Loop subdivision

Loop subdivision turns a coarse triangle mesh into a smoother one: every triangle becomes four, and every vertex
moves to a weighted average of its neighbours. Repeat it and the mesh converges to a smooth surface.]]
  say [[
It is done in four phases, and the app's **Shift+L** runs them one at a time (L runs all four):

- **1. new positions**: compute where every old vertex goes, and where a new vertex on each edge will go
- **2. split every edge** of the original mesh (never the new ones)
- **3. flip** every new edge that joins an old vertex to a new one
- **4. move** every vertex to the position computed in phase 1]]
  say("Counts afterwards: V' = V + E, E' = 2E + 3F, F' = 4F. The cube has " .. counts(meshedit.cube())
    .. ", so one step gives 26 vertices, 72 edges and 48 faces. Press **Next** to watch each phase.")
end)

step("Phase 1: new positions", function()
  local mesh, state = cube_after(1)
  show(mesh)
  local v0 = mesh:vertex(0)
  local e0 = mesh:edge(0)
  highlight(v0, "yellow")
  highlight(e0, "orange")
  label(v0, "degree " .. v0:degree() .. ", u = " .. fmt(state.u[0]))
  say [[
Every position is computed from the **original** mesh, before anything changes (that is why this phase
only stores numbers):

- an old vertex with n neighbours moves to (1 - n u) p + u (sum of neighbours), with u = 3/16 when n = 3 and
  u = 3/(8n) otherwise
- the new vertex on an edge a-b, with c and d the corners opposite it, goes to 3/8 (a + b) + 1/8 (c + d)]]
  say("The yellow vertex `v0` has " .. v0:degree() .. " neighbours, so u = " .. fmt(state.u[0]) .. ": it will go from "
    .. tostring(v0.position) .. " to " .. tostring(state.vertex[0]) .. ". The new vertex on the orange edge `e0` "
    .. "will sit at " .. tostring(state.edge[0]) .. ".")
  say "Nothing on screen has moved yet: phase 1 only computes."
end)

step("Phase 2: split every edge", function()
  local mesh, state = cube_after(2)
  show(mesh)
  for i = state.V, mesh:num_vertices() - 1 do highlight(mesh:vertex(i), "yellow") end
  for _, i in ipairs(state.cross) do highlight(mesh:edge(i), "orange") end
  say("Every one of the " .. state.E .. " original edges has been split with the same split as part 5. The mesh "
    .. "now has " .. counts(mesh) .. ": the new vertices (yellow) still sit at the edge midpoints.")
  say [[
Only the original edges are split: list them *before* splitting, because each split adds edges, and splitting
those too would never end. Each split made two edges that cut across an old face (orange): some join two new
vertices, others an old vertex and a new one.]]
end)

step("Phase 3: flip", function()
  local mesh, state = cube_after(3)
  show(mesh)
  for _, i in ipairs(state.flipped) do highlight(mesh:edge(i), "orange") end
  say("Of the " .. #state.cross .. " edges the splits made across faces, " .. #state.flipped .. " joined an old "
    .. "vertex to a new one; those are flipped (orange). Now every old triangle is cut into four: three at its "
    .. "corners and one in the middle, whose edges join new vertices only.")
  say("The counts have not changed (" .. counts(mesh) .. "): a flip creates nothing. The mesh passes validation: "
    .. tostring(mesh:validate()) .. ".")
end)

step("Phase 4: move", function()
  local mesh = cube_after(4)
  show(mesh)
  local reference = meshedit.cube()
  reference:loop_subdivide()
  local worst = 0
  for v in reference:vertices() do
    worst = math.max(worst, (v.position - mesh:vertex(index(v)).position):length())
  end
  say("Every vertex moves to its phase-1 position: the cube turns into a rounder blob of " .. counts(mesh) .. ".")
  if worst < 1e-9 and reference:num_faces() == mesh:num_faces() then
    say("These four phases, written in Lua in this lesson, give exactly the mesh the app's **L** gives: the same "
      .. "counts, and every vertex at the same place. Your `upsample` must do the same.")
  else
    say("The Lua phases differ from the app's L by " .. fmt(worst) .. ".")
  end
end)

local PHASE_NAMES = { "compute new positions", "split every original edge",
  "flip new edges joining an old and a new vertex", "move every vertex to its new position" }

-- Whether `mesh` is `expected`: the same counts, every vertex at the same place and every edge between the same
-- two vertices (ids compared, as the app's phases and the Lua ones number alike). False for anything else.
local function same_mesh(mesh, expected)
  if not mesh or mesh:num_vertices() ~= expected:num_vertices() or mesh:num_edges() ~= expected:num_edges()
    or mesh:num_faces() ~= expected:num_faces() then
    return false
  end
  local ok, same = pcall(function()
    for v in expected:vertices() do
      if (mesh:vertex(index(v)).position - v.position):length() > 1e-9 then return false end
    end
    for e in expected:edges() do
      local h, g = e.halfedge, mesh:edge(index(e)).halfedge
      local a, b, c, d = index(h.vertex), index(h.twin.vertex), index(g.vertex), index(g.twin.vertex)
      if not ((a == c and b == d) or (a == d and b == c)) then return false end
    end
    return true
  end)
  return ok and same
end

-- What phase `phase` did to the cube on screen (`mesh`), with the elements it touched marked.
local function phase_report(phase, mesh, state)
  clear()
  if phase == 1 then
    return "Phase 1 computed every new position and changed nothing: the cube still has " .. counts(mesh) .. "."
  elseif phase == 2 then
    for i = state.V, mesh:num_vertices() - 1 do highlight(mesh:vertex(i), "yellow") end
    return "Phase 2 split all " .. state.E .. " original edges: now " .. counts(mesh) .. ", the new vertices "
      .. "(yellow) still at the midpoints."
  elseif phase == 3 then
    for _, i in ipairs(state.flipped) do highlight(mesh:edge(i), "orange") end
    return "Phase 3 flipped the " .. #state.flipped .. " new edges joining an old and a new vertex (orange): still "
      .. counts(mesh) .. "."
  end
  highlight(mesh:vertex(0), "yellow")
  return "Phase 4 moved every vertex: v0 went from " .. tostring(meshedit.cube():vertex(0).position) .. " to "
    .. tostring(mesh:vertex(0).position) .. "."
end

step("Your turn: Shift+L", function()
  show(meshedit.cube())
  camera "fit"
  say [[
Now run the four phases yourself on a fresh cube: press **Shift+L** four times (the status bar names each phase).
After each press this lesson compares the mesh on screen with its own Lua phases.]]
  local phase, mesh = 1, nil
  while phase <= 4 do
    wait_for { key = "shift+L", hint = "Press Shift+L: phase " .. phase .. " of 4, " .. PHASE_NAMES[phase] }
    mesh = current_mesh()
    local expected, state = cube_after(phase)
    if same_mesh(mesh, expected) then
      say(phase_report(phase, mesh, state))
      phase = phase + 1
    else
      show(meshedit.cube())
      clear()
      say("That is not the cube after phase " .. phase .. " (did another key change the mesh?). Here is a fresh "
        .. "cube: press **Shift+L** again, from phase 1.")
      phase = 1
    end
  end
  say("One step done: " .. counts(mesh) .. ", " .. (mesh:validate() and "valid" or "NOT valid") .. ". Press **L** "
    .. "to run all four phases at once, again and again, to watch the surface converge; each step multiplies the "
    .. "faces by four, so stop after four or five.")
end)

step("The cube's asymmetry", function()
  local mesh = meshedit.cube()
  for i = 0, 7 do label(mesh:vertex(i), "degree " .. mesh:vertex(i):degree()) end
  local subdivided = mesh:copy()
  subdivided:loop_subdivide()
  subdivided:loop_subdivide()
  show(subdivided)
  for i = 0, 7 do
    label(subdivided:vertex(i), "degree " .. mesh:vertex(i):degree())
    highlight(subdivided:vertex(i), mesh:vertex(i):degree() == 6 and "orange" or "yellow")
  end
  local lo, hi = corner_range(subdivided)
  local degrees = {}
  for i = 0, 7 do degrees[#degrees + 1] = tostring(mesh:vertex(i):degree()) end
  say("Look at the cube after two steps: it is **lopsided**. Its 12 triangles come from cutting each square face "
    .. "along one diagonal, so the corners do not all have the same number of neighbours: the degrees of v0 to v7 "
    .. "are " .. table.concat(degrees, ", ") .. ". The weights depend on that number, so corners with different "
    .. "degrees move differently (orange: degree 6, yellow: fewer).")
  say("After two steps the 8 corners are between " .. fmt(lo) .. " and " .. fmt(hi) .. " from the centre. A "
    .. "symmetric input would put them all at the same distance.")
end)

step("The pre-split fix", function()
  local cube = meshedit.cube()
  show(cube)
  local list = diagonals(cube)
  local ids = {}
  for _, e in ipairs(list) do
    highlight(e, "yellow")
    ids[#ids + 1] = "`" .. tostring(e) .. "`"
  end
  say("The fix: make every face the same before subdividing. Split each of the six yellow diagonals ("
    .. table.concat(ids, ", ") .. "): select one, press **S**, and repeat. Each square face then has a vertex in "
    .. "its middle joined to all four of its corners, and every corner has 6 neighbours.")
  local split = wait_for {
    hint = "Split all six diagonals with S",
    condition = function()
      local m = current_mesh()
      if not m or m:num_vertices() ~= 14 or not m:validate() then return false end
      for i = 0, 7 do if m:vertex(i):degree() ~= 6 then return false end end
      return m
    end,
  }
  say("All six split: " .. counts(split) .. ", and every corner has degree 6. Now press **L** twice.")
  local mesh = wait_for {
    hint = "Press L twice",
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == 16 * split:num_faces() and m:validate() and m
    end,
  }
  local lo, hi = corner_range(mesh)
  if hi - lo < 1e-9 then
    say("After two steps: " .. counts(mesh) .. ". All 8 corners are " .. fmt(hi) .. " from the centre: the same "
      .. "distance, a symmetric shape.")
  else
    say("After two steps: " .. counts(mesh) .. ". The corners are between " .. fmt(lo) .. " and " .. fmt(hi)
      .. " from the centre: still not symmetric. Did every face get its middle vertex?")
  end
end)

-- The cube after three steps, optionally with every edge at corner v7 split first; and v7's distance from the
-- centre after each step.
local function corner_run(presplit)
  local mesh = meshedit.cube()
  if presplit then
    local edges = {}
    for h in mesh:vertex(7):halfedges() do edges[#edges + 1] = h.edge end
    for _, e in ipairs(edges) do assert(mesh:split(e)) end
  end
  local radii = {}
  for level = 1, 3 do
    mesh:loop_subdivide()
    radii[level] = mesh:vertex(7).position:length()
  end
  return mesh, radii
end

step("Sharp corners", function()
  local cube = meshedit.cube()
  local _, plain = corner_run(false)
  local mesh, sharp = corner_run(true)
  show(mesh)
  camera "fit"
  highlight(mesh:vertex(7), "yellow")
  label(mesh:vertex(7), "corner v7")
  highlight(mesh:vertex(0), "orange")
  label(mesh:vertex(0), "corner v0")
  say [[
Loop subdivision **approximates**: old vertices move toward their neighbours, so a cube's sharp corners are
rounded away, and the mesh shrinks inside its control mesh.]]
  say("Every corner starts " .. fmt(cube:vertex(7).position:length()) .. " from the centre. On the plain cube, "
    .. "corner `v7` is " .. fmt(plain[1]) .. ", " .. fmt(plain[2]) .. " and " .. fmt(plain[3])
    .. " away after one, two and three steps.")
  say("To keep a corner sharper, give the mesh more vertices near it before subdividing. On screen, every edge at "
    .. "`v7` was split first: after the same three steps `v7` is still " .. fmt(sharp[3]) .. " from the centre, "
    .. "while the untouched corner `v0` (orange) is at " .. fmt(mesh:vertex(0).position:length()) .. ".")
  say [[
The averages near v7 now run over points close to it, so it rounds off less. Real creases need an extension of
the rules (crease edges with their own weights), which is beyond this assignment. Try it: split the edges
around a corner with S, then press L a few times.]]
end)

step("A mesh with a boundary", function()
  local grid = meshedit.grid(2, 2)
  show(grid)
  camera "fit"
  highlight(grid:vertex(0), "yellow")
  label(grid:vertex(0), "corner (0, 0)")
  say [[
On a mesh with a **boundary** the rules change along the border, so it stays a curve of its own:

- a boundary edge's new vertex is its midpoint, (a + b) / 2
- a boundary vertex moves to 3/4 p + 1/8 (left + right), using only its two neighbours along the boundary]]
  say("This grid has " .. counts(grid) .. " and one boundary loop. Press **L**.")
  local mesh = wait_for {
    hint = "Press L",
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == 4 * grid:num_faces() and m:validate() and m
    end,
  }
  local p = mesh:vertex(0).position
  highlight(mesh:vertex(0), "yellow")
  label(mesh:vertex(0), "corner")
  say("Now " .. counts(mesh) .. ", still " .. mesh:num_boundaries() .. " boundary loop. The corner moved from "
    .. "(0, 0, 0) to " .. tostring(p) .. ": 3/4 of itself plus 1/8 of each boundary neighbour, (1, 0, 0) and "
    .. "(0, 1, 0). The corner of the grid is cut off, as corners are on a closed mesh.")
end)
