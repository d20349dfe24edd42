-- Scripted answers for lessons/2_bezier_patches.lua: the quiz gets a wrong count (4) before the right one (5).
-- Step 3's Continue button is pressed by the headless driver; the other steps do not wait.
return {
  [2] = { {key = "4"}, {key = "5"} },
}
