// ValueBridge: raw, bounded copies of Lua values between two states (see value_bridge.h).
#include "grade/value_bridge.h"

#include <vector>

#include <glm/vec3.hpp>
#include <lua.hpp>

#include "script/bezier_bindings.h"
#include "script/lua_handles.h"
#include "script/mesh_bindings.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

// The registry name vec3_bindings.cpp gives the vec3 metatable (tests/grade checks a vec3 keeps it).
constexpr const char* kVec3Metatable = "meshedit.vec3";

// The vec3 metatable of L, or nullptr. The name is already interned in L, so this allocates nothing.
const void* vec3_metatable(lua_State* L) {
  luaL_getmetatable(L, kVec3Metatable);
  const void* p = lua_istable(L, -1) ? lua_topointer(L, -1) : nullptr;
  lua_pop(L, 1);
  return p;
}

std::string key_path(lua_State* L, int key_index, const std::string& path) {
  // A deep (or cyclic) value would make paths as long as its depth: keep them readable.
  if (path.size() > 80) return path.back() == '.' ? path : path.substr(0, 60) + "....";
  switch (lua_type(L, key_index)) {
    case LUA_TSTRING: return path + "." + lua_tostring(L, key_index);
    case LUA_TNUMBER:
      if (lua_isinteger(L, key_index)) return path + "[" + std::to_string(lua_tointeger(L, key_index)) + "]";
      return path + "[" + std::to_string(lua_tonumber(L, key_index)) + "]";
    case LUA_TBOOLEAN: return path + (lua_toboolean(L, key_index) ? "[true]" : "[false]");
    default: return path + "[?]";
  }
}

}  // namespace

ValueBridge::ValueBridge(lua_State* from, lua_State* to, BridgeOptions options)
    : from_(from), to_(to), options_(options), from_vec3_metatable_(vec3_metatable(from)) {}

void ValueBridge::copy(int index, const std::string& what) { copy_value(lua_absindex(from_, index), 0, what); }

void ValueBridge::push_points_table(const void* points_begin, size_t count) {
  const auto* points = static_cast<const glm::dvec3*>(points_begin);
  lua_createtable(to_, 0, 1);
  lua_createtable(to_, static_cast<int>(count), 0);
  for (size_t i = 0; i < count; ++i) {
    push_vec3(to_, points[i]);
    lua_rawseti(to_, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(to_, -2, "points");
}

void ValueBridge::copy_value(int index, int depth, const std::string& path) {
  if (++items_ > options_.max_items) {
    throw BridgeError(path + ": too large to pass (more than " + std::to_string(options_.max_items) + " values)");
  }
  luaL_checkstack(to_, 4, "copying a value");
  switch (lua_type(from_, index)) {
    case LUA_TNIL: lua_pushnil(to_); return;
    case LUA_TBOOLEAN: lua_pushboolean(to_, lua_toboolean(from_, index)); return;
    case LUA_TNUMBER:
      if (lua_isinteger(from_, index)) lua_pushinteger(to_, lua_tointeger(from_, index));
      else lua_pushnumber(to_, lua_tonumber(from_, index));
      return;
    case LUA_TSTRING: {
      size_t len = 0;
      const char* s = lua_tolstring(from_, index, &len);
      if (len > options_.max_string_bytes) {
        throw BridgeError(path + ": string too long to pass (" + std::to_string(len) + " bytes)");
      }
      lua_pushlstring(to_, s, len);
      return;
    }
    case LUA_TTABLE: copy_table(index, depth, path); return;
    case LUA_TUSERDATA: {
      if (auto mesh = to_mesh(from_, index)) {
        push_mesh(to_, std::move(mesh));
        return;
      }
      if (const Handle* h = test_handle(from_, index)) {
        push_handle(to_, h->mesh(), h->ref());
        return;
      }
      if (const auto* points = to_curve(from_, index)) {
        if (options_.bezier_as_tables) push_points_table(points->data(), points->size());
        else push_curve(to_, *points);
        return;
      }
      if (const BezierPatch* patch = to_patch(from_, index)) {
        if (options_.bezier_as_tables) push_points_table(patch->points.data(), patch->points.size());
        else push_patch(to_, *patch);
        return;
      }
      throw BridgeError(path + ": cannot pass this userdata value");
    }
    default: throw BridgeError(path + ": cannot pass a " + std::string(lua_typename(from_, lua_type(from_, index))));
  }
}

void ValueBridge::copy_table(int index, int depth, const std::string& path) {
  if (depth >= options_.max_depth) {
    throw BridgeError(path + ": nested more than " + std::to_string(options_.max_depth) + " tables deep (a cycle?)");
  }
  if (!lua_checkstack(from_, 4)) throw BridgeError(path + ": no stack space to read it");
  bool is_vec3 = false;
  if (lua_getmetatable(from_, index)) {
    is_vec3 = from_vec3_metatable_ && lua_topointer(from_, -1) == from_vec3_metatable_;
    lua_pop(from_, 1);
  }
  lua_newtable(to_);
  const int target = lua_gettop(to_);
  lua_pushnil(from_);
  while (lua_next(from_, index) != 0) {
    const int key = lua_gettop(from_) - 1;
    const int key_type = lua_type(from_, key);
    if (key_type != LUA_TSTRING && key_type != LUA_TNUMBER && key_type != LUA_TBOOLEAN) {
      lua_pop(from_, 2);
      throw BridgeError(path + ": a table key is a " + std::string(lua_typename(from_, key_type)) +
                        " (only strings, numbers and booleans can be passed)");
    }
    const std::string child = key_path(from_, key, path);
    copy_value(key, depth + 1, child);      // the key
    copy_value(key + 1, depth + 1, child);  // the value
    lua_rawset(to_, target);
    lua_pop(from_, 1);
  }
  if (is_vec3) luaL_setmetatable(to_, kVec3Metatable);
}

}  // namespace meshedit
