-- Scripted answers for lessons/byo_mesh.lua: every question is answered wrong once (the feedback must name that
-- mistake), then right; L on the quad cube is refused, and L subdivides the triangulated cube the lesson leaves on screen.
return {
  ["Which way is up"] = {
    { choose = "Z up", feedback = "3D printing" }, { choose = "Y up" },
    { choose = "Rotate it 90 degrees in Blender and export again", feedback = "every position" },
    { choose = "View > Up axis > Z up" },
  },
  ["A bow-tie vertex"] = { { answer = 5, feedback = "the file's count" }, { answer = 6 } },
  ["A fin and a flipped face"] = {
    { choose = "face 1", feedback = "proper pair" }, { choose = "face 2" },
    { choose = "face 0", feedback = "lowest face" }, { choose = "face 1" },
  },
  ["The Repairs tab"] = {
    { choose = "Edit > Triangulate", feedback = "never got there" }, { choose = "File > Open a repaired copy" },
    { click = "v0", feedback = "That is a vertex" }, { click = "f5", feedback = "faced the right way" },
    { click = "f6" },
  },
  ["Open a scan with defects"] = { { answer = 26, feedback = "same triangle twice" }, { answer = 25 },
    { open_repaired = "../assets/scan_with_defects.ply" } },
  ["Triangulate the quads"] = { { key = "L" }, { answer = 6, feedback = "number of quads" }, { answer = 24, feedback = "n - 2" },
    { answer = 12 }, { triangulate = true } },
  ["Subdivide it"] = { { subdivide = true }, { answer = 48, feedback = "Loop's count" }, { answer = 36 } },
}
