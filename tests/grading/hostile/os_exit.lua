-- Hostile fixture (split.lua): ends the process "successfully" before the grader can record a failure.
function split_edge(mesh, e)
  os.exit(0, true)
end
