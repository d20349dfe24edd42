-- Bring your own mesh: what MeshEdit does with a real user's file. Which axis a scan (.ply) or a Blender export
-- (.glb, .gltf, .obj) is shown with up, and View > Up axis; what happens to a file that is not an oriented
-- manifold (the refusal, File > Open a repaired copy, the Repairs tab, `meshedit repair` and `meshedit info`);
-- triangulating quads so Loop accepts them; and the Subdivide menu. Every step asks the student to predict or act
-- before it tells, and each likely wrong answer is named in its feedback.
-- Every number and report line comes from the core: the broken meshes are built here from lists of polygons and
-- handed to meshedit.from_polygons (the refusal) and meshedit.repair (engine/core/mesh_repair.h), the quads to
-- mesh:triangulate(), mesh:loop_subdivide() and mesh:catmull_clark() on copies.
-- CI runs it headless (tests/lesson/lessons_b_test.cpp):
--   meshedit lesson lessons/byo_mesh.lua --headless --answers tests/lesson/lessons/byo_mesh_answers.lua
-- Invariants: the lesson never assumes what file the student opened; it inspects only the meshes it builds and
-- what current_mesh() returns. Every step shows what it talks about itself (Back runs a step again).

lesson {
  title = "Bring your own mesh",
  summary = "Open a scan or a Blender export the right way up, repair a file that is not a manifold, triangulate "
    .. "quads and subdivide them.",
}

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

-- The message the mesh builder refuses polygons with (a file goes through the same check), without the note on
-- numbering that every refusal ends with.
local function refusal(positions, polygons)
  local ok, message = pcall(meshedit.from_polygons, positions, polygons)
  assert(not ok, "these polygons were meant to be refused")
  return (tostring(message):gsub(" %(face k is polygons.*$", ""))
end

-- The number in the first change that matches `pattern` (a Lua pattern with one capture), e.g. "face (%d+) reversed".
local function number_in(report, pattern)
  for _, change in ipairs(report.changes) do
    local n = change:match(pattern)
    if n then return tonumber(n) end
  end
  error("no change of the report matches " .. pattern)
end

-- A repair report as the Repairs tab lists it: the summary, then one line per change.
local function report_text(report)
  local lines = { "**" .. report.summary .. "**" }
  for _, change in ipairs(report.changes) do lines[#lines + 1] = "- " .. change end
  return table.concat(lines, "\n")
end

-- Three broken pieces, as lists of positions and 1-based polygons (what a file holds).
-- A bow-tie: two triangles that share only vertex 0.
local BOWTIE = {
  positions = { { 0, 0, 0 }, { 1, 0.5, 0 }, { 1, -0.5, 0 }, { -1, -0.5, 0 }, { -1, 0.5, 0 } },
  polygons = { { 1, 2, 3 }, { 1, 4, 5 } },
}
-- A fin: three triangles on the edge from vertex 0 to vertex 1.
local FIN = {
  positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0 }, { 0.5, 0, 1 } },
  polygons = { { 1, 2, 3 }, { 2, 1, 4 }, { 1, 2, 5 } },
}
-- A flipped face: two triangles on the edge from vertex 0 to vertex 1 that both run from 0 to 1.
local FLIPPED = {
  positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0 } },
  polygons = { { 1, 2, 3 }, { 1, 2, 4 } },
}

