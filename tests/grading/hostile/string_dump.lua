-- Hostile fixture (split.lua): turns functions into bytecode to read or patch them.
function split_edge(mesh, e)
  local code = string.dump(flip_edge)
  return load(code, "flip", "b")(mesh, e)
end
