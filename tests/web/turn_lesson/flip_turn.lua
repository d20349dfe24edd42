-- A lesson of one your_turn on the student's flip_edge, for tests/web/lesson_your_turn_runaway.txt: the page runs the
-- student's code of a your_turn in its worker for student code, and the step waits for the verdict.
lesson { title = "Flip turn" }

step("Yours", function()
  your_turn { exercise = "flip", mesh = meshedit.grid(1, 1), element = "e2" }
  say("flipped")
end)
