---@meta meshedit
-- LuaLS type descriptions of the `meshedit` module (engine/script/*_bindings.cpp), for editors only: this file
-- is never run. Every `function X.name` / `function X:name` and `---@field` below names something the real
-- module has; tests/lesson/api_docs_test.cpp checks that in both directions, so keep them in step.

---A point or direction: a table {x=, y=, z=} sharing one metatable. Plain {x, y, z} or {x=, y=, z=} tables
---are accepted wherever a point is expected.
---@class vec3
---@field x number
---@field y number
---@field z number
---@operator add(vec3): vec3
---@operator sub(vec3): vec3
---@operator mul(number): vec3
---@operator div(number): vec3
---@operator unm: vec3
local vec3 = {}

---@param w vec3|number[]
---@return number
function vec3:dot(w) end

---@param w vec3|number[]
---@return vec3
function vec3:cross(w) end

---@return number
function vec3:length() end

---@return vec3 unit the vector divided by its length
function vec3:normalized() end

---Anything accepted as a point: a vec3, {x, y, z} or {x=, y=, z=}.
---@alias point vec3|number[]|{x: number, y: number, z: number}

---Element kinds as `x.kind` gives them.
---@alias ElementKind "vertex"|"halfedge"|"edge"|"face"|"boundary"

---Fields common to every element handle. `tostring(x)` gives its id ("h37"); handles compare with ==.
---@class Element
---@field id integer the element's index (h37 -> 37)
---@field kind ElementKind
---@field mesh Mesh the mesh the element belongs to
local Element = {}

---@return boolean
function Element:is_boundary() end

---@class Vertex: Element
---@field halfedge Halfedge one halfedge leaving the vertex (writable)
---@field position vec3 a fresh copy on each read; assign a point to move the vertex
local Vertex = {}

---@return integer number of edges at the vertex
function Vertex:degree() end

---Iterator over the halfedges leaving the vertex: v.halfedge first, then h.twin.next, which turns clockwise
---around the vertex seen from outside.
---@return fun(): Halfedge?
function Vertex:halfedges() end

---Iterator over the neighbouring vertices, in the order of Vertex:halfedges() (the far end of each).
---@return fun(): Vertex?
function Vertex:neighbors() end

---@class Halfedge: Element
---@field next Halfedge (writable)
---@field twin Halfedge (writable)
---@field vertex Vertex the vertex it leaves (writable)
---@field edge Edge (writable)
---@field face Face|Boundary (writable)
local Halfedge = {}

---@return Halfedge the halfedge whose next is this one
function Halfedge:prev() end

---Sets all five pointers at once.
---@param next Halfedge
---@param twin Halfedge
---@param vertex Vertex
---@param edge Edge
---@param face Face|Boundary
function Halfedge:set_neighbors(next, twin, vertex, edge, face) end

---@class Edge: Element
---@field halfedge Halfedge (writable)
local Edge = {}

---@class Face: Element
---@field halfedge Halfedge (writable)
local Face = {}

---@return integer number of sides
function Face:degree() end

---The face's halfedges: f.halfedge first, then h.next, counter-clockwise seen from outside.
---@return fun(): Halfedge?
function Face:halfedges() end

---@return fun(): Vertex?
function Face:vertices() end

---A boundary loop (a hole), stored like a face.
---@class Boundary: Element
---@field halfedge Halfedge (writable)
local Boundary = {}

---@return fun(): Halfedge?
function Boundary:halfedges() end

---@return fun(): Vertex?
function Boundary:vertices() end

---@return integer
function Boundary:degree() end

---@class Violation
---@field element string "h3"
---@field invariant string
---@field message string

---@class ValidationReport
---@field summary string
---@field total integer
---@field violations Violation[]

---One entry of mesh:record().
---@class EditRecord
---@field what "set"|"new"|"delete"|"operation"
---@field element string "h3"
---@field field string
---@field before string
---@field after string
---@field where string "flip.lua:12"

---One entry of mesh:diff().
---@class FieldChange
---@field element string "h3"
---@field field string "next"
---@field before string "h4"
---@field after string "h7"

---A copy of a mesh's state (mesh:snapshot()); tostring "snapshot (8 vertices, 18 edges, 12 faces)".
---@class Snapshot

---@class VertexRow
---@field id string
---@field halfedge string
---@field position vec3

---@class HalfedgeRow
---@field id string
---@field next string
---@field twin string
---@field vertex string
---@field edge string
---@field face string

---@class ElementRow
---@field id string
---@field halfedge string

---@class MeshTables
---@field vertices VertexRow[]
---@field halfedges HalfedgeRow[]
---@field edges ElementRow[]
---@field faces ElementRow[]
---@field boundaries ElementRow[]

---A half-edge mesh. tostring(mesh) -> "mesh (8 vertices, 18 edges, 12 faces)".
---@class Mesh
local Mesh = {}

---@return fun(): Halfedge?
function Mesh:halfedges() end
---@return fun(): Vertex?
function Mesh:vertices() end
---@return fun(): Edge?
function Mesh:edges() end
---@return fun(): Face?
function Mesh:faces() end
---@return fun(): Boundary?
function Mesh:boundaries() end

---Handle by id (may be dead; an error past the end).
---@param i integer
---@return Halfedge
function Mesh:halfedge(i) end
---@param i integer
---@return Vertex
function Mesh:vertex(i) end
---@param i integer
---@return Edge
function Mesh:edge(i) end
---@param i integer
---@return Face
function Mesh:face(i) end
---@param i integer
---@return Boundary
function Mesh:boundary(i) end

---The element with a printed id: mesh:element("h37").
---@param id string
---@return Element
function Mesh:element(id) end

---@return integer
function Mesh:num_vertices() end
---@return integer
function Mesh:num_halfedges() end
---@return integer
function Mesh:num_edges() end
---@return integer
function Mesh:num_faces() end
---@return integer
function Mesh:num_boundaries() end

---@return boolean ok
---@return ValidationReport report
function Mesh:validate() end

---Writes the mesh (format from the extension). Not available to student code under grading.
---@param path string
function Mesh:save(path) end

---@return Mesh
function Mesh:copy() end

---@param element Element
---@return boolean
function Mesh:alive(element) end

---@return MeshTables
function Mesh:tables() end

---@param position? point
---@return Vertex
function Mesh:new_vertex(position) end
---@return Halfedge
function Mesh:new_halfedge() end
---@return Edge
function Mesh:new_edge() end
---@return Face
function Mesh:new_face() end
---@return Boundary
function Mesh:new_boundary() end

---@param element Element
function Mesh:delete(element) end

---Runs fn and returns every change it made to this mesh.
---@param fn fun()
---@return EditRecord[]
function Mesh:record(fn) end

---@param e Edge
---@return Edge|nil e
---@return string? reason
function Mesh:flip(e) end

---@param e Edge
---@return Vertex|nil v the new vertex
---@return string? reason
function Mesh:split(e) end

---@param e Edge
---@return Vertex|nil v the surviving vertex
---@return string? reason
function Mesh:collapse(e) end

---@return true|nil ok
---@return string? reason
function Mesh:loop_subdivide() end

---Splits every face of more than three corners into triangles (ear clipping in the face's plane, keeping its
---orientation). The mesh is rebuilt from its faces: live vertices keep their order and positions but are numbered
---densely, and every face, edge and halfedge gets a new id. A mesh of triangles only is left as it is (0).
---@return integer|nil polygons_split the number of faces that became triangles
---@return string? reason
function Mesh:triangulate() end

---Catmull-Clark subdivision, one level: any polygons in, quads out (an undo point).
---@return true|nil ok
---@return string? reason
function Mesh:catmull_clark() end

---Linear subdivision, one level: triangles into 4 at their edges' midpoints, other faces into quads around their
---centroid; no vertex moves (an undo point).
---@return true|nil ok
---@return string? reason
function Mesh:linear_subdivide() end

---A scheme's phases, one call each, on this mesh: what the window's Subdivide menu steps through.
---"loop" (4 phases, the course's weights): compute positions, split every original edge, flip new edges joining an
---old and a new vertex, move every vertex. "catmull-clark" (3): compute face, edge and vertex points, split every
---face into quads (nothing moves yet), move every vertex. "linear" (2): compute midpoints and centres, split every
---face. Phase 1 only computes; each later phase is an undo point.
---@param scheme "loop"|"catmull-clark"|"linear"
---@return SubdivisionPhases
function Mesh:subdivision_phases(scheme) end

---@class SubdivisionPhases
---@field scheme string "loop", "catmull-clark" or "linear"
---@field phase_count integer 4, 3 or 2
---@field next_phase integer the phase step() runs next, 1 to phase_count
---@field next_label string "Catmull-Clark 2/3: split every face into quads (nothing moves yet)"
local SubdivisionPhases = {}

---Runs the next phase. Refused (nothing changes) when phase 1 is refused as the one-call method would be, or when
---the mesh changed since the last phase (restart() starts again).
---@return integer|nil phase the phase that ran
---@return string label_or_reason its label, or why nothing ran
function SubdivisionPhases:step() end

---What phase 1 computed, by the ids of the mesh it read (nil before phase 1 and after the last phase):
---Loop `vertices` and `edges`; Catmull-Clark `vertices`, `edges` and `faces`; linear `edges`, and `faces` for the
---faces of more than three sides (their centres).
---@return {vertices: table<integer, Vec3>?, edges: table<integer, Vec3>?, faces: table<integer, Vec3>?}|nil
function SubdivisionPhases:points() end

---Back to phase 1; the computed points are dropped.
function SubdivisionPhases:restart() end

---@return Snapshot
function Mesh:snapshot() end

---The mesh becomes the snapshot again, ids included (an undo point). Only into the mesh it was taken of.
---@param snapshot Snapshot
function Mesh:restore(snapshot) end

---Changes from `before` (a snapshot or a mesh) to this mesh.
---@param before Snapshot|Mesh
---@return FieldChange[]
function Mesh:diff(before) end

---@return string|nil what what was undone ("flip e3")
function Mesh:undo() end

---@return string|nil what what was redone
function Mesh:redo() end

---A Bézier curve (immutable). #c is the number of control points; tostring "curve (4 points)".
---@class Curve
---@field points vec3[] a fresh list on each read
local Curve = {}

---@param t number
---@return vec3
function Curve:evaluate(t) end

---Every de Casteljau level at t: levels[k + 1] is level k (Lua lists start at 1), so levels[1] is level 0,
---the control points, and the last entry is the single curve point.
---@param t number
---@return vec3[][]
function Curve:levels(t) end

---One de Casteljau step of any list of points (n -> n - 1).
---@param points point[]
---@param t number
---@return vec3[]
function Curve:step(points, t) end

---@param t number
---@return Curve left
---@return Curve right
function Curve:split(t) end

---@class PatchEvaluation
---@field rows vec3[] the 4 rows evaluated at u
---@field column_levels vec3[][] the column's levels at v, {{4}, {3}, {2}, {1}} points: [k + 1] is level k, [1] = rows
---@field point vec3

---A bicubic Bézier patch (immutable); tostring "patch".
---@class Patch
---@field points vec3[] 16 control points, row-major (points[row * 4 + col + 1])
local Patch = {}

---@param u number
---@param v number
---@return vec3
function Patch:evaluate(u, v) end

---@param u number
---@return vec3[] rows 4 points
function Patch:rows(u) end

---@param u number
---@param v number
---@return PatchEvaluation
function Patch:evaluation(u, v) end

---@class meshedit
meshedit = {}

---Loads a mesh file (.dae, .obj, .ply, .gltf...). Not available to student code under grading.
---With `{repair = true}` the file's polygons are repaired first (bow-tie vertices split, extra faces at an edge
---detached, repeated and degenerate faces dropped, faces re-oriented, unused vertices dropped) and the report is
---returned too; its numbers are the file's (0-based).
---@param path string
---@param options? {repair: boolean}
---@return Mesh
---@return RepairReport? report only with repair = true
function meshedit.load(path, options) end

---@return Mesh
function meshedit.cube() end
---@return Mesh
function meshedit.tetrahedron() end
---@return Mesh
function meshedit.icosahedron() end

---@param nx integer
---@param ny integer
---@return Mesh
function meshedit.grid(nx, ny) end

---positions[k] becomes v(k-1); polygons are lists of 1-based indices into positions, polygons[k] f(k-1).
---@param positions point[]
---@param polygons integer[][]
---@return Mesh
function meshedit.from_polygons(positions, polygons) end

---What a repair changed: one sentence per change, naming the input's vertex and face numbers (0-based: vertex k
---is positions[k+1], face k is polygons[k+1]; a new vertex by its id in the repaired mesh), and a one-line summary.
---@class RepairReport
---@field summary string "nothing to repair", or "repaired: 1 bow-tie vertex split, 2 faces reversed"
---@field changes string[] e.g. "vertex 0 was a bow-tie: split into 0 and new vertex 5 (face 1 moved)"

---Like from_polygons, but repairs the polygons first (see meshedit.load's repair option) instead of refusing them.
---The repaired polygons always make a mesh (a one-sided surface is cut along the edges whose faces cannot agree),
---so it raises an error only for arguments that are not positions and polygons.
---@param positions point[]
---@param polygons integer[][]
---@return Mesh
---@return RepairReport report
function meshedit.repair(positions, polygons) end

---Missing components are 0.
---@param x? number
---@param y? number
---@param z? number
---@return vec3
function meshedit.vec3(x, y, z) end

---@param points point[]
---@return Curve
function meshedit.curve(points) end

---@param points point[] 16 control points, row-major
---@return Patch
function meshedit.patch(points) end

---A .bzc file.
---@param path string
---@return Curve
function meshedit.load_curve(path) end

---A .bez file.
---@param path string
---@return Patch[]
function meshedit.load_patches(path) end

return meshedit
