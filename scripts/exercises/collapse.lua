-- An exercise defined in Lua alone: edge collapse. The window's Exercises tab lists it (its "mine" run, the pointer
-- table beside the reference's, the write-by-write replay), a lesson asks for it with
-- your_turn{ exercise = "collapse", mesh = m, element = e }, and it grades as a suite of its own:
--   meshedit grade --suite scripts/exercises/collapse.lua --submission scripts/student
-- The reference is the core's collapse (engine/core/mesh_ops.h); the diagnoses name the likely mistakes before
-- the checker's own differences (validation, the surface up to renumbering, the returned vertex).

-- The diagram's names around e, read from the mesh before the call: h0 inside a face, a = h0.vertex, b its twin's.
local function names(e)
  local h0 = e.halfedge
  if h0.face:is_boundary() then h0 = h0.twin end
  local h1 = h0.twin
  return { h0 = h0, h1 = h1, a = h0.vertex, b = h1.vertex, c = h0.next.next.vertex,
    d = (not h1.face:is_boundary()) and h1.next.next.vertex or nil }
end

local function near(p, q) return (p - q):length() < 1e-9 end

-- Whether `mesh` has a vertex at `p`.
local function has_vertex_at(mesh, p)
  for v in mesh:vertices() do
    if near(v.position, p) then return true end
  end
  return false
end

exercise {
  name = "collapse",
  title = "Extra: edge collapse",
  file = "collapse.lua",
  call = "collapse_edge",
  signature = "collapse_edge(mesh, e) -> the vertex that remains, or nil",
  takes = "edge",
  reference = function(mesh, e) return mesh:collapse(e) end,
  hint = "Read every handle first (h0 to h5, a to d, t2 to t5), point the halfedges that left b at a, join the "
    .. "twins across each vanished triangle, repoint a, c and d, move a to the midpoint, then delete b, e, the two "
    .. "faces, their six halfedges and the edges b-c and b-d.",
  diagnose = function(run)
    local n = names(run.element)
    local a, b = n.a.position, n.b.position
    local mid = (a + b) / 2
    local out = {}
    local removed = run.before:num_vertices() - run.mine:num_vertices()
    if removed == 0 then
      out[#out + 1] = "your collapse_edge deleted no vertex: b must go (mesh:delete(b)), after every halfedge that "
        .. "left b leaves a"
    elseif not has_vertex_at(run.mine, mid) then
      if has_vertex_at(run.mine, a) then
        out[#out + 1] = "the vertex that remains is still where a was; collapse moves it to the midpoint of a and b, "
          .. string.format("(%g, %g, %g)", mid.x, mid.y, mid.z)
      else
        out[#out + 1] = "no vertex of yours is at the midpoint of a and b, "
          .. string.format("(%g, %g, %g)", mid.x, mid.y, mid.z) .. ", where the vertex that remains goes"
      end
    end
    local faces_gone = run.before:num_faces() - run.mine:num_faces()
    local want = run.before:num_faces() - run.reference:num_faces()
    if removed > 0 and faces_gone < want then
      out[#out + 1] = "your collapse_edge deleted " .. faces_gone .. " face(s); the two triangles beside e both "
        .. "vanish (delete f0 and f1 with their halfedges)"
    end
    return out
  end,
  fixtures = {
    { name = "an edge of an icosahedron", mesh = meshedit.icosahedron(), element = "e0", points = 2 },
    { name = "another edge of an icosahedron", mesh = meshedit.icosahedron(), element = "e17", points = 2 },
    { name = "a diagonal of a 2x2 grid's corner square", mesh = meshedit.grid(2, 2), element = "e2", points = 1 },
  },
}
