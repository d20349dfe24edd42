-- Scripted answers for lessons/6_loop_subdivision.lua: L on the cube; the six diagonal splits then L twice;
-- L on the grid. The phase steps and the explanations wait for nothing.
return {
  ["Your turn: L"] = { {subdivide = true} },
  ["The pre-split fix"] = { {split = "e2"}, {split = "e7"}, {split = "e11"}, {split = "e14"}, {split = "e16"},
    {split = "e17"}, {subdivide = true}, {subdivide = true} },
  ["A mesh with a boundary"] = { {subdivide = true} },
}
