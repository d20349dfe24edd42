-- Hostile fixture (split.lua): reads the suite (hidden tests, expected answers) from disk.
function split_edge(mesh, e)
  local found
  for _, path in ipairs({"hostile_suite.lua", "tests/grading/hostile/hostile_suite.lua", "/autograder/source/suite.lua"}) do
    found = found or (loadfile and loadfile(path)) or (dofile and dofile(path))
  end
  local suite_mesh = meshedit.load((SUITE_DIR or ".") .. "/hostile_suite.lua")
  return found or suite_mesh
end
