-- Hostile fixture (split.lua): makes coroutines without end, each suspended and kept alive.
function split_edge(mesh, e)
  local all = {}
  while true do
    local co = coroutine.create(function()
      while true do coroutine.yield() end
    end)
    coroutine.resume(co)
    all[#all + 1] = co
  end
end
