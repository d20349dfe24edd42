-- Scripted answers for lessons/1_de_casteljau.lua (meshedit lesson ... --headless --answers THIS). The quiz gets
-- a wrong key first (it must not move the step on), then the right one. Steps 1 and 6 do not wait; step 5's
-- Continue button is pressed by the headless driver.
return {
  [2] = { {key = "E"} },
  [3] = { {key = "4"}, {key = "3"} },
  [4] = { {key = "C"} },
}
