-- Hostile fixture (split.lua): an endless loop that catches every error, so a limit raised as an error
-- cannot stop it.
function split_edge(mesh, e)
  while true do
    pcall(function()
      while true do end
    end)
  end
end
