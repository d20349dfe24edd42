-- A lesson that does not compile (line 7): opened in the window or the page, the status line and the lesson panel
-- name the file and the line, as for any Lua error. tests/web/lesson_syntax_error.txt.
lesson { title = "Broken on purpose" }

step("First", function()
  say "never shown"
  if then
end)
