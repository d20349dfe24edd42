-- Scripted answers for lessons/welcome.lua (meshedit lesson ... --headless --answers THIS): one list per step
-- that waits. Steps 1 and 5 do not wait.
return {
  [2] = { {key = "W"} },
  [3] = { {click = "v0"} },
  [4] = { {key = "N"} },
}
