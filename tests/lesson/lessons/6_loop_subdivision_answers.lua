-- Scripted answers for lessons/6_loop_subdivision.lua: each question answered wrong once (or more), with the words
-- its feedback must contain, then right; the four Loop phases on the cube, each as the window's Shift+L (the phase,
-- then the key the lesson waits for); a flip that makes the corners' degrees worse, then the six diagonal splits
-- that make them all 6; the six diagonal splits then L twice; edits near a sharp corner, checked; L on the grid.
-- On the cube after phase 2: e0 and e18 are halves of split original edges (e0 the half m-b, e18 the half a-m of
-- e0's split), e22 a new edge between two new vertices, e19 a new edge from an old corner to a new vertex.
return {
  ["Four phases"] = { {answer = 8, feedback = "every edge split adds one"},
    {answer = 32, feedback = "vertices are not"}, {answer = 26} },
  ["Phase 1: new positions"] = { {answer = "3/16", feedback = "n = 3 only"}, {answer = "1/6", feedback = "n u = 1"},
    {answer = "1/16"} },
  ["Phase 2: split every edge"] = {
    {choose = "Every edge, new ones too", feedback = "never end"},
    {choose = "The 18 original edges"} },
  ["Phase 3: which edges flip"] = { {click = "e0", feedback = "half of a split original edge"},
    {click = "e18", feedback = "not a new edge"}, {click = "e22", feedback = "Both ends"},
    {click = "v0", feedback = "click an edge"}, {click = "e19"} },
  ["Phase 4: move"] = { {choose = "It is only faster", feedback = "not about speed"},
    {choose = "The neighbours have changed"} },
  ["The app's phases: Shift+L"] = {
    {loop_phase = true}, {key = "shift+L"},  -- 1: compute the new positions
    {loop_phase = true}, {key = "shift+L"},  -- 2: split every original edge
    {loop_phase = true}, {key = "shift+L"},  -- 3: flip
    {loop_phase = true}, {key = "shift+L"},  -- 4: move
  },
  ["The cube's lopsided result"] = {
    {choose = "Rounding error", feedback = "rounding in double precision"},
    {choose = "Splitting in id order", feedback = "Phase 1"},
    {choose = "Corners at different distances", feedback = "They are not"},
    {choose = "Corners differ in degree"},
    {choose = "The degree-4 corners", feedback = "They stay farther out"},
    {choose = "All at the same distance", feedback = "They are not"},
    {choose = "The degree-6 corners"} },
  -- e2 joins v0 and v3: flipping it takes v3 to degree 3 and leaves v7 at 6, worse than before; then each of the
  -- six diagonals split (e2 as flipped too) gives every corner degree 6.
  ["Make every corner alike"] = { {flip = "e2"}, {split = "e2"}, {split = "e7"}, {split = "e11"}, {split = "e14"},
    {split = "e16"}, {split = "e17"} },
  ["The pre-split fix"] = { {split = "e2"}, {split = "e7"}, {split = "e11"}, {split = "e14"}, {split = "e16"},
    {split = "e17"}, {subdivide = true}, {subdivide = true} },
  -- v7's edges are e6, e8, e15 (along the cube's edges) and e7, e14, e17 (diagonals). Check on the plain cube,
  -- after the three cube edges split, then after all six.
  ["Sharp corners"] = { {button = "Check"}, {split = "e6"}, {split = "e8"}, {split = "e15"}, {button = "Check"},
    {split = "e7"}, {split = "e14"}, {split = "e17"}, {button = "Check"},
    {choose = "Its degree went up", feedback = "weigh 3/8"},
    {choose = "Its neighbours are nearer to it"} },
  ["A mesh with a boundary"] = { {answer = {0, 0}, feedback = "moves too"}, {answer = {0.25, 0.25}, feedback = "1/8"},
    {answer = "0.125, 0.125"}, {subdivide = true} },
  ["Your own upsample"] = { {choose = "One old end and one new end", feedback = "halves"},
    {choose = "Ids past the original count", feedback = "new id"},
    {choose = "Flags set while splitting"}, {your_turn = "right"}, {your_turn = "right"} },
}
