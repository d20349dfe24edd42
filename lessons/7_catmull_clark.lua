-- Part 7: Catmull-Clark subdivision, beside part 6 (Loop). On a cube of six quads the student predicts a face
-- point, an edge point and where a corner goes by the vertex rule (F + 2R + (n - 3) P) / n, then the counts
-- after one level, what the rule makes of triangles (a tetrahedron), the boundary rules on a grid of quads, how
-- linear subdivision differs (nothing moves), and the student's own level (scripts/exercises/catmull_clark.lua:
-- linear subdivision, then the rules; run by your_turn on the cube). Every step asks before it tells: where the
-- face point goes, which points the edge point averages and which way a corner moves come before each rule; each
-- likely wrong answer is named in its feedback. Every number the lesson prints comes from the core:
-- mesh:catmull_clark() and mesh:subdivision_phases("catmull-clark") on copies (engine/core/catmull_clark.h),
-- positions read back. The student runs the window's Subdivide menu twice: the whole level, and then its three
-- phases one at a time, each checked against the lesson's own phases.
-- CI runs it headless (tests/lesson/lessons_b_test.cpp):
--   meshedit lesson lessons/7_catmull_clark.lua --headless --answers tests/lesson/lessons/7_catmull_clark_answers.lua
-- Invariants: every step builds its meshes afresh (Back runs a step again); the core numbers a level's new
-- vertices after the old ones, one per edge in edge id order, then one per face in face id order, so on a fresh
-- mesh (ids dense) the point of edge e is vertex V + e and the point of face f is vertex V + E + f.

lesson {
  title = "Part 7: Catmull-Clark subdivision",
  summary = "Face, edge and vertex points on a cube of quads, the counts after one level, triangles into quads, "
    .. "the boundary rules, and linear subdivision beside it.",
}

-- The cube's six sides as counter-clockwise quads seen from outside (1-based corners of meshedit.cube()).
local CUBE_QUADS = { { 1, 3, 4, 2 }, { 5, 6, 8, 7 }, { 1, 2, 6, 5 }, { 3, 7, 8, 4 }, { 1, 5, 7, 3 }, { 2, 4, 8, 6 } }

