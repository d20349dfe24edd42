-- Scripted answers for lessons/byo_mesh.lua: every question is answered wrong once (the feedback must name that
-- mistake), then right; L on Suzanne (assets/suzanne.obj, quads and triangles) is refused, and L subdivides her once
-- triangulated.
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
  ["Triangulate the quads"] = { { key = "L" }, { answer = 500, feedback = "Each quad is cut in two" },
    { answer = 1904, feedback = "n - 2" }, { answer = 1000, feedback = "stay as they are" }, { answer = 968 },
    { triangulate = true } },
  ["Subdivide it"] = { { subdivide = true }, { answer = 3872, feedback = "Loop's count" }, { answer = 2904 } },
}
