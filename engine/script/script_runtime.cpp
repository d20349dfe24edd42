// A LuaRuntime with the meshedit module (see script_runtime.h).
#include "script/script_runtime.h"

#include "script/mesh_bindings.h"

namespace meshedit {

// A throw here leaves the base fully made, so its destructor closes the state.
ScriptRuntime::ScriptRuntime(LuaLimits limits) : LuaRuntime(limits) { open_mesh_bindings(state()); }

}  // namespace meshedit
