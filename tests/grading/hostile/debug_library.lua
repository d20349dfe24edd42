-- Hostile fixture (split.lua): removes the instruction hook and reads the registry.
function split_edge(mesh, e)
  debug.sethook()
  local registry = debug.getregistry()
  return registry
end
