-- Hostile fixture (split.lua): loads modules (os, a native library) to get back what the sandbox removed.
function split_edge(mesh, e)
  local real_os = require("os")
  package.loadlib("/lib/x86_64-linux-gnu/libc.so.6", "system")("touch /tmp/meshedit_pwned")
  real_os.execute("true")
  return mesh:vertex(0)
end
