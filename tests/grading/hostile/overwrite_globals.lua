-- Hostile fixture (split.lua): replaces the grader's globals (expect, test, suite, student) with versions
-- that pass everything, then returns without splitting.
local yes = function() return true end
expect = setmetatable({}, {__index = function() return yes end, __call = yes})
test = yes
suite = yes
student = nil
validate = yes
meshedit.cube = function() return nil end
function split_edge(mesh, e)
  expect.valid(mesh)
  expect.mesh_equal(mesh, mesh)
  return mesh:vertex(0)
end
