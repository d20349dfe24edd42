// Arguments of Lua-called C functions and errors at the script's line (see lua_args.h).
#include "script/lua_args.h"

#include <cstring>
#include <exception>

#include "core/compiler_builtins.h"
#include "script/exception_text.h"
#include "script/lua_handles.h"
#include "script/lua_runtime.h"

namespace meshedit {

std::string script_where(lua_State* L, int first_level) {
  lua_Debug ar;
  for (int level = first_level; lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar)) break;
    if (ar.currentline <= 0 || std::strcmp(ar.source, kApiPreludeSource) == 0) continue;
    return std::string(ar.short_src) + ":" + std::to_string(ar.currentline);
  }
  return "";
}

std::string caller_where(lua_State* L) { return script_where(L, 1); }

[[noreturn]] void raise(lua_State* L, const std::string& message) {
  try {
    const std::string where = caller_where(L);
    lua_pushstring(L, (where.empty() ? message : where + ": " + message).c_str());
  } catch (const std::exception&) {  // memory ran out placing the message: say so instead
    LuaRuntime::note_out_of_memory(L);
    lua_pushstring(L, kScriptMemoryRanOut);
  }
  lua_error(L);
  MESHEDIT_UNREACHABLE();  // lua_error never returns (it throws in this C++ build of Lua)
}

std::string type_name(lua_State* L, int index) { return luaL_typename(L, index); }

void check_fields(lua_State* L, int index, const char* call, std::initializer_list<const char*> allowed,
                  bool positional) {
  index = lua_absindex(L, index);
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    lua_pop(L, 1);
    bool ok = positional && lua_isinteger(L, -1) && lua_tointeger(L, -1) == 1;
    if (lua_type(L, -1) == LUA_TSTRING) {
      for (const char* name : allowed) ok = ok || std::strcmp(lua_tostring(L, -1), name) == 0;
    }
    if (!ok) {
      std::string list;
      for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      const std::string key = lua_type(L, -1) == LUA_TSTRING ? "'" + std::string(lua_tostring(L, -1)) + "'"
                                                             : "a " + type_name(L, -1) + " key";
      raise(L, std::string(call) + ": unknown field " + key + " (fields: " + (positional ? "[1], " : "") + list + ")");
    }
  }
}

std::optional<ElementRef> to_element(lua_State* L, int index) {
  if (lua_type(L, index) == LUA_TSTRING) return parse_element(lua_tostring(L, index));
  if (const Handle* handle = test_handle(L, index)) return handle->ref();
  return std::nullopt;
}

bool read_point(lua_State* L, int index, glm::dvec3& out) {
  if (!lua_istable(L, index)) return false;
  index = lua_absindex(L, index);
  lua_getfield(L, index, "x");
  const bool named = lua_type(L, -1) == LUA_TNUMBER;
  lua_pop(L, 1);
  double c[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    if (named) lua_getfield(L, index, i == 0 ? "x" : i == 1 ? "y" : "z");
    else lua_geti(L, index, i + 1);
    const int type = lua_type(L, -1);
    if (type == LUA_TNUMBER) c[i] = lua_tonumber(L, -1);
    lua_pop(L, 1);
    if (type != LUA_TNUMBER && (i < 2 || type != LUA_TNIL)) return false;
  }
  out = {c[0], c[1], c[2]};
  return true;
}

}  // namespace meshedit
