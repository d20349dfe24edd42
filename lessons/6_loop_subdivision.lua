-- Part 6: Loop subdivision, phase by phase. The lesson runs the four phases itself in Lua (the same phases the
-- app's Shift+L steps through, engine/core/loop_subdivision.h), telling old from new by flags set as it splits,
-- as scripts/student/upsample.lua asks. Each phase step asks first: the vertex count, u at degree 6, which edges
-- to split, which edge to flip (a pick on the split cube: the halves of a split edge are the trap), why the
-- positions come first. Then the student runs the app's phases with Shift+L, each checked against the Lua ones;
-- explains the cube's lopsided result and predicts which corners end nearer the centre before the lesson says
-- why; makes every corner's degree the same with flips and splits of their own (told when a flip makes it worse)
-- before the diagonal pre-split is shown; keeps a corner sharp to a target distance by editing near it before the
-- lesson says how; predicts where a boundary corner goes; and ends with their own upsample.lua run by your_turn on
-- a cube and a tetrahedron (every vertex of degree 3).
-- CI runs it headless:
--   meshedit lesson lessons/6_loop_subdivision.lua --headless \
--     --answers tests/lesson/lessons/6_loop_subdivision_answers.lua --student tests/exercise/solutions
-- Invariants: every step rebuilds its meshes from scratch (Back runs a step again, and must not subdivide
-- twice); the Lua phases use the course weights and split edges in id order, so their ids match the core's.

lesson {
  title = "Part 6: Loop subdivision",
  summary = "Loop subdivision in four phases, the cube's asymmetry and the pre-split fix, sharp corners, "
    .. "a mesh with a boundary, and your own upsample.",
}

local function index(element) return element.id end

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

local function fmt(x) return string.format("%.4f", x) end

-- The degrees a mesh's vertices have, smallest first: "4 or 6", "3".
local function degrees_of(mesh)
  local seen, list = {}, {}
  for v in mesh:vertices() do
    if not seen[v:degree()] then
      seen[v:degree()] = true
      list[#list + 1] = v:degree()
    end
  end
  table.sort(list)
  if #list == 1 then return tostring(list[1]) end
  return table.concat(list, ", ", 1, #list - 1) .. " or " .. list[#list]
end

-- ---- the four phases, on a closed triangle mesh, course weights ----

-- Phase 1: positions from the original mesh; nothing changes yet.
local function phase1(mesh)
  local state = { V = mesh:num_vertices(), E = mesh:num_edges(), vertex = {}, edge = {}, u = {} }
  for v in mesh:vertices() do
    local n = v:degree()
    local u = n == 3 and 3 / 16 or 3 / (8 * n)
    local sum = meshedit.vec3(0, 0, 0)
    for w in v:neighbors() do sum = sum + w.position end
    state.vertex[v.id] = v.position * (1 - n * u) + sum * u
    state.u[v.id] = u
  end
  for e in mesh:edges() do
    local h = e.halfedge
    local a, b = h.vertex.position, h.twin.vertex.position
    local c, d = h.next.next.vertex.position, h.twin.next.next.vertex.position
    state.edge[e.id] = (a + b) * (3 / 8) + (c + d) * (1 / 8)
  end
  return state
end

-- Phase 2: split every original edge (listed before the first split), in id order. Flags, by id: is_new_vertex
-- for each m, is_new_edge for the two edges from m to the corners across (m-c, m-d); the halves of the split edge
-- (a-m, m-b) stay unmarked. state.cross lists the new edges in the order the splits made them.
local function phase2(mesh, state)
  state.new_position = {}
  for i, p in pairs(state.vertex) do state.new_position[i] = p end
  state.is_new_vertex, state.is_new_edge, state.cross = {}, {}, {}
  local originals = {}
  for e in mesh:edges() do originals[#originals + 1] = e.id end
  for _, id in ipairs(originals) do
    local e = mesh:edge(id)
    local a, b = e.halfedge.vertex.id, e.halfedge.twin.vertex.id
    local m = assert(mesh:split(e))
    state.is_new_vertex[m.id] = true
    state.new_position[m.id] = state.edge[id]
    -- Around m (clockwise from m.halfedge): to a, c, b, d. The edges to c and d are the new ones.
    for h in m:halfedges() do
      local far = h.twin.vertex.id
      if far ~= a and far ~= b then
        state.is_new_edge[h.edge.id] = true
        state.cross[#state.cross + 1] = h.edge.id
      end
    end
  end
end

-- Whether edge `e` joins an old vertex and a new one, by the flags.
local function old_to_new(state, e)
  local h = e.halfedge
  return (state.is_new_vertex[h.vertex.id] or false) ~= (state.is_new_vertex[h.twin.vertex.id] or false)
end

-- Phase 3: flip every new edge (flagged) that joins an old vertex and a new one.
local function phase3(mesh, state)
  state.flipped = {}
  for _, i in ipairs(state.cross) do
    if old_to_new(state, mesh:edge(i)) then
      assert(mesh:flip(mesh:edge(i)))
      state.flipped[#state.flipped + 1] = i
    end
  end
end

-- Phase 4: every vertex to its computed position.
local function phase4(mesh, state)
  for v in mesh:vertices() do v.position = state.new_position[v.id] end
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
  answer {
    "The cube on screen has " .. counts(meshedit.cube()) .. ". How many vertices will it have after one step?",
    number = 26,
    tolerance = 0.5,
    feedback = function(value)
      if value == 8 then return "8 counts only the old vertices, which stay; every edge split adds one more." end
      if value == 32 then
        return "Faces are multiplied by four, vertices are not: the old ones stay and each edge adds one."
      end
      if value == 20 then return "20 = 8 + 12 counts a new vertex per face; phase 2 splits edges, one vertex each." end
      if value == 44 then return "44 = 8 + 36 counts two new vertices per edge: a split adds one." end
    end,
    hint = "The old vertices stay; phase 2 adds one vertex per original edge.",
  }
  say("Yes: V' = V + E. And E' = 2E + 3F, F' = 4F. The cube has " .. counts(meshedit.cube())
    .. ", so one step gives 26 vertices, 72 edges and 48 faces. Press **Next** to watch each phase.")
end)

step("Phase 1: new positions", function()
  local mesh, state = cube_after(1)
  show(mesh)
  local v0 = mesh:vertex(0)
  local e0 = mesh:edge(0)
  highlight(v0, "yellow")
  highlight(e0, "orange")
  label(v0, "degree " .. v0:degree())
  say [[
Every position is computed from the **original** mesh, before anything changes (that is why this phase
only stores numbers):

- an old vertex p with n neighbours q1..qn moves to (1 - n u) p + u (q1 + ... + qn),
  with u = 3/16 when n = 3 and u = 3/(8n) otherwise
- the new vertex on an edge a-b, with c and d the corners opposite it, goes to 3/8 (a + b) + 1/8 (c + d)]]
  answer {
    "The yellow vertex v0 has 6 neighbours. What is u for it?",
    number = 1 / 16,
    feedback = function(value)
      if math.abs(value - 3 / 16) < 1e-3 then
        return "3/16 is u for n = 3 only. For every n > 3, u = 3/(8n)."
      end
      if math.abs(value - 1 / 6) < 1e-3 then
        return "1/6 = 1/n would make n u = 1: v0's own weight 1 - n u would be 0, and it would jump to the "
          .. "plain average of its neighbours. Loop keeps part of the vertex itself: u = 3/(8n)."
      end
      if math.abs(value - 3 / 8) < 1e-3 then
        return "3/8 is n u, what all six neighbours weigh together; each one gets u = 3/(8n)."
      end
      if math.abs(value - 5 / 8) < 1e-3 then return "5/8 = 1 - n u is the weight v0 keeps for itself." end
    end,
    hint = "u = 3/(8n) for n > 3: put in n = 6.",
  }
  say("u = 3/48 = 1/16, and n u = 6/16 = **3/8**. That is so for every n > 3: n u = 3n/(8n) = 3/8, "
    .. "whatever the degree. The vertex keeps 5/8 of its own position and its neighbours share the other 3/8, "
    .. "however many they are; the weights always sum to 1, so a flat patch stays flat. (n = 3 is the exception: "
    .. "u = 3/16, n u = 9/16.)")
  plot {
    title = "n u, the neighbours' total weight", x = { 3, 12 }, y = { 0, 1 }, samples = 90,
    curves = {
      { label = "course: n u, with u = 3/(8n) (3/16 at n = 3)", colour = "blue",
        fn = function(n) return n < 3.5 and 9 / 16 or 3 / 8 end },
      { label = "Loop's own: n beta(n)", colour = "orange",
        fn = function(n) return 5 / 8 - (3 / 8 + 1 / 4 * math.cos(2 * math.pi / n)) ^ 2 end },
      { label = "n u with u = 1/n (no weight kept)", colour = "grey", fn = function() return 1 end },
    },
  }
  say("The yellow vertex `v0` has " .. v0:degree() .. " neighbours, so u = " .. fmt(state.u[0]) .. ": it will go from "
    .. tostring(v0.position) .. " to " .. tostring(state.vertex[0]) .. ". The new vertex on the orange edge `e0` "
    .. "will sit at " .. tostring(state.edge[0]) .. ".")
  say "Nothing on screen has moved yet: phase 1 only computes."
end)

step("Phase 2: split every edge", function()
  show(meshedit.cube())
  choose {
    "Phase 2 splits edges. Which ones?",
    options = { "The 18 original edges", "Every edge, new ones too",
      "Only the edges phase 3 flips" },
    answer = "The 18 original edges",
    feedback = {
      ["Every edge, new ones too"] = "Each split adds three edges; if those were split too, "
        .. "the loop would never end (and each face would be cut far more than into four).",
      ["Only the edges phase 3 flips"] = "The edges phase 3 flips do not exist yet: splits make them. "
        .. "Phase 2 splits every edge of the mesh as it was before phase 2.",
      ["The 18 original edges"] = "Only those: list them before the first split.",
    },
    hint = "Each split adds edges. What happens if the loop visits them too?",
  }
  local mesh, state = cube_after(2)
  show(mesh)
  for v in mesh:vertices() do if state.is_new_vertex[v.id] then highlight(v, "yellow") end end
  for _, i in ipairs(state.cross) do highlight(mesh:edge(i), "orange") end
  say("Every one of the " .. state.E .. " original edges has been split with the same split as part 5. The mesh "
    .. "now has " .. counts(mesh) .. ": the new vertices (yellow) still sit at the edge midpoints.")
  say [[
As it splits, the lesson's phase 2 **flags** what is new: the vertex m of each split (yellow), and the two
edges from m to the corners across, m-c and m-d (orange). The two halves of the split edge, a-m and m-b, are
not new: they lie along an original edge. Flags, not ids: split keeps e's id for the half m-b and gives the
half a-m a new id, so "an id past the original count" does not mean "a new edge".]]
end)

step("Phase 3: which edges flip", function()
  local mesh, state = cube_after(2)
  show(mesh)
  view { halfedges = false, wireframe = true }  -- edges drawn, no arrows over them: a click picks an edge
  for v in mesh:vertices() do if state.is_new_vertex[v.id] then highlight(v, "yellow") end end
  say [[
Here is the cube after phase 2 again; the new vertices are yellow, the old ones (the cube's corners) are not.
Phase 3 flips every **new** edge that joins an old vertex and a new one.]]
  pick {
    "Which of these edges should be flipped? Click one.",
    answer = function(x)
      if x.kind == "halfedge" then x = x.edge end  -- an arrow stands for its edge
      if x.kind ~= "edge" then return false, "That is a " .. x.kind .. ": click an edge." end
      if state.is_new_edge[x.id] and old_to_new(state, x) then
        return true, "Yes: a new edge from a corner across an old face to a new vertex."
      end
      if state.is_new_edge[x.id] then
        return false, "Both ends of this edge are new vertices: it is an edge of an old triangle's middle "
          .. "triangle, and stays as it is."
      end
      return false, "This edge joins an old corner to a new vertex, but it is a half of a split original edge "
        .. "(a-m or m-b), not a new edge. Subdivision keeps the original edges, in two halves; flipping a half "
        .. "would swap it for an edge across two old triangles, and those would no longer be four triangles "
        .. "each. Only the flags tell the halves from the new edges."
    end,
    hint = "Look for an edge that cuts across one of the cube's old triangles, from a corner to a yellow vertex.",
  }
  mesh, state = cube_after(3)
  show(mesh)
  clear()
  for _, i in ipairs(state.flipped) do highlight(mesh:edge(i), "orange") end
  say("Of the " .. #state.cross .. " edges the splits made across faces, " .. #state.flipped .. " joined an old "
    .. "vertex to a new one; those are flipped (orange). Now every old triangle is cut into four: three at its "
    .. "corners and one in the middle, whose edges join new vertices only.")
  say("The counts have not changed (" .. counts(mesh) .. "): a flip creates nothing. The mesh passes validation: "
    .. tostring(mesh:validate()) .. ".")
end)

step("Phase 4: move", function()
  local mesh = cube_after(3)
  show(mesh)
  view { halfedges = true }  -- back on after phase 3's question turned them off
  choose {
    "Phase 4 moves every vertex to a position phase 1 computed. Why compute them in phase 1, before any split, "
      .. "and not now?",
    options = { "The neighbours have changed",
      "Splits would move stored positions", "It is only faster" },
    answer = "The neighbours have changed",
    feedback = {
      ["Splits would move stored positions"] = "Splits and flips change pointers, and "
        .. "a split only places m at a midpoint; the stored positions are numbers, nothing moves them. The "
        .. "question is what the weights would read now.",
      ["It is only faster"] = "It is not about speed: computed now, the result would be wrong. Look at "
        .. "v0's neighbours on screen.",
      ["The neighbours have changed"] = "Right: the weights are "
        .. "defined on the original mesh; after phase 2 an old vertex is joined only to new vertices.",
    },
    hint = "Select v0 and look at what it is joined to now.",
  }
  mesh = cube_after(4)
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
    for v in mesh:vertices() do if state.is_new_vertex[v.id] then highlight(v, "yellow") end end
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

step("The app's phases: Shift+L", function()
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

-- The degrees of corners v0..v7 of `mesh`, and the smallest and largest of them.
local function corner_degrees(mesh)
  local degrees, lo, hi = {}, math.huge, 0
  for i = 0, 7 do
    local n = mesh:vertex(i):degree()
    degrees[i] = n
    lo, hi = math.min(lo, n), math.max(hi, n)
  end
  return degrees, lo, hi
end

-- The mean distance from the centre, after two steps of L, of the corners whose degree on `mesh` is `n`.
local function mean_corner_distance(mesh, subdivided, n)
  local sum, count = 0, 0
  for i = 0, 7 do
    if mesh:vertex(i):degree() == n then
      sum, count = sum + subdivided:vertex(i).position:length(), count + 1
    end
  end
  return sum / count
end

step("The cube's lopsided result", function()
  local mesh = meshedit.cube()
  local subdivided = mesh:copy()
  subdivided:loop_subdivide()
  subdivided:loop_subdivide()
  show(subdivided)
  camera "fit"
  local lo, hi = corner_range(subdivided)
  say("Here is the cube after two steps of L. A cube is symmetric, yet the result is **lopsided**: after two "
    .. "steps the 8 corners are between " .. fmt(lo) .. " and " .. fmt(hi) .. " from the centre. A symmetric "
    .. "input would put them all at the same distance.")
  local right = "Corners differ in degree"
  choose {
    "Why is it lopsided? (degree: a vertex's number of neighbours)",
    options = { "Rounding error", "Splitting in id order", right, "Corners at different distances" },
    answer = right,
    feedback = {
      ["Rounding error"] = string.format("The corners differ by %.3f; rounding in double "
        .. "precision is about 1e-16. Something in the mesh itself differs from corner to corner.", hi - lo),
      ["Splitting in id order"] = "Phase 1 computes every "
        .. "position from the original mesh before the first split, so the order of the splits cannot move "
        .. "anything; it only decides the new ids.",
      ["Corners at different distances"] = "They are not: every corner of the "
        .. "cube is " .. fmt(mesh:vertex(0).position:length()) .. " from the centre before subdividing. Look at "
        .. "how each corner is connected instead.",
      [right] = "Right: the cube's 12 triangles cut each square face along one diagonal.",
    },
    hint = "The rule for an old vertex depends on one number per vertex. Is it the same at every corner?",
  }
  local degrees, low, high = corner_degrees(mesh)
  for i = 0, 7 do label(subdivided:vertex(i), "degree " .. degrees[i]) end
  local at_high, at_low = mean_corner_distance(mesh, subdivided, high), mean_corner_distance(mesh, subdivided, low)
  local high_option, low_option = "The degree-" .. high .. " corners", "The degree-" .. low .. " corners"
  local nearer, farther = high_option, low_option
  if at_low < at_high then nearer, farther = low_option, high_option end
  local pull = meshedit.vec3(0, 0, 0)
  for w in mesh:vertex(0):neighbors() do pull = pull + w.position end
  pull = pull / mesh:vertex(0):degree()
  choose {
    "Each corner is labelled with its degree on the cube before subdividing. After the two steps, which corners "
      .. "are nearer the centre?",
    options = { high_option, low_option, "All at the same distance" },
    answer = nearer,
    feedback = {
      [farther] = "They stay farther out. Corner v0 (degree " .. degrees[0] .. ") is joined to three corners along "
        .. "the cube's edges and to others across the faces' diagonals, and its neighbours average to "
        .. tostring(pull) .. ": how far is that from the centre?",
      ["All at the same distance"] = "They are not: the corners are between " .. fmt(lo) .. " and " .. fmt(hi)
        .. " from the centre, and the degrees on their labels differ.",
      [nearer] = "Yes: after two steps the degree-" .. high .. " corners are " .. fmt(at_high) .. " from the centre "
        .. "on average, the degree-" .. low .. " ones " .. fmt(at_low) .. ".",
    },
    hint = "A corner moves towards the average of its neighbours. Where is that average for v0, and where for a "
      .. "corner of degree " .. low .. "?",
  }
  for i = 0, 7 do highlight(subdivided:vertex(i), degrees[i] == high and "orange" or "yellow") end
  local list = {}
  for i = 0, 7 do list[#list + 1] = tostring(degrees[i]) end
  say("Its 12 triangles come from cutting each square face along one diagonal, so the corners do not all have the "
    .. "same number of neighbours: the degrees of v0 to v7 are " .. table.concat(list, ", ") .. ". The weights "
    .. "depend on that number, and so does what they average: v0's " .. degrees[0] .. " neighbours average to "
    .. tostring(pull) .. ", the centre itself, so it is pulled straight in (orange: degree " .. high .. ", yellow: "
    .. "degree " .. low .. ").")
end)

-- What the student's last edit did to the corners' degrees: a line for the live text.
local function degree_report(degrees, lo, hi, before_spread, flips_only)
  local list = {}
  for i = 0, 7 do list[#list + 1] = "v" .. i .. " " .. degrees[i] end
  local now = "Degrees now: " .. table.concat(list, ", ") .. "."
  if hi - lo > before_spread then
    return now .. " That made it worse: the corners now range from " .. lo .. " to " .. hi .. ", against "
      .. before_spread .. " apart before. A flip takes one neighbour from each end of the edge and gives one to each "
      .. "corner across."
  end
  if flips_only >= 3 then
    return now .. " Flips alone cannot do it: they keep 8 vertices and 18 edges, so the degrees always add up to "
      .. "36, which is 4.5 per corner. Something must add a vertex."
  end
  return now
end

step("Make every corner alike", function()
  local cube = meshedit.cube()
  show(cube)
  camera "fit"
  view { halfedges = false, wireframe = true }  -- edges to select, no arrows over them
  local degrees, lo, hi = corner_degrees(cube)
  local function label_corners(mesh)
    clear()
    for i = 0, 7 do label(mesh:vertex(i), "degree " .. degrees[i]) end
  end
  label_corners(cube)
  say [[
Fix the input, not the rules: change the cube so that **all 8 corners have the same degree**. Select an edge and
press **F** to flip it or **S** to split it, as in parts 4 and 5, as often as you like. The labels give each
corner's degree, and they and the line below follow your edits.]]
  local status = "Degrees now: the corners range from " .. lo .. " to " .. hi .. "."
  live(function() return status end)
  local last, spread, flips_only = cube, hi - lo, 0
  while true do
    local mesh = wait_for {
      hint = "Flip (F) or split (S) edges until every corner has the same degree",
      condition = function()
        local m = current_mesh()
        if m and m:num_vertices() >= 8 and #m:diff(last) > 0 then return m end
        return false
      end,
    }
    last = mesh
    if mesh:num_vertices() == 8 then flips_only = flips_only + 1 else flips_only = 0 end
    degrees, lo, hi = corner_degrees(mesh)
    label_corners(mesh)
    if lo == hi then break end
    status = degree_report(degrees, lo, hi, spread, flips_only)
    spread = hi - lo
  end
  status = "Every corner has degree " .. lo .. ": " .. counts(last) .. "."
  say [[
Done: no corner is special any more. The next step shows one way that treats every face alike.]]
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
  say("A fix that treats every face alike: split each of the six yellow diagonals ("
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

-- The distance to aim for in "Sharp corners": halfway between where v7 ends on the plain cube and where it ends
-- with its edges split first, after three steps, rounded down to a hundredth.
local function sharp_target(plain, presplit) return math.floor((plain + presplit) / 2 * 100) / 100 end

step("Sharp corners", function()
  local cube = meshedit.cube()
  local _, plain = corner_run(false)
  local _, sharp = corner_run(true)
  local target = sharp_target(plain[3], sharp[3])
  show(cube)
  camera "fit"
  view { halfedges = false, wireframe = true }
  highlight(cube:vertex(7), "yellow")
  label(cube:vertex(7), "corner v7")
  say [[
Loop subdivision **approximates**: old vertices move toward their neighbours, so a cube's sharp corners are
rounded away, and the mesh shrinks inside its control mesh.]]
  say("Every corner starts " .. fmt(cube:vertex(7).position:length()) .. " from the centre. On the plain cube, "
    .. "corner `v7` is " .. fmt(plain[1]) .. ", " .. fmt(plain[2]) .. " and " .. fmt(plain[3])
    .. " away after one, two and three steps.")
  say("Your goal: change the cube so that after **three** steps of L, corner `v7` is still at least **"
    .. string.format("%.2f", target) .. "** from the centre. Flip (F) and split (S) edges of the cube, without "
    .. "pressing L, then press **Check**: the lesson subdivides a copy three times and measures v7.")
  local status = "Press Check when your edits are done."
  live(function() return status end)
  local reached
  while not reached do
    wait_for { button = "Check", hint = "Edit the cube near v7, then press Check" }
    local mesh = current_mesh()
    if not mesh or mesh:num_faces() > 200 or not mesh:validate() then
      status = "That is not an edited cube (was L pressed?): press Back for a fresh one."
    else
      local copy = mesh:copy()
      for _ = 1, 3 do copy:loop_subdivide() end
      local r = copy:vertex(7).position:length()
      if r >= target then
        reached = copy
        status = "Reached: after three steps v7 is " .. fmt(r) .. " from the centre."
      elseif #mesh:diff(cube) == 0 then
        status = "That is the plain cube: v7 ends " .. fmt(r) .. " from the centre. What would keep v7's "
          .. "neighbours close to it?"
      else
        status = "After three steps v7 is " .. fmt(r) .. " from the centre (the plain cube's: " .. fmt(plain[3])
          .. "); the goal is " .. string.format("%.2f", target) .. ". Which of your edits touch v7's neighbours?"
      end
    end
  end
  show(reached)
  camera "fit"
  clear()
  highlight(reached:vertex(7), "yellow")
  label(reached:vertex(7), "corner v7")
  local right = "Its neighbours are nearer to it"
  choose {
    "Why does v7 stay farther out now?",
    options = { right, "Its degree went up", "The splits gave it a weight of its own" },
    answer = right,
    feedback = {
      ["Its degree went up"] = "Its degree is not what moves it: for any degree above 3 its neighbours weigh 3/8 "
        .. "together, however many there are (a split of an edge at v7 even keeps v7's degree: it joins v7 to the "
        .. "new vertex instead of the far end). What changed is where its neighbours are.",
      ["The splits gave it a weight of its own"] = "The rules are the same for every vertex; only what they average "
        .. "changed.",
      [right] = "Yes: v7 moves toward the average of its neighbours, and they now sit close to it.",
    },
    hint = "A vertex moves toward the average of its neighbours. Where are v7's neighbours after your splits?",
  }
  say("With every edge at v7 split first, v7 ends " .. fmt(sharp[3]) .. " from the centre after three steps, "
    .. "against " .. fmt(plain[3]) .. " on the plain cube.")
  say [[
To keep a corner sharper, give the mesh more vertices near it before subdividing: the averages near it then run
over points close to it, so it rounds off less. Real creases need an extension of the rules (crease edges with
their own weights), which is beyond this assignment.]]
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
  say("This grid has " .. counts(grid) .. " and one boundary loop. The yellow corner is at (0, 0); its neighbours "
    .. "along the boundary are (1, 0) and (0, 1).")
  answer {
    "Where will the yellow corner be after one step? Give x, y.",
    point = { 0.125, 0.125 },
    feedback = function(p)
      if p:length() < 1e-3 then
        return "A boundary vertex moves too, along the boundary's own rule: 3/4 of itself plus 1/8 of each "
          .. "boundary neighbour."
      end
      if (p - meshedit.vec3(0.25, 0.25)):length() < 1e-3 then
        return "That gives each neighbour 1/4; the boundary rule gives each 1/8 and the corner 3/4."
      end
      if (p - meshedit.vec3(1 / 3, 1 / 3)):length() < 1e-2 then
        return "That is the plain average of the corner and its two neighbours; the rule keeps 3/4 of the corner."
      end
    end,
    hint = "3/4 (0, 0) + 1/8 ((1, 0) + (0, 1)).",
  }
  say "Now press **L** and check."
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

step("Your own upsample", function()
  local cube = meshedit.cube()
  show(cube)
  camera "fit"
  local right = "Flags set while splitting"
  choose {
    "In your upsample, how will phase 3 tell the edges to flip from the others?",
    options = { "Ids past the original count", "One old end and one new end",
      right },
    answer = right,
    feedback = {
      ["Ids past the original count"] = "split keeps e's id for the half m-b and gives the "
        .. "half a-m a new id (ea): ids past the original count include halves of original edges, which must "
        .. "not be flipped.",
      ["One old end and one new end"] = "The halves of a split edge join an old vertex and a new "
        .. "one too: that test alone flips them, the trap of phase 3. Only new edges with one old and one new end.",
      [right] = "Yes: flag them as you split, then flip the flagged edges with one old end and one new end.",
    },
    hint = "Think back to the edges you could click in phase 3 that were not the answer.",
  }
  say [[
Now write it: open **scripts/student/upsample.lua** in your editor. It lists the same work in five steps (its
steps 1 and 2 are phase 1 here), with the flags (is_new[v.id], is_new_edge[e.id]) and the boundary rules as extra
credit. The lesson runs your `upsample` on a copy of this cube each time you save the file and compares the
result with the reference's: it names the vertices that moved to the wrong place, the weight they moved with (a
weight like 3 // 16 is 0 in Lua), the edges flipped wrongly, and how many of the new edges you flipped against how
many the reference flips. An upsample that never ends is stopped, at the line it was running.]]
  your_turn {
    exercise = "upsample",
    mesh = cube,
    hint = "Compute every new position first, split only the original edges, flip only flagged new edges with one "
      .. "old and one new end, and write the positions last.",
  }
  local tetrahedron = meshedit.tetrahedron()
  show(tetrahedron)
  camera "fit"
  say("Right on the cube, whose vertices have " .. degrees_of(cube) .. " neighbours. Every vertex of a tetrahedron "
    .. "has " .. degrees_of(tetrahedron) .. ", the one degree where u is not 3 / (8n): the lesson runs yours on it "
    .. "next.")
  your_turn {
    exercise = "upsample",
    mesh = tetrahedron,
    hint = "u = 3/16 when n = 3, and 3 / (8n) otherwise.",
  }
  say [[
Your `upsample` gives the reference's mesh, up to the order you made the new elements in. The **Exercises** tab
(**X**, choose **upsample**, **Run mine**) runs it on any mesh on screen and replays its writes one by one; try it
on a mesh with a boundary for the extra credit.]]
end)
