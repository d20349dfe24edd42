-- The welcome lesson: what MeshEdit is for, how to look around, how to pick elements, and the keys every
-- later lesson uses (the student flips an edge with one of them). CI runs it headless with scripted answers:
--   meshedit lesson lessons/welcome.lua --headless --answers tests/lesson/lessons/welcome_answers.lua

lesson {
  title = "Welcome to MeshEdit",
  summary = "What this app is for, how to look around and pick elements, and the keys you will use in every part.",
}

local cube = meshedit.cube()

step("What MeshEdit is", function()
  show(cube)
  camera "fit"
  say [[
# Welcome

MeshEdit is a workbench for **geometric modelling**: the curves and surfaces that modelling programs,
games and films are built from. You will build each piece yourself, and see every step it takes.]]
  say [[
The lessons follow the parts of the assignment:

- **Bézier curves**, evaluated by de Casteljau's algorithm, one level at a time
- **Bézier patches**, the surfaces the Utah teapot is made of
- **half-edge meshes**: walking around faces and vertices, and vertex normals
- **edge flip** and **edge split**, the two local operations
- **Loop subdivision**, which turns a coarse mesh into a smooth one
- and, beyond the assignment, **Catmull-Clark** subdivision and **bringing your own mesh**]]
  say [[
On screen is a cube made of 12 triangles, stored as a half-edge mesh. Press **Next** when you are ready.]]
end)

step("Look around", function()
  say [[
Drag with the mouse to **orbit** around the cube. Hold Shift (or the middle button) and drag to **pan**;
turn the wheel to **zoom**. **Space** brings the view back.]]
  say [[
Two keys change how the mesh is drawn:

- **W** switches the wireframe on and off: the edges drawn over the faces
- **Q** switches between flat shading (one normal per face) and smooth (Phong) shading

Press **W** now.]]
  wait_for { key = "W", hint = "Press W to switch the wireframe" }
  say [[
Well done. Keep the wireframe on: from now on you will want to see every edge.]]
end)

step("Pick a vertex", function()
  say [[
A mesh is made of **vertices** (points), **edges** (segments between two vertices) and **faces** (the
polygons the edges enclose). Every element has an id: `v3` is vertex 3, `e7` edge 7, `f2` face 2.]]
  say [[
**Click** on a corner of the cube to select a vertex. If the dots are hidden, turn them on in the
**View** menu. Press **I** to open the inspector: it lists everything about the selection.]]
  local v = wait_for { click = "vertex" }
  highlight(v, "yellow")
  label(v, "you are here")
  if type(v) == "string" then
    say("You picked **" .. v .. "**.")
  else
    say("You picked **" .. tostring(v) .. "**. " .. v:degree() .. " edges meet there: that number is the vertex's "
      .. "**degree**. The inspector shows it too.")
  end
end)

step("Walk the halfedges", function()
  say [[
Inside the mesh, every edge is two **halfedges**, one for each face beside it, pointing opposite ways.
A halfedge knows five things: `next` (the following halfedge around its face), `twin` (its partner
across the edge), `vertex` (where it starts), `edge` and `face`. Everything else is found by walking.]]
  say [[
With something selected, press **N** to go to the *next* halfedge. (From a vertex, N first takes the
vertex's own halfedge, then its next.)]]
  wait_for { key = "N", hint = "Press N to walk to the next halfedge" }
  say [[
Press **N** two more times: the cube's faces are triangles, so three presses bring you back to the halfedge
you started from (from a vertex: its own halfedge). Then press **T** to jump to the *twin*, into the
neighbouring face. **V**, **E** and **H** take you to the vertex, the edge and back to a halfedge. This walking
is exactly what your code will do.]]
end)

-- The two vertices edge `id` of `mesh` joins, as "v1 and v2".
local function ends_of(mesh, id)
  local h = mesh:edge(id).halfedge
  return tostring(h.vertex) .. " and " .. tostring(h.twin.vertex)
end

step("Keys for the parts ahead", function()
  show(cube)
  local diagonal = 11  -- e11 cuts the front square (y = -0.5, facing the start view) into two triangles
  highlight(cube:edge(diagonal), "orange")
  label(cube:edge(diagonal), "e11")
  say("Some keys change the mesh. Try one: the orange edge e11, the diagonal of the front square, joins "
    .. ends_of(cube, diagonal) .. ". **Click** it to select it, then press **F** and watch which corners it joins "
    .. "afterwards.")
  wait_for { selection = "e11", hint = "Click the orange edge e11" }
  wait_for { key = "F", hint = "Press F to flip e11" }
  local flipped = current_mesh()
  if flipped and ends_of(flipped, diagonal) ~= ends_of(cube, diagonal) then
    say("e11 now joins " .. ends_of(flipped, diagonal) .. ": it turned inside its two triangles to join their other "
      .. "two corners, the square's other diagonal. That was an **edge flip**, part 4 of the assignment.")
  end
  say [[
Every change can be undone with **Ctrl+Z** (and redone with **Ctrl+Y**). The keys that change the mesh:

- **F** flips the selected edge: it turns to join the other two corners of its two triangles
- **S** splits the selected edge: a new vertex in its middle, joined to the opposite corners
- **L** runs one step of Loop subdivision; **Shift+L** runs it one phase at a time
- **C** collapses the selected edge into a single vertex]]
  say [[
The pointer tables in the right column (the **Pointers** tab) show every `next`, `twin`, `vertex`, `edge` and
`face`: after an edit, the cells that changed are highlighted. Press **F1** any time for the list of keys.]]
  say [[
That is all you need. Open the lesson list to start with **de Casteljau's algorithm**.]]
end)