-- The unit cube centred at 0 (meshedit.cube()'s corners, v0 at (-0.5, -0.5, -0.5)) as six quads.
local function quad_cube()
  local corners = meshedit.cube()
  local positions = {}
  for i = 0, 7 do positions[i + 1] = corners:vertex(i).position end
  return meshedit.from_polygons(positions, CUBE_QUADS)
end

-- An n by n grid of unit quads in the z = 0 plane, v0 at (0, 0), row by row.
local function quad_grid(n)
  local positions, quads = {}, {}
  for y = 0, n do
    for x = 0, n do positions[#positions + 1] = { x, y, 0 } end
  end
  for y = 0, n - 1 do
    for x = 0, n - 1 do
      local a = y * (n + 1) + x + 1
      quads[#quads + 1] = { a, a + 1, a + n + 2, a + n + 1 }
    end
  end
  return meshedit.from_polygons(positions, quads)
end

-- One level of the core's Catmull-Clark on a copy.
local function catmull_clark(mesh)
  local copy = mesh:copy()
  assert(copy:catmull_clark())
  return copy
end

-- The core's new points, read back from one level on a copy (ids as the header comment says).
local function face_point(mesh, f)
  return catmull_clark(mesh):vertex(mesh:num_vertices() + mesh:num_edges() + f.id).position
end
local function edge_point(mesh, e) return catmull_clark(mesh):vertex(mesh:num_vertices() + e.id).position end
local function vertex_point(mesh, v) return catmull_clark(mesh):vertex(v.id).position end

-- A number with at most four decimals, trailing zeros dropped ("0.5", "-0.2778", "0"); never "-0".
local function num(x)
  local text = string.format("%.4f", x + 0.0):gsub("0+$", ""):gsub("%.$", "")
  if text == "-0" then return "0" end
  return text
end
local function point(p) return "(" .. num(p.x) .. ", " .. num(p.y) .. ", " .. num(p.z) .. ")" end

-- x as a fraction p/q with the smallest q up to 100, or nil.
local function fraction(x)
  for q = 1, 100 do
    local p = x * q
    if math.abs(p - math.floor(p + 0.5)) < 1e-9 then return string.format("%d/%d", math.floor(p + 0.5), q) end
  end
end

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

-- How many faces of each number of sides: "24 quads", "12 triangles and 3 quads".
local function face_kinds(mesh)
  local by_sides = {}
  for f in mesh:faces() do by_sides[f:degree()] = (by_sides[f:degree()] or 0) + 1 end
  local names = { [3] = "triangles", [4] = "quads" }
  local parts = {}
  for sides = 3, 12 do
    if by_sides[sides] then parts[#parts + 1] = by_sides[sides] .. " " .. (names[sides] or (sides .. "-gons")) end
  end
  return table.concat(parts, " and ")
end

-- The mean of a list of points.
local function mean(points)
  local sum = meshedit.vec3(0, 0, 0)
  for _, p in ipairs(points) do sum = sum + p end
  return sum / #points
end

local function centroid(f)
  local corners = {}
  for v in f:vertices() do corners[#corners + 1] = v.position end
  return mean(corners)
end

-- The edge joining vertices a and b.
local function edge_between(mesh, a, b)
  for e in mesh:edges() do
    local h = e.halfedge
    if (h.vertex.id == a and h.twin.vertex.id == b) or (h.vertex.id == b and h.twin.vertex.id == a) then return e end
  end
end

local function near(p, q, tolerance) return (p - q):length() < (tolerance or 1e-3) end

-- One mesh holding `a` and `b` side by side, b moved by `offset`: a's vertex k is vertex k, b's is #a + k.
local function side_by_side(a, b, offset)
  local positions, polygons = {}, {}
  for _, part in ipairs({ { a, meshedit.vec3(0, 0, 0) }, { b, offset } }) do
    local base = #positions
    for v in part[1]:vertices() do positions[base + v.id + 1] = v.position + part[2] end
    for f in part[1]:faces() do
      local polygon = {}
      for v in f:vertices() do polygon[#polygon + 1] = base + v.id + 1 end
      polygons[#polygons + 1] = polygon
    end
  end
  return meshedit.from_polygons(positions, polygons)
end


step("Face points", function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local top = cube:face(1)
  highlight(top, "yellow")
  local half = cube:vertex(7).position
  say [[
# Catmull-Clark subdivision

Loop subdivision (part 6) needs triangles. **Catmull-Clark** takes any polygons: every face of n corners becomes
n quads. From the old mesh it makes a **face point** per face, an **edge point** per edge and a **vertex point**
per old vertex (where that vertex moves). The window's **Subdivide** menu runs it whole, or a phase at a time.]]
  say("On screen: the unit cube centred at 0 as **six quads** (" .. counts(cube) .. "), its corners at (±"
    .. num(half.x) .. ", ±" .. num(half.y) .. ", ±" .. num(half.z) .. "). The yellow face is the top, where z = "
    .. num(centroid(top).z) .. ".")
  local right = face_point(cube, top)
  local sum = centroid(top) * top:degree()
  answer {
    "A face point stands for its whole face, and no corner of the face counts more than another. Where would you "
      .. "put the yellow face's? Give x, y, z.",
    point = { right.x, right.y, right.z },
    feedback = function(p)
      if p:length() < 1e-3 then
        return "(0, 0, 0) is the centre of the whole cube, the mean of all 8 corners; the face point is the mean of "
          .. "this face's corners only."
      end
      if near(p, sum) then return point(sum) .. " is the sum of the four corners: divide it by 4." end
      for v in top:vertices() do
        if near(p, v.position) then return "That is a corner of the face; the face point is the mean of all four." end
      end
    end,
    hint = "Add up the four corners and divide by four.",
  }
  label(top, "face point")
  say("The core puts it at " .. point(right) .. ": the centre of the top. That is the rule: a face point is the "
    .. "**centroid** of the face's corners, their sum divided by their number. Every face gets one; on the cube "
    .. "they are the centres of the six sides.")
end)

step("Edge points", function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = false }  -- the lesson's own labels only: the edge, the two face points
  local e = edge_between(cube, 0, 1)
  local h = e.halfedge
  local a, b = h.vertex.position, h.twin.vertex.position
  local f0, f1 = centroid(h.face), centroid(h.twin.face)
  highlight(e, "orange")
  label(e, tostring(e))
  label(h.face, "face point")
  label(h.twin.face, "face point")
  say("Each edge gets an **edge point**, a new vertex near the edge. The orange edge " .. tostring(e) .. " runs "
    .. "from " .. point(a) .. " to " .. point(b) .. "; the two faces beside it have the face points "
    .. point(f0) .. " and " .. point(f1) .. ".")
  local both = "The two ends and the two face points"
  choose {
    "The edge point should lie near the edge, but also feel the two faces beside it, so that the new mesh is "
      .. "smoother than the old. Which points would you average?",
    options = { "The two ends: the midpoint", both, "The two face points only", "Every corner of the two faces" },
    answer = both,
    feedback = {
      ["The two ends: the midpoint"] = "The midpoint feels only the edge: a sharp edge between two faces would stay "
        .. "exactly as sharp. (That is the rule on a boundary edge, where there is only one face.)",
      ["The two face points only"] = "The face points alone forget where the edge itself is: every edge of a face "
        .. "would feel the same two points and lose its place.",
      ["Every corner of the two faces"] = "The faces' corners are what their face points already sum up; counting "
        .. "them again weighs the far corners as much as the edge's own ends.",
      [both] = "Yes: the edge point is the mean of those four points, (a + b + f0 + f1) / 4.",
    },
    hint = "It must depend on the edge and on each face beside it. Which points stand for those?",
  }
  local right = edge_point(cube, e)
  local midpoint = (a + b) / 2
  answer {
    "Where is the orange edge's edge point? Give x, y, z.",
    point = { right.x, right.y, right.z },
    feedback = function(p)
      if near(p, midpoint) then
        return point(midpoint) .. " is the edge's midpoint: that forgets the two face points, which pull the edge "
          .. "point inwards. (The midpoint is the rule only on a boundary edge.)"
      end
      if near(p, (f0 + f1) / 2) then
        return "That is the mean of the two face points alone; the edge's own two ends count as well."
      end
      if near(p, (midpoint + f0 + f1) / 3) then
        return "That averages the midpoint with the two face points, counting the edge's ends once between them. "
          .. "Each of the four points, a, b and the two face points, weighs 1/4."
      end
    end,
    hint = "(a + b + f0 + f1) / 4, with a and b the edge's ends and f0, f1 the two faces' face points.",
  }
  arrow(midpoint, right, "blue")
  say("The core puts it at " .. point(right) .. ". The blue arrow goes from the midpoint " .. point(midpoint)
    .. " to it: the two face points pull it " .. num((midpoint - right):length()) .. " in, towards the "
    .. "faces' centres.")
end)

step("Vertex points", function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = false }
  local v = cube:vertex(0)
  local n = v:degree()
  local P = v.position
  local faces, midpoints, neighbours = {}, {}, {}
  for h in v:halfedges() do
    if h.face.kind == "face" then faces[#faces + 1] = centroid(h.face) end
    midpoints[#midpoints + 1] = (P + h.twin.vertex.position) / 2
    neighbours[#neighbours + 1] = h.twin.vertex.position
  end
  local F, R = mean(faces), mean(midpoints)
  highlight(v, "yellow")
  label(v, "v0, n = " .. n)
  local inwards = "Towards the centre, along the diagonal"
  choose {
    "Catmull-Clark moves every old vertex too, to its vertex point, an average of points around it. Where will "
      .. "the yellow corner v0 go?",
    options = { "It stays where it is", inwards, "Away from the centre", "Onto one of its faces' face points" },
    answer = inwards,
    feedback = {
      ["It stays where it is"] = "Then the cube's corners would stay sharp at every level. Catmull-Clark "
        .. "approximates: the averages pull every old vertex in.",
      ["Away from the centre"] = "Every point around v0, its faces' face points and its edges' midpoints, lies "
        .. "inside the corner; an average of them cannot move it out.",
      ["Onto one of its faces' face points"] = "v0 has three faces alike; an average treats them the same, so it "
        .. "cannot pick one. And it would jump much too far.",
      [inwards] = "Yes: the points it averages all lie inside the corner, and the cube's symmetry keeps it on "
        .. "the diagonal. How far it goes is what the rule below says.",
    },
    hint = "An average of points can only land among them. Where are the points around v0?",
  }
  say [[
An old vertex P with n edges moves to its **vertex point**

  (F + 2R + (n - 3) P) / n

where F is the mean of the face points of its n faces and R the mean of the **midpoints** of its n edges.]]
  say("The yellow corner v0 has n = " .. n .. " edges, and\n\n"
    .. "- P, where it is: " .. point(P) .. "\n"
    .. "- F, the mean of its faces' face points: " .. point(F) .. "\n"
    .. "- R, the mean of its edges' midpoints: " .. point(R))
  local right = vertex_point(cube, v)
  local mistakes = {
    { P, "It moves: Catmull-Clark approximates, every old vertex goes to its vertex point." },
    { (F + 2 * R + P) / n, "That weighs P once; its weight is n - 3, which is 0 at a corner of degree 3." },
    { (F + R + P) / 3, "That is the plain mean of F, R and P. The rule counts R twice and P n - 3 times, over n." },
    { (F + 2 * mean(neighbours)) / n, "That uses the mean of the neighbouring vertices for R; R is the mean of "
      .. "the edges' midpoints, halfway to the neighbours." },
    { F, "That is F alone; add 2R and (n - 3) P, then divide by n." },
  }
  if near(mistakes[4][1], F) then  -- the same point on the cube: one answer, both mistakes named
    mistakes[4][2] = mistakes[4][2] .. " (Here that is also F alone, which leaves out 2R and (n - 3) P.)"
  end
  answer {
    "Where does the corner v0 go? Give x, y, z.",
    point = { right.x, right.y, right.z },
    feedback = function(p)
      for _, mistake in ipairs(mistakes) do
        if near(p, mistake[1]) then return mistake[2] end
      end
    end,
    hint = "With n = 3 the (n - 3) P term is zero: (F + 2R) / 3.",
  }
  arrow(P, right, "blue")
  local ratio = right:length() / P:length()
  say("The core moves v0 to " .. point(right) .. " (blue arrow): " .. (fraction(ratio) or num(ratio)) .. " of its "
    .. "distance from the centre, along the same diagonal. Every corner of the cube does the same, so one level "
    .. "already rounds the cube off.")
end)

step("Counting after one level", function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local V, E, F = cube:num_vertices(), cube:num_edges(), cube:num_faces()
  local after = catmull_clark(cube)
  local sides = 0
  for f in cube:faces() do sides = sides + f:degree() end
  say("One level keeps every old vertex, moved to its vertex point. The cube has V = " .. V .. ", E = " .. E
    .. " and F = " .. F .. ".")
  local right = (V + E + F) .. " = V + E + F"
  assert(after:num_vertices() == V + E + F, "the core's vertex count is not V + E + F")
  local options = { right, (V + E) .. " = V + E", (V + F) .. " = V + F", (4 * F) .. " = 4F" }
  choose {
    "How many vertices will the cube have after one level?",
    options = options,
    answer = right,
    feedback = {
      [options[2]] = "V + E is Loop's count: it adds a vertex per edge only. Catmull-Clark adds one per face too.",
      [options[3]] = "That leaves out the edge points: every edge gets a new vertex as well.",
      [options[4]] = "4F counts every quad's corners separately, but faces share their corners.",
      [right] = "Yes: the old vertices stay, plus one new vertex per edge and one per face.",
    },
    hint = "Which of the three kinds of points become new vertices, and how many of each are there?",
  }
  answer {
    "Each face of n corners becomes n quads. How many faces after one level?",
    number = after:num_faces(),
    tolerance = 0.5,
    feedback = function(value)
      if value == F then return "The faces are not kept: each one is cut into quads, one per corner." end
      if value == 2 * F * 4 then
        return "That is Loop's count on the cube of " .. 2 * F .. " triangles; here each quad gives 4 quads."
      end
      if value == V + E + F then return "That is the number of vertices; each face gives one quad per corner." end
    end,
    hint = "The cube has " .. F .. " faces of 4 corners each.",
  }
  say "Now do it: **Subdivide > Catmull-Clark subdivision** (the menu above the view) on the cube on screen."
  wait_for {
    condition = function()
      local mesh = current_mesh()
      return mesh ~= nil and mesh:num_faces() == after:num_faces() and mesh:num_vertices() == after:num_vertices()
    end,
    hint = "Subdivide > Catmull-Clark subdivision",
  }
  camera "fit"
  view { labels = false }  -- 26 vertices and 48 edges: their ids would hide the quads
  local yours = current_mesh()
  say("Your level: " .. counts(yours) .. ", all " .. face_kinds(yours) .. ". Every new quad joins an old "
    .. "vertex, an edge point, a face point and the next edge point, so the " .. sides .. " corners of the old faces "
    .. "give " .. after:num_faces() .. " quads and E' = 2E + " .. sides .. " = " .. after:num_edges() .. " edges.")
end)

-- Whether `mesh` (the mesh on screen) is `expected`: the same counts and every vertex at the same place by id (the
-- window's phases and the lesson's are the core's, so a vertex keeps its id in both).
local function same_mesh(mesh, expected)
  if not mesh or mesh:num_vertices() ~= expected:num_vertices() or mesh:num_faces() ~= expected:num_faces()
    or mesh:num_edges() ~= expected:num_edges() then
    return false
  end
  for v in expected:vertices() do
    local ok, same = pcall(function() return near(mesh:vertex(v.id).position, v.position, 1e-9) end)
    if not ok or not same then return false end
  end
  return true
end

step("The app's phases", function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local e = edge_between(cube, 0, 1)
  local a, b = cube:vertex(0).position, cube:vertex(1).position
  highlight(e, "yellow")
  say [[
The **Subdivide** menu also runs Catmull-Clark **one phase at a time**, as Shift+L does for Loop:
1. **compute** every face, edge and vertex point from the cube as it is; nothing changes yet;
2. **split** every face into quads, with a new vertex on every edge and in every face;
3. **move** every vertex to its point.]]
  local midpoint = "At the edge's midpoint " .. point((a + b) / 2)
  local edge_point_option = "At its edge point " .. point(edge_point(cube, e))
  local corner = "On v0, until phase 3 moves it"
  choose {
    "After phase 2, where is the new vertex on the yellow edge " .. tostring(e) .. "?",
    options = { edge_point_option, midpoint, corner },
    answer = midpoint,
    feedback = {
      [edge_point_option] = "Phase 2 only changes the connectivity. The edge point is where phase 3 moves it to.",
      [corner] = "A new vertex is made on its edge, between v0 and v1, never on top of a corner.",
      [midpoint] = "Yes: phase 2 places it halfway, so the shape has not changed yet. Linear subdivision stops "
        .. "there.",
    },
    hint = "Phase 2 splits faces; which phase moves vertices?",
  }
  local expected = cube:copy()
  local phases = expected:subdivision_phases("catmull-clark")
  local new_vertex = cube:num_vertices() + e.id  -- the core numbers edge points after the old vertices
  local computed
  say "Now run **Subdivide > Catmull-Clark** one phase at a time, three times; the menu item names the next phase."
  local phase = 1
  while phase <= 3 do
    wait_for { command = "catmull-clark-phase", hint = "Subdivide > " .. phases.next_label }
    assert(phases:step())
    if phase == 1 then computed = phases:points() end
    local mesh = current_mesh()
    if not same_mesh(mesh, expected) then
      expected = quad_cube()
      phases = expected:subdivision_phases("catmull-clark")
      show(quad_cube())
      highlight(e, "yellow")
      say("That is not the cube after phase " .. phase .. " (did another command change the mesh?). Here is a "
        .. "fresh cube: from phase 1 again.")
      phase = 1
    else
      if phase == 1 then
        say("**Phase 1** computed " .. cube:num_faces() .. " face points, " .. cube:num_edges() .. " edge points and "
          .. cube:num_vertices() .. " vertex points, and nothing moved: the edge point of " .. tostring(e) .. " is "
          .. point(computed.edges[e.id]) .. ", the vertex point of v0 " .. point(computed.vertices[0]) .. ".")
      elseif phase == 2 then
        label("v" .. new_vertex, "new on " .. tostring(e))
        say("**Phase 2** split the " .. cube:num_faces() .. " faces into " .. mesh:num_faces() .. " quads. The new "
          .. "vertex v" .. new_vertex .. " sits at " .. point(mesh:vertex(new_vertex).position) .. ", the midpoint, "
          .. "and v0 is still at " .. point(mesh:vertex(0).position) .. ".")
      else
        say("**Phase 3** moved every vertex to its point: v" .. new_vertex .. " to "
          .. point(mesh:vertex(new_vertex).position) .. ", the edge point, and v0 to "
          .. point(mesh:vertex(0).position) .. ", its vertex point. One level done: " .. counts(mesh) .. ".")
      end
      phase = phase + 1
    end
  end
end)

step("Triangles become quads", function()
  local tetrahedron = meshedit.tetrahedron()
  show(tetrahedron)
  camera "fit"
  view { halfedges = false, labels = true }
  local after = catmull_clark(tetrahedron)
  local right = after:num_faces() .. " quads"
  local loop = tetrahedron:copy()
  assert(loop:loop_subdivide())
  local options = { right, loop:num_faces() .. " triangles", tetrahedron:num_faces() .. " triangles and "
    .. after:num_faces() .. " quads" }
  say("Catmull-Clark does not need quads. Here is a tetrahedron: " .. counts(tetrahedron) .. ", all "
    .. face_kinds(tetrahedron) .. ".")
  choose {
    "What faces does one level of Catmull-Clark make of it?",
    options = options,
    answer = right,
    feedback = {
      [options[2]] = "That is Loop subdivision: each triangle into four triangles. Catmull-Clark cuts a face of n "
        .. "corners into n quads, one at each corner.",
      [options[3]] = "No old face survives: every triangle is cut into quads, one per corner.",
      [right] = "Yes: each triangle gives three quads, one at each corner.",
    },
    hint = "A face of n corners gives n faces. What kind of faces?",
  }
  show(after)
  camera "fit"
  view { labels = false }
  say("The core's level: " .. counts(after) .. ", all " .. face_kinds(after) .. ". After one level every face is a "
    .. "quad whatever the input was, so from then on Catmull-Clark works on quads only. The vertices that were "
    .. "triangles' face points have 3 edges: those, like the old corners, are the **extraordinary** vertices "
    .. "(not 4 edges), and their number never grows.")
end)

step("Boundary rules", function()
  local grid = quad_grid(2)
  show(grid)
  camera { fit = true, pitch = 70 }  -- a flat mesh: seen from above
  view { halfedges = false, labels = true }
  local corner = grid:vertex(0)
  local e = edge_between(grid, 0, 1)
  local a, b = corner.position, grid:vertex(1).position
  local inside = centroid(e.halfedge.face.kind == "face" and e.halfedge.face or e.halfedge.twin.face)
  highlight(e, "orange")
  highlight(corner, "yellow")
  label(corner, "corner v0")
  say("On a mesh with a **boundary** the border gets rules of its own, so it stays a curve of its own. This grid "
    .. "of quads has " .. counts(grid) .. " and " .. grid:num_boundaries() .. " boundary loop. The orange edge "
    .. "runs along the boundary from " .. point(a) .. " to " .. point(b) .. "; it has one face beside it, whose "
    .. "face point is " .. point(inside) .. ".")
  local right_edge = edge_point(grid, e)
  answer {
    "Where is the orange boundary edge's edge point? Give x, y.",
    point = { right_edge.x, right_edge.y },
    feedback = function(p)
      if near(p, (a + b + inside) / 3) then
        return "That is the interior rule with the one face point it has. A boundary edge ignores the faces: its "
          .. "point is the midpoint, so the border depends only on the border."
      end
      if near(p, (a + b + 2 * inside) / 4) or near(p, (a + b + inside) / 4) then
        return "That applies the interior rule, with a face point that is not there. A boundary edge's point is "
          .. "simpler."
      end
    end,
    hint = "A boundary edge has only one face. Which point of the edge needs no face at all?",
  }
  say("The core puts it at the **midpoint**, " .. point(right_edge) .. ".")
  local left, right = nil, nil
  for h in corner:halfedges() do
    local other = h.twin.vertex
    if h.edge:is_boundary() then
      if left then right = other.position else left = other.position end
    end
  end
  local along = "Itself and its two neighbours along the boundary"
  choose {
    "The yellow corner is on the boundary too. Which points should its rule use, so that the border stays a curve "
      .. "of its own?",
    options = { along, "Itself and all its neighbours", "Itself, its neighbours and its face's face point" },
    answer = along,
    feedback = {
      ["Itself and all its neighbours"] = "A neighbour inside the mesh would pull the border inwards, and the border "
        .. "would depend on the inside. Only the points on the border itself may count.",
      ["Itself, its neighbours and its face's face point"] = "The face point lies inside the mesh: the border would "
        .. "then depend on the faces, as the edge point you just found does not.",
      [along] = "Yes: the same rule as a curve's, from the points of the border alone.",
    },
    hint = "The edge point of a boundary edge used the edge alone. Do the same for a vertex.",
  }
  say("A boundary vertex P moves to 3/4 P + 1/8 of its two neighbours **along the boundary**. The yellow corner's "
    .. "are " .. point(left) .. " and " .. point(right) .. ".")
  local right_vertex = vertex_point(grid, corner)
  answer {
    "Where does the yellow corner go? Give x, y.",
    point = { right_vertex.x, right_vertex.y },
    feedback = function(p)
      if near(p, a) then return "A boundary vertex moves too, by the boundary's own rule." end
      if near(p, a * 0.5 + (left + right) * 0.25) then
        return "That gives each neighbour 1/4; the rule keeps 3/4 of the corner and gives each neighbour 1/8."
      end
      if near(p, (a + left + right) / 3) then
        return "That is the plain mean of the corner and its two neighbours; the rule keeps 3/4 of the corner."
      end
    end,
    hint = "3/4 of the corner plus 1/8 of each of its two boundary neighbours.",
  }
  local after = catmull_clark(grid)
  show(after)
  clear()
  view { labels = false }
  highlight(after:vertex(0), "yellow")
  label(after:vertex(0), "corner")
  arrow(a, right_vertex, "blue")
  say("The core's level: " .. counts(after) .. ", still " .. after:num_boundaries() .. " boundary loop. The corner "
    .. "went from " .. point(a) .. " to " .. point(right_vertex) .. " (blue arrow), cut off as a closed mesh's "
    .. "corners are.")
end)

step("Linear subdivision beside it", function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local linear = cube:copy()
  assert(linear:linear_subdivide())
  local smooth = catmull_clark(cube)
  say("The Subdivide menu also has **Linear subdivision**: the same new vertices and the same quads as "
    .. "Catmull-Clark (" .. counts(linear) .. " on the cube), but every new vertex stays at its edge's midpoint or "
    .. "its face's centroid.")
  local ratio = smooth:vertex(0).position:length() / cube:vertex(0).position:length()
  local right = "Where it was"
  local travelled = fraction(1 - ratio) or num(1 - ratio)
  local options = { right, travelled .. " of the way to the centre", "At a face centroid" }
  choose {
    "After one level of linear subdivision, where is the corner v0?",
    options = options,
    answer = right,
    feedback = {
      [options[2]] = "That is where Catmull-Clark's vertex point takes it; linear subdivision moves no old vertex.",
      [options[3]] = "The face centroids are new vertices (the face points); the old corner is still there too.",
      [right] = "Yes: linear subdivision only adds vertices; the shape stays the cube.",
    },
    hint = "Linear subdivision only places new vertices at midpoints and centroids. What does it do to the old ones?",
  }
  local moved = 0
  for v in cube:vertices() do moved = math.max(moved, (linear:vertex(v.id).position - v.position):length()) end
  local width = 0
  for v in cube:vertices() do width = math.max(width, v.position.x) end
  local both = side_by_side(linear, smooth, meshedit.vec3(4 * width, 0, 0))
  show(both)
  camera "fit"
  view { labels = false }
  label(both:vertex(0), "linear")
  label(both:vertex(linear:num_vertices()), "Catmull-Clark")
  highlight(both:vertex(0), "yellow")
  highlight(both:vertex(linear:num_vertices()), "yellow")
  say("Left, linear: " .. (moved == 0 and "not one old vertex moved" or ("its old vertices moved by at most "
    .. num(moved))) .. ", and v0 is still at " .. point(linear:vertex(0).position) .. ". Right, Catmull-Clark: "
    .. "v0 went to " .. point(smooth:vertex(0).position)
    .. ". Both have " .. counts(smooth) .. ".")
  local levels = smooth:copy()
  assert(levels:catmull_clark())
  assert(levels:catmull_clark())
  say("Linear subdivision gives a finer mesh of the same shape; Catmull-Clark's rules move every vertex, and "
    .. "level after level the mesh converges to a smooth surface (v0 starts "
    .. num(cube:vertex(0).position:length()) .. " from the centre; after three levels it is "
    .. num(levels:vertex(0).position:length()) .. " from it, and there are " .. levels:num_faces()
    .. " quads). Try both in the window's **Subdivide** menu.")
end)

step("Your own Catmull-Clark", function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = false }
  local linear = cube:copy()
  assert(linear:linear_subdivide())
  local right = "Linear subdivision first, then move every vertex"
  choose {
    "You have seen that linear subdivision makes Catmull-Clark's quads with every new vertex at a midpoint or a "
      .. "centroid. How could your own code do one level of Catmull-Clark?",
    options = { right, "Move the old vertices first, then subdivide", "Subdivide, then move only the old vertices" },
    answer = right,
    feedback = {
      ["Move the old vertices first, then subdivide"] = "Then the midpoints and centroids linear subdivision places "
        .. "would come from the moved corners, and the edge and face points would be wrong: the rules read the "
        .. "mesh before anything moves.",
      ["Subdivide, then move only the old vertices"] = "The edge vertices move too: from the midpoint to the edge "
        .. "point, pulled toward the two faces. Only the face vertices stay, at their faces' centroids.",
      [right] = "Yes: mesh:linear_subdivide() makes the quads, and each vertex's rule can be read from its "
        .. "neighbours in the refined mesh, as long as every new position is computed before any moves.",
    },
    hint = "Which phase of the Subdivide menu's Catmull-Clark is exactly linear subdivision?",
  }
  say("Linear subdivision gives " .. counts(linear) .. ", every vertex where phase 2 put it. Now write it: open "
    .. "**scripts/student/catmull_clark.lua**. It gives the rules as they read in the refined mesh (an edge vertex "
    .. "goes to the mean of its four neighbours, an old vertex to (F + 2R + (n - 3) P) / n with R the mean of its "
    .. "neighbours). The lesson runs your `catmull_clark_level` on a copy of this cube each time you save the file "
    .. "and compares every vertex with the core's level.")
  your_turn {
    exercise = "catmull_clark",
    mesh = cube,
    hint = "Remember the old ids, call mesh:linear_subdivide(), compute every new position into a table, then move "
      .. "them all.",
  }
  say [[
Your level is the core's. The **Exercises** tab (**X**, choose **catmull_clark**, **Run mine**) runs it on any
mesh without triangles that you open (File > Open); try one with a boundary for the boundary rules. From a
terminal, the exercise's own suite grades it:

    meshedit grade --suite scripts/exercises/catmull_clark.lua --submission scripts/student]]
end)
