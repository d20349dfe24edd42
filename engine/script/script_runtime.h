// The runtime MeshEdit runs scripts in: a LuaRuntime (the sandbox and its limits, lua_runtime.h) with the `meshedit`
// module opened (mesh_bindings.h). Whoever runs a student's, a lesson's, a suite's or the console's code builds one;
// a runtime for plain data (a lesson's answers file) is a LuaRuntime alone.
#pragma once

#include "script/lua_runtime.h"

namespace meshedit {

class ScriptRuntime final : public LuaRuntime {
 public:
  // Throws std::bad_alloc when the state or the module cannot be made (the state is closed again).
  explicit ScriptRuntime(LuaLimits limits = {});
};

}  // namespace meshedit
