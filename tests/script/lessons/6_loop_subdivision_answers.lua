-- Scripted answers for lessons/6_loop_subdivision.lua: the four Loop phases on the cube, each as the window's
-- Shift+L (the phase, then the key the lesson waits for); the six diagonal splits then L twice; L on the grid.
-- The phase steps and the explanations wait for nothing.
return {
  ["Your turn: Shift+L"] = {
    {loop_phase = true}, {key = "shift+L"},  -- 1: compute the new positions
    {loop_phase = true}, {key = "shift+L"},  -- 2: split every original edge
    {loop_phase = true}, {key = "shift+L"},  -- 3: flip
    {loop_phase = true}, {key = "shift+L"},  -- 4: move
  },
  ["The pre-split fix"] = { {split = "e2"}, {split = "e7"}, {split = "e11"}, {split = "e14"}, {split = "e16"},
    {split = "e17"}, {subdivide = true}, {subdivide = true} },
  ["A mesh with a boundary"] = { {subdivide = true} },
}
