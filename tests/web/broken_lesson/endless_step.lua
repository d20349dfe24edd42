-- A lesson whose first step never ends: opened in the window or the page, the step stops at the lesson's instruction
-- budget with its line, and the next step still runs. tests/web/lesson_endless_step.txt.
lesson { title = "Endless on purpose" }

step("Endless", function()
  say "spinning"
  while true do end
end)

step("After", function() say "still working" end)