-- The three pieces side by side in one list, as one file that has all three problems.
local function all_three()
  local positions, polygons = {}, {}
  for piece_index, piece in ipairs({ BOWTIE, FIN, FLIPPED }) do
    local base = #positions
    for _, p in ipairs(piece.positions) do
      positions[#positions + 1] = { p[1] + 3 * (piece_index - 1), p[2], p[3] }
    end
    for _, polygon in ipairs(piece.polygons) do
      local shifted = {}
      for k, corner in ipairs(polygon) do shifted[k] = corner + base end
      polygons[#polygons + 1] = shifted
    end
  end
  return positions, polygons
end

-- The cube's six sides as counter-clockwise quads (1-based corners of meshedit.cube()), like a Blender export
-- that was not triangulated.
local CUBE_QUADS = { { 1, 3, 4, 2 }, { 5, 6, 8, 7 }, { 1, 2, 6, 5 }, { 3, 7, 8, 4 }, { 1, 5, 7, 3 }, { 2, 4, 8, 6 } }
local function quad_cube()
  local corners = meshedit.cube()
  local positions = {}
  for i = 0, 7 do positions[i + 1] = corners:vertex(i).position end
  return meshedit.from_polygons(positions, CUBE_QUADS)
end

step("Which way is up", function()
  show(quad_cube())
  camera "fit"
  view { labels = false }
  say [[
# Bring your own mesh

Everything you wrote works on any mesh, not only the course files. MeshEdit opens **.obj**, **glTF** (.gltf,
.glb), **.ply**, .stl, .off and .dae with **Ctrl+O** or by dropping the file on the window. Positions are never
rotated: only the view chooses which axis points up, by the file's format.]]
  choose {
    "A laser scan saved as .ply (the Stanford bunny, say) has no up axis in the file. Which does MeshEdit show up?",
    options = { "Y up", "Z up" }, answer = "Y up",
    feedback = {
      ["Y up"] = "The Stanford scans stand on Y, and MeshLab keeps a scan's axes, so a .ply opens Y-up.",
      ["Z up"] = "Z up is for .stl and .off: 3D printing and CAD put the build plate in the XY plane. Scans differ.",
    },
    hint = "Think of where the scans come from, not of Blender.",
  }
  choose {
    "Blender's glTF export keeps +Y Up by default, glTF's own rule. You ticked it off, so the file is Z-up, and "
      .. "MeshEdit shows it lying on its side. What do you change?",
    options = { "View > Up axis > Z up", "Rotate it 90 degrees in Blender and export again", "Nothing: Ctrl+O again" },
    answer = "View > Up axis > Z up",
    feedback = {
      ["View > Up axis > Z up"] = "Only the view turns; the file's coordinates stay as they are.",
      ["Rotate it 90 degrees in Blender and export again"] = "That changes every position in the file to fix what "
        .. "is only a question of the view.",
      ["Nothing: Ctrl+O again"] = "Opening it again reads the same file the same way: a .glb is shown Y-up.",
    },
  }
  say [[
The **status bar** says which axis is up. Y is up for .obj (Blender's default export), glTF and .ply; Z for .stl
and .off; a COLLADA file says so itself. **View > Up axis** overrides it for the file on screen.]]
end)

step("A bow-tie vertex", function()
  local fixed, report = meshedit.repair(BOWTIE.positions, BOWTIE.polygons)
  show(fixed)
  camera { fit = true, pitch = 55 }  -- flat pieces: seen from above
  view { labels = false }
  label(fixed:vertex(0), "vertex 0")
  label(fixed:face(0), "face 0")
  label(fixed:face(1), "face 1")
  say [[
A half-edge mesh can only hold an **oriented manifold**: at most two faces per edge, running along it in opposite
directions, and the faces around each vertex a single fan. On screen: two triangles from a file that share only
**vertex 0**, with nothing else between them, a bow-tie. MeshEdit refuses such a file, naming the faces and the
vertex. File > **Open a repaired copy** opens it repaired instead.]]
  answer {
    "The file has " .. #BOWTIE.positions .. " vertices. How many does the repaired mesh have?",
    number = fixed:num_vertices(),
    feedback = function(value)
      if value == #BOWTIE.positions then
        return "That is the file's count. A vertex can be the corner of one fan only: one triangle needs a vertex "
          .. "of its own there."
      end
      if value < #BOWTIE.positions then return "The repair never merges or drops a vertex a face uses." end
      return "The repair adds one vertex per fan beyond the first, and here there are two fans."
    end,
  }
  say("Refused as it is: " .. refusal(BOWTIE.positions, BOWTIE.polygons) .. ".")
  say("Repaired (meshedit.repair): " .. counts(fixed) .. ".\n\n" .. report_text(report))
  local moved = number_in(report, "%(face (%d+) moved%)")
  highlight(fixed:face(moved), "orange")
  say("The orange face, f" .. moved .. ", is the one moved to the new vertex, at the same place as vertex 0.")
end)

step("A fin and a flipped face", function()
  local fin_fixed, fin_report = meshedit.repair(FIN.positions, FIN.polygons)
  local detached = number_in(fin_report, "face (%d+) detached")
  show(fin_fixed)
  camera { fit = true, pitch = 30 }
  view { labels = false }
  for f = 0, 2 do label(fin_fixed:face(f), "face " .. f) end
  label(fin_fixed:vertex(0), "0")
  label(fin_fixed:vertex(1), "1")
  say [[
Three triangles on the edge from vertex 0 to vertex 1, a **fin**: face 0 runs 0 to 1, face 1 runs 1 to 0 and
face 2 runs 0 to 1 again. An edge keeps only two faces, one each way; the repair gives each other face corners of
its own there (it *detaches* it).]]
  choose {
    "Which face does the repair detach?",
    options = { "face 0", "face 1", "face 2" }, answer = "face " .. detached,
    feedback = {
      ["face " .. detached] = "Yes: the repair keeps the edge for the first face and the first later face that runs "
        .. "the other way.",
      ["face 0"] = "Face 0 is the first face on the edge: it keeps it.",
      ["face 1"] = "Face 1 runs 1 to 0, against face 0: the two are a proper pair, and it keeps the edge.",
    },
  }
  say("Refused: " .. refusal(FIN.positions, FIN.polygons) .. ".")
  say("Repaired: " .. counts(fin_fixed) .. ".\n\n" .. report_text(fin_report))
  highlight(fin_fixed:face(detached), "orange")

  local flip_fixed, flip_report = meshedit.repair(FLIPPED.positions, FLIPPED.polygons)
  local reversed = number_in(flip_report, "face (%d+) reversed")
  clear()
  show(flip_fixed)
  camera { fit = true, pitch = 55 }
  for f = 0, 1 do label(flip_fixed:face(f), "face " .. f) end
  label(flip_fixed:vertex(0), "0")
  label(flip_fixed:vertex(1), "1")
  say [[
Now two triangles on one edge that **both** run from vertex 0 to vertex 1: one of them faces the wrong way, and
the repair turns it.]]
  choose {
    "Which face does the repair reverse?",
    options = { "face 0", "face 1", "neither: it is refused" }, answer = "face " .. reversed,
    feedback = {
      ["face " .. reversed] = "Yes: the repair turns faces to agree with the lowest face of their piece, unless more "
        .. "of them already face the other way.",
      ["face 0"] = "Face 0 is the lowest face of the piece, and the two are one each: the others follow face 0.",
      ["neither: it is refused"] = "from_polygons refuses it; meshedit.repair and Open a repaired copy fix it.",
    },
  }
  highlight(flip_fixed:face(reversed), "orange")
  say("Refused: " .. refusal(FLIPPED.positions, FLIPPED.polygons) .. ".")
  say("Repaired: " .. counts(flip_fixed) .. ".\n\n" .. report_text(flip_report))
end)

step("The Repairs tab", function()
  local positions, polygons = all_three()
  local fixed, report = meshedit.repair(positions, polygons)
  local reversed = number_in(report, "face (%d+) reversed")
  show(fixed)
  camera { fit = true, pitch = 55 }
  view { labels = false }
  for f = 0, fixed:num_faces() - 1 do label(fixed:face(f), "f" .. f) end
  choose {
    "Ctrl+O refuses your file, naming faces and a vertex. How do you see it anyway?",
    options = { "File > Open a repaired copy", "Edit > Triangulate", "View > Up axis" },
    answer = "File > Open a repaired copy",
    feedback = {
      ["Edit > Triangulate"] = "Triangulate works on the mesh on screen, and a refused file never got there.",
      ["View > Up axis"] = "The up axis only turns the view; it cannot make a mesh of a file that is refused.",
    },
  }
  say([[
The three pieces side by side, as one file with all three problems, opened repaired. The **Repairs** tab lists
every change with the file's own vertex and face numbers; clicking a row selects and highlights its spot. Here is
the list the repair gives, for a mesh of ]] .. counts(fixed) .. ".\n\n" .. report_text(report))
  pick {
    "Click the face the row \"... reversed ...\" names, as a click on that row would select it.",
    answer = function(e)
      if e.kind ~= "face" then return false, "That is a " .. e.kind .. ": click inside a triangle." end
      return e.id == reversed
    end,
    feedback = function(e)
      if e.kind == "face" then return "f" .. e.id .. " faced the right way already. Nothing was dropped, so a face "
        .. "keeps the file's number." end
    end,
  }
  highlight(fixed:face(reversed), "orange")
  say [[
Outside the window: `meshedit info FILE` lists what a repair would change, and `meshedit repair IN -o OUT` writes
the repaired copy. In Lua, `meshedit.repair(positions, polygons)` returns the mesh and this report.]]
end)

-- A scan patch shipped with the app (assets/scan_with_defects.ply, see assets/README.md): a flipped face, a repeated
-- face and a loose triangle touching the patch at one corner, as scans have.
local SCAN = "../assets/scan_with_defects.ply"

step("Open a scan with defects", function()
  local scan, report = meshedit.load(lesson_file(SCAN), { repair = true })
  say([[
Now a real file. The app ships a small scanned patch in MeshEdit's folder, **assets/scan_with_defects.ply**. Open
it with **File > Open** (Ctrl+O): it is refused, and the status bar names the problem. Then **File > Open a
repaired copy**.]])
  answer {
    "Before you open it: the file has " .. (scan:num_faces() + 1) .. " faces, and one of them repeats another. "
      .. "How many faces will the repaired copy have?",
    number = scan:num_faces(),
    feedback = function(value)
      if value == scan:num_faces() + 1 then return "The repeated face is dropped: it is the same triangle twice." end
      if value < scan:num_faces() then return "Only the repeated face goes; a flipped face is turned, not dropped." end
    end,
    hint = "Which of a repeat, a flipped face and a bow-tie corner removes a face?",
  }
  wait_for {
    hint = "File > Open assets/scan_with_defects.ply, then File > Open a repaired copy",
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == scan:num_faces() and m:num_vertices() == scan:num_vertices()
    end,
  }
  camera "fit"
  say("The repaired copy: " .. counts(scan) .. ". The Repairs tab lists what was done, in the file's numbers:\n\n"
    .. report_text(report) .. "\n\nClick its rows: each one selects its spot on the patch.")
end)

-- Suzanne, Blender's test character, as Blender 3.4 exports her to .obj with its default settings (assets/README.md):
-- quads and triangles, and a hole at each eye.
local SUZANNE = "../assets/suzanne.obj"

-- How many faces of `mesh` have `sides` sides.
local function faces_with(mesh, sides)
  local n = 0
  for f in mesh:faces() do if f:degree() == sides then n = n + 1 end end
  return n
end

step("Triangulate the quads", function()
  local suzanne = meshedit.load(lesson_file(SUZANNE))
  show(suzanne, { up = "y" }) -- her .obj is Y-up, as opening it in the window shows her
  camera "fit"
  view { labels = false, halfedges = false }
  local quads, triangles_before = faces_with(suzanne, 4), faces_with(suzanne, 3)
  say("A Blender export keeps Blender's quads unless you triangulate. On screen: **Suzanne**, Blender's test "
    .. "character, exported to .obj as Blender does by default (assets/suzanne.obj): " .. counts(suzanne) .. ", "
    .. quads .. " of the faces quads and " .. triangles_before .. " triangles. Press **L** to try Loop "
    .. "subdivision on her.")
  wait_for { key = "L", hint = "Press L" }
  local loop_ok, why = suzanne:copy():loop_subdivide()
  assert(not loop_ok, "Loop subdivision was meant to refuse quads")
  say("Loop subdivision refuses her, and the status bar says why: " .. why .. ".")
  local triangles = suzanne:copy()
  local split = triangles:triangulate()
  answer {
    "How many faces will she have after Edit > Triangulate?",
    number = triangles:num_faces(),
    feedback = function(value)
      if value == suzanne:num_faces() then return "That is the number of faces now. Each quad is cut in two." end
      if value == 4 * quads + triangles_before then
        return "Four per quad is a cut through the centre; triangulation adds no vertex, so a quad makes n - 2 = 2."
      end
      if value == 2 * suzanne:num_faces() then return "The " .. triangles_before .. " triangles stay as they are." end
    end,
    hint = "A face of n corners becomes n - 2 triangles.",
  }
  say "Now do it: **Edit > Triangulate** on the mesh on screen."
  local yours = wait_for {
    hint = "Edit > Triangulate",
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == triangles:num_faces() and m:validate() and m
    end,
  }
  say("Triangulate split " .. split .. " faces: " .. counts(suzanne) .. " before, " .. counts(yours)
    .. " after. No vertex was added or moved. In Lua it is mesh:triangulate(); on the shell, "
    .. "`meshedit triangulate IN -o OUT`.")
end)

step("Subdivide it", function()
  local mesh = current_mesh()
  if not mesh then
    local triangles = meshedit.load(lesson_file(SUZANNE))
    triangles:triangulate()
    show(triangles, { up = "y" })
    mesh = current_mesh()
  end
  local ok_loop, why = mesh:copy():loop_subdivide()
  if not ok_loop then
    say("The mesh on screen cannot be Loop-subdivided: " .. why .. ". Go Back to triangulate it.")
    return
  end
  say("Press **L** to subdivide the mesh on screen (" .. counts(mesh) .. ").")
  local after = wait_for {
    hint = "Press L",
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == 4 * mesh:num_faces() and m:validate() and m
    end,
  }
  camera "fit"
  say("Loop: " .. counts(after) .. ".")
  local cc = mesh:copy()
  assert(cc:catmull_clark())
  answer {
    "The Subdivide menu also has Catmull-Clark. How many faces would it make of the " .. mesh:num_faces()
      .. " triangles you had before L?",
    number = cc:num_faces(),
    feedback = function(value)
      if value == after:num_faces() then
        return "That is Loop's count, four per triangle. Catmull-Clark makes one quad per corner of each face."
      end
    end,
  }
  local linear = mesh:copy()
  assert(linear:linear_subdivide())
  say("Catmull-Clark: " .. counts(cc) .. ", all quads. The menu's **Linear** cuts the same way as Loop ("
    .. counts(linear) .. ") but moves no vertex. Save any of them with File > Save as... and open it in Blender.")
end)
