-- Bring your own mesh: export a glTF from Blender, open it in MeshEdit, read what the validator says, and
-- subdivide it. The lesson inspects whatever mesh is on screen (a stand-in icosahedron until the student
-- opens a file), so it works the same in the window and headless.
-- CI runs it headless:
--   meshedit lesson lessons/byo_mesh.lua --headless --answers tests/script/lessons/byo_mesh_answers.lua
-- Invariant: the lesson never assumes what the student opened; every number it says is read from
-- current_mesh() at the time.

lesson {
  title = "Bring your own mesh",
  summary = "Export a model from Blender as glTF, open it, understand what the validator says, and subdivide it.",
}

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

-- The mesh on screen, or the stand-in shown when there is none.
local function mesh_on_screen()
  local mesh = current_mesh()
  if mesh then return mesh end
  show(meshedit.icosahedron())
  return current_mesh()
end

-- The largest number of sides of any face (3 for a triangle mesh).
local function most_sides(mesh)
  local most = 0
  for f in mesh:faces() do most = math.max(most, f:degree()) end
  return most
end

-- The error message a bad polygon list gets from the mesh builder (the same check a file goes through).
local function refusal(positions, polygons)
  local ok, message = pcall(meshedit.from_polygons, positions, polygons)
  if ok then return "accepted" end
  return tostring(message)
end

step("Export from Blender", function()
  show(meshedit.icosahedron())
  camera "fit"
  say [[
# Bring your own mesh

Everything you wrote works on any triangle mesh, not just the course files. This lesson takes a model from
**Blender** into MeshEdit. MeshEdit reads **glTF** (.gltf and .glb) as well as .obj, .dae, .ply, .stl and .off.]]
  say [[
In Blender, with your object selected:

- **Triangulate**: in Edit Mode select everything (A), then Face > Triangulate Faces (Ctrl+T). Loop
  subdivision, flip and split need triangles.
- **Weld**: Mesh > Clean Up > Merge by Distance, so no two vertices sit at the same place.
- **Apply transforms**: in Object Mode, Object > Apply > All Transforms (Ctrl+A), so the mesh's own coordinates
  are what you see.]]
  say [[
Then File > Export > glTF 2.0, and in the export options:

- Format **glTF Binary (.glb)**; Include: **Selected Objects**
- Data > Mesh: untick **UVs** and **Normals**. glTF stores one vertex per distinct set of attributes, so UV seams
  and sharp edges would split vertices apart, and MeshEdit (like glTF) does not weld them back: each seam would
  open into a boundary.
- Transform: keep **+Y Up**, glTF's convention and the default: MeshEdit shows a glTF with +Y up (the status
  bar says which axis is up). Exported with +Z up, Blender's own, it lies on its side: View > Up axis > **Z up**
  stands it up. Only the view changes, never the mesh.]]
end)

step("Open it", function()
  local mesh = mesh_on_screen()
  say [[
Open the file with **Ctrl+O**, or drag and drop it onto the window. A file MeshEdit cannot read is refused with
one line naming the file and the place, and the mesh you had stays on screen.]]
  say [[
No file at hand? Keep the icosahedron on screen: it stands in for yours. Press the button when your mesh is open.]]
  wait_for { button = "My mesh is open", hint = "Ctrl+O or drag a .glb onto the window" }
  mesh = mesh_on_screen()
  local ok, report = mesh:validate()
  local chi = mesh:num_vertices() - mesh:num_edges() + mesh:num_faces()
  say("Your mesh has " .. counts(mesh) .. " and " .. mesh:num_boundaries() .. " boundary loop(s). Its Euler "
    .. "characteristic V - E + F is " .. chi .. (chi == 2 and mesh:num_boundaries() == 0
      and ": a closed surface like a sphere." or ".") .. " The validator says: "
    .. (ok and "valid." or report.summary))
  if most_sides(mesh) > 3 then
    say("Some faces have " .. most_sides(mesh) .. " sides: triangulate in Blender (Ctrl+T) and export again before "
      .. "subdividing.")
  else
    say "Every face is a triangle: ready for flips, splits and subdivision."
  end
  if mesh:num_boundaries() > 0 then
    say [[
The boundary loops are drawn in blue. If you did not expect any, a UV seam or a sharp edge split the vertices
in the export: untick UVs and Normals, or merge by distance, and export again.]]
  end
end)

step("When the file is refused", function()
  say [[
MeshEdit only accepts **manifold, consistently oriented** surfaces: every edge has at most two faces, the two
faces of an edge run along it in opposite directions, and the faces around each vertex form a single fan. A
half-edge mesh cannot store anything else, so such a file is refused with the faces and the vertex or edge
that break the rule. Three examples, built here from lists of triangles:]]
  local fin = refusal({ {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1} },
    { {1, 2, 3}, {2, 1, 4}, {1, 2, 5} })
  say("Three triangles on one edge (a \"fin\"): " .. fin)
  local flipped = refusal({ {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0} }, { {1, 2, 3}, {1, 2, 4} })
  say("Two triangles facing opposite ways: " .. flipped)
  local bowtie = refusal({ {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0} }, { {1, 2, 3}, {1, 4, 5} })
  say("Two triangles touching at one vertex (a bow-tie): " .. bowtie)
  say [[
A file goes through the same checks; its message names the file and its own face and vertex numbers.
In Blender, Select > Select All by Trait > **Non Manifold** (in Edit Mode) selects the culprits; Mesh >
Normals > **Recalculate Outside** (Shift+N) fixes inconsistent orientation. Fix, export, open again.]]
end)

step("Subdivide it", function()
  local mesh = mesh_on_screen()
  if most_sides(mesh) > 3 then
    say("Loop subdivision needs triangles, and this mesh has faces with " .. most_sides(mesh) .. " sides. "
      .. "Triangulate it (Edit > Triangulate), then come back to this step (Back, Next).")
    return
  end
  say("Press **L** to subdivide your mesh (" .. counts(mesh) .. "). Each step makes every triangle four, so on a "
    .. "big mesh stop after one or two.")
  local after = wait_for {
    hint = "Press L",
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == 4 * mesh:num_faces() and m:validate() and m
    end,
  }
  say("Subdivided: " .. counts(after) .. ", that is V + E vertices and 4F faces, and still valid. Boundary loops: "
    .. after:num_boundaries() .. " (the same as before: subdivision never opens or closes a hole).")
  say [[
Save the result with File > **Save as...** as .obj, .gltf, .glb, .ply or .stl, and open it back in Blender. Then try
your own flips and splits on it, and your own `upsample` from the exercises.]]
end)
