-- An exercise defined in Lua alone: one level of Catmull-Clark subdivision on a mesh without triangles, written the
-- way lesson 7 teaches it. The student lets linear subdivision make the quads (mesh:linear_subdivide(), which puts
-- every new vertex at its edge's midpoint or its face's centroid), then moves every vertex by the rules, read from
-- its neighbours in the refined mesh, all positions computed before any moves. The Exercises tab lists it, lesson 7
-- asks for it with your_turn{ exercise = "catmull_clark", mesh = m }, and it grades as a suite of its own:
--   meshedit grade --suite scripts/exercises/catmull_clark.lua --submission scripts/student
-- The reference is the core's Catmull-Clark (engine/core/catmull_clark.h). Linear subdivision and Catmull-Clark
-- lay out the new ids alike (engine/core/subdivision_refine.h), so the diagnoses compare the student's vertices
-- with the reference's by id: which kind of vertex (old, edge, face) is misplaced, and how.

local function near(p, q) return (p - q):length() < 1e-9 end

local function fmt(p) return string.format("(%.4g, %.4g, %.4g)", p.x, p.y, p.z) end

-- The refined mesh's vertices by kind: old (the input's ids), edge (a new vertex joined to an old one) and face (a
-- new vertex joined to edge vertices only), as lists of ids.
local function kinds(before, refined)
  local old, by_kind = {}, { old = {}, edge = {}, face = {} }
  for v in before:vertices() do old[v.id] = true end
  for v in refined:vertices() do
    local kind = "face"
    if old[v.id] then
      kind = "old"
    else
      for w in v:neighbors() do
        if old[w.id] then kind = "edge" end
      end
    end
    by_kind[kind][#by_kind[kind] + 1] = v.id
  end
  return by_kind
end

-- How many of `ids` are at the same place in `mine` and in `other`; the first that is not.
local function matches(ids, mine, other)
  local count, first = 0, nil
  for _, id in ipairs(ids) do
    if near(mine:vertex(id).position, other:vertex(id).position) then count = count + 1 else first = first or id end
  end
  return count, first
end

-- The mesh linear subdivision makes of `before`: where every vertex sits before the rules move it.
local function linear_of(before)
  local linear = before:copy()
  assert(linear:linear_subdivide())
  return linear
end

-- Catmull-Clark's rule for vertex `v` of the refined mesh, read from its neighbours there; `kind` is "old", "edge"
-- or "face" (kinds()).
local function rule(v, kind)
  local p, sum, n = v.position, meshedit.vec3(0, 0, 0), 0
  for w in v:neighbors() do sum, n = sum + w.position, n + 1 end
  if kind == "face" or (kind == "edge" and v:is_boundary()) then return p end
  if kind == "edge" then return sum / n end
  if v:is_boundary() then
    local along = meshedit.vec3(0, 0, 0)
    for h in v:halfedges() do
      if h.face:is_boundary() or h.twin.face:is_boundary() then along = along + h.twin.vertex.position end
    end
    return p * 0.5 + along * 0.25
  end
  local faces = meshedit.vec3(0, 0, 0)
  for h in v:halfedges() do faces = faces + h.next.next.vertex.position end
  return (faces / n + sum / n * 2 + p * (n - 3)) / n
end

-- The rules applied to `linear` vertex by vertex in id order, each written as soon as it is computed: what a loop
-- that moves as it goes gives.
local function moved_in_place(linear, by_kind)
  local mesh = linear:copy()
  local kind_of = {}
  for kind, ids in pairs(by_kind) do
    for _, id in ipairs(ids) do kind_of[id] = kind end
  end
  for v in mesh:vertices() do v.position = rule(v, kind_of[v.id]) end
  return mesh
end

-- Whether every vertex of `a` is where the same id of `b` is.
local function same_places(a, b)
  for v in a:vertices() do
    if not near(v.position, b:vertex(v.id).position) then return false end
  end
  return true
end

local function diagnose_edges(run, by_kind, linear)
  local right, first = matches(by_kind.edge, run.mine, run.reference)
  if right == #by_kind.edge then return nil end
  local at_midpoint = matches(by_kind.edge, run.mine, linear)
  local id = "v" .. first
  if at_midpoint == #by_kind.edge then
    return "your edge points are still at the edges' midpoints, where linear subdivision put them (e.g. " .. id
      .. " at " .. fmt(run.mine:vertex(first).position) .. "); an edge point is the mean of the edge's two ends and "
      .. "the two face points beside it, (a + b + f0 + f1) / 4: in the refined mesh, the mean of its four "
      .. "neighbours"
  end
  return right .. " of your " .. #by_kind.edge .. " edge points are right; " .. id .. " is at "
    .. fmt(run.mine:vertex(first).position) .. ", the reference's at " .. fmt(run.reference:vertex(first).position)
    .. " (interior edge: the mean of its four neighbours; boundary edge: its midpoint)"
end

local function diagnose_old(run, by_kind, linear)
  local right, first = matches(by_kind.old, run.mine, run.reference)
  if right == #by_kind.old then return nil end
  local id = "v" .. first
  if matches(by_kind.old, run.mine, linear) == #by_kind.old then
    return "your old vertices have not moved (" .. id .. " is still at " .. fmt(run.mine:vertex(first).position)
      .. "); each goes to its vertex point, (F + 2R + (n - 3) P) / n inside the mesh, 1/2 P + 1/4 (the two "
      .. "boundary midpoints beside it) on the boundary"
  end
  return right .. " of your " .. #by_kind.old .. " old vertices are right; " .. id .. " is at "
    .. fmt(run.mine:vertex(first).position) .. ", its vertex point is " .. fmt(run.reference:vertex(first).position)
    .. ": F is the mean of the face vertices of the quads around it, R the mean of its neighbours (the edge "
    .. "midpoints), n its degree"
end

exercise {
  name = "catmull_clark",
  title = "Extra: Catmull-Clark subdivision",
  file = "catmull_clark.lua",
  call = "catmull_clark_level",
  signature = "catmull_clark_level(mesh) -> nothing; one level of Catmull-Clark in place (no triangles)",
  takes = "mesh",
  reference = function(mesh)
    for f in mesh:faces() do
      if f:degree() == 3 then
        return nil, tostring(f) .. " is a triangle: this exercise's way (linear subdivision, then the rules) needs "
          .. "faces of 4 or more corners, since linear subdivision cuts a triangle into four triangles"
      end
    end
    assert(mesh:catmull_clark())
    return nil
  end,
  hint = "Record which vertex ids are old, call mesh:linear_subdivide(), compute every new position from the "
    .. "refined mesh (face vertices stay; an edge vertex goes to the mean of its neighbours, or stays on the "
    .. "boundary; an old vertex to (F + 2R + (n - 3) P) / n), and only then move them all.",
  diagnose = function(run)
    if run.mine:num_vertices() ~= run.reference:num_vertices() or run.mine:num_faces() ~= run.reference:num_faces()
    then
      return "your mesh has " .. run.mine:num_vertices() .. " vertices and " .. run.mine:num_faces() .. " faces; one "
        .. "level has " .. run.reference:num_vertices() .. " and " .. run.reference:num_faces() .. " (V + E + F "
        .. "vertices, a quad per corner of every face): let mesh:linear_subdivide() make them, once"
    end
    local by_kind = kinds(run.before, run.mine)
    local linear = linear_of(run.before)
    if same_places(run.mine, moved_in_place(linear, by_kind)) then
      return "your vertices read neighbours you had already moved: each one went to its rule's place from a mesh "
        .. "in which the vertices before it (by id) had moved. Compute every new position first, into a table, "
        .. "from the mesh as linear subdivision left it; then move them all"
    end
    local out = {}
    local face_right, face_first = matches(by_kind.face, run.mine, run.reference)
    if face_right < #by_kind.face then
      out[#out + 1] = "your face vertex v" .. face_first .. " moved to " .. fmt(run.mine:vertex(face_first).position)
        .. "; a face point is its face's centroid, where linear subdivision already put it: leave face vertices "
        .. "where they are"
    end
    out[#out + 1] = diagnose_edges(run, by_kind, linear)
    out[#out + 1] = diagnose_old(run, by_kind, linear)
    return out
  end,
  fixtures = {
    { name = "a cube of six quads", mesh = meshedit.from_polygons(
      { { -0.5, -0.5, -0.5 }, { 0.5, -0.5, -0.5 }, { -0.5, 0.5, -0.5 }, { 0.5, 0.5, -0.5 },
        { -0.5, -0.5, 0.5 }, { 0.5, -0.5, 0.5 }, { -0.5, 0.5, 0.5 }, { 0.5, 0.5, 0.5 } },
      { { 1, 3, 4, 2 }, { 5, 6, 8, 7 }, { 1, 2, 6, 5 }, { 3, 7, 8, 4 }, { 1, 5, 7, 3 }, { 2, 4, 8, 6 } }),
      points = 2 },
    { name = "a 2x2 grid of quads (a boundary)", mesh = meshedit.from_polygons(
      { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0.5 }, { 2, 1, 0 }, { 0, 2, 0 }, { 1, 2, 0 },
        { 2, 2, 0 } },
      { { 1, 2, 5, 4 }, { 2, 3, 6, 5 }, { 4, 5, 8, 7 }, { 5, 6, 9, 8 } }),
      points = 2 },
    { name = "a square pyramid (its triangles are refused: change nothing)", mesh =
      meshedit.from_polygons({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 } },
        { { 4, 3, 2, 1 }, { 1, 2, 5 }, { 2, 3, 5 }, { 3, 4, 5 }, { 4, 1, 5 } }),
      points = 1 },
  },
}
