-- Hostile fixture (split.lua): raises error objects whose __tostring fails or never returns, hoping the
-- grader hangs or crashes while printing the error.
function split_edge(mesh, e)
  pcall(error, setmetatable({}, {__tostring = function() error("no message for you") end}))
  error(setmetatable({}, {__tostring = function()
    while true do end
  end}))
end
