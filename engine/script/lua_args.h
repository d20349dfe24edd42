// Reading the arguments of a C function called from Lua, with errors that name the script's own line: what every
// module that defines Lua functions (the lesson globals, exercise{}, the suites) shares.
//
// Invariants:
// - raise() never returns and never throws a C++ exception: it is a Lua error whose message starts with the script's
//   line, the innermost frame with a line that is not an API prelude (chunks named kApiPreludeName).
// - The readers only read: they raise for a bad argument and change nothing.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>

#include <glm/vec3.hpp>
#include <lua.hpp>

#include "core/ids.h"

namespace meshedit {

// The chunk name of Lua code an API runs on the script's behalf (a prelude): script_where skips its frames.
inline constexpr const char* kApiPreludeName = "(meshedit api)";
inline constexpr const char* kApiPreludeSource = "@(meshedit api)";

// "welcome.lua:12" of the innermost frame of thread L at or above `first_level` that the script's author wrote
// (C functions and API preludes skipped); "" when there is none.
std::string script_where(lua_State* L, int first_level);
// Where the script called the running C function: "lesson.lua:12", or "".
std::string caller_where(lua_State* L);
// A Lua error "lesson.lua:12: message" (the caller's line); never returns.
[[noreturn]] void raise(lua_State* L, const std::string& message);

// "nil", "number", "table"...: Lua's name of the type of the value at `index`.
std::string type_name(lua_State* L, int index);
// Checks that the table at `index` has only the listed string keys (and, with `positional`, the integer key 1);
// raises "CALL: unknown field 'x' (fields: a, b)" otherwise.
void check_fields(lua_State* L, int index, const char* call, std::initializer_list<const char*> allowed,
                  bool positional = false);

// An element handle (of any mesh) or an id string ("e7"), else nullopt. Never raises.
std::optional<ElementRef> to_element(lua_State* L, int index);
// A point: a table with numeric x, y (z optional) or a list {x, y[, z]}; false for anything else. Never raises.
bool read_point(lua_State* L, int index, glm::dvec3& out);

}  // namespace meshedit
