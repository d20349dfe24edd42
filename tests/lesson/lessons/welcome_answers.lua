-- Scripted answers for lessons/welcome.lua (meshedit lesson ... --headless --answers THIS): one list per step
-- that waits. Step 1 does not wait.
return {
  [2] = { {key = "W"} },
  [3] = { {click = "v0"} },
  [4] = { {key = "N"} },
  [5] = { {selection = "e11"}, {flip = "e11"}, {key = "F"} },
}
