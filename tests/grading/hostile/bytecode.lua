-- Hostile fixture (split.lua): loads hand-made bytecode (crafted bytecode can corrupt the interpreter's memory).
local bytes = "\27Lua\84\0\25\147\13\10\26\10\4\8\8\120\86\0\0\0\0\0\0\0\0\0\0\0\40\119\64\1\128\129"
function split_edge(mesh, e)
  local chunk, why = load(bytes, "=evil", "b")
  if not chunk then error(why) end
  return chunk(mesh, e)
end
