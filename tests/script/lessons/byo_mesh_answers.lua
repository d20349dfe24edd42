-- Scripted answers for lessons/byo_mesh.lua: the stand-in icosahedron stays on screen (the "My mesh is open"
-- button is pressed by itself) and L subdivides it.
return {
  ["Subdivide it"] = { {subdivide = true} },
}
