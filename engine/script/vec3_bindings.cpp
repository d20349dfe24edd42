// vec3 for scripts: see vec3_bindings.h for the contract.
#include "script/vec3_bindings.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <lua.hpp>

#include "core/value_format.h"

namespace meshedit {
namespace {

constexpr const char* kVec3Metatable = "meshedit.vec3";
const char* const kComponents[] = {"x", "y", "z"};

// Reads component i by name, then by position (a plain {1, 2, 3} list). rawget: a table's own
// metamethods must not run here (a hostile __index could loop).
bool read_component(lua_State* L, int index, int i, double& out) {
  lua_pushstring(L, kComponents[i]);
  if (lua_rawget(L, index) == LUA_TNIL) {
    lua_pop(L, 1);
    lua_rawgeti(L, index, i + 1);
  }
  int is_number = 0;
  out = lua_tonumberx(L, -1, &is_number);
  const bool number = lua_type(L, -1) == LUA_TNUMBER && is_number;  // not a numeric string
  lua_pop(L, 1);
  return number;
}

glm::dvec3 operand(lua_State* L, int index, const char* op) {
  glm::dvec3 v;
  if (!to_vec3(L, index, v)) {
    luaL_error(L, "vec3 '%s': expected a vec3, got %s", op, luaL_typename(L, index));
  }
  return v;
}

int vec3_new(lua_State* L) {
  glm::dvec3 v(0.0);
  for (int i = 0; i < 3; ++i) v[i] = luaL_optnumber(L, i + 1, 0.0);
  push_vec3(L, v);
  return 1;
}

int vec3_add(lua_State* L) {
  push_vec3(L, operand(L, 1, "+") + operand(L, 2, "+"));
  return 1;
}

int vec3_sub(lua_State* L) {
  push_vec3(L, operand(L, 1, "-") - operand(L, 2, "-"));
  return 1;
}

int vec3_mul(lua_State* L) {
  // number * vec3 or vec3 * number; vec3 * vec3 is ambiguous (dot? componentwise?) so it is refused.
  const int number_at = lua_type(L, 1) == LUA_TNUMBER ? 1 : 2;
  const int vector_at = 3 - number_at;
  if (lua_type(L, number_at) != LUA_TNUMBER) {
    return luaL_error(L, "vec3 '*': multiply by a number (use a:dot(b) or a:cross(b) for two vectors)");
  }
  push_vec3(L, operand(L, vector_at, "*") * lua_tonumber(L, number_at));
  return 1;
}

int vec3_div(lua_State* L) {
  if (lua_type(L, 2) != LUA_TNUMBER) return luaL_error(L, "vec3 '/': divide by a number");
  push_vec3(L, operand(L, 1, "/") / lua_tonumber(L, 2));
  return 1;
}

int vec3_unm(lua_State* L) {
  push_vec3(L, -operand(L, 1, "-"));
  return 1;
}

int vec3_eq(lua_State* L) {
  glm::dvec3 a, b;
  lua_pushboolean(L, to_vec3(L, 1, a) && to_vec3(L, 2, b) && a == b);
  return 1;
}

int vec3_tostring(lua_State* L) {
  const glm::dvec3 v = operand(L, 1, "tostring");
  const std::string text = "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
  lua_pushlstring(L, text.data(), text.size());
  return 1;
}

int vec3_dot(lua_State* L) {
  lua_pushnumber(L, glm::dot(operand(L, 1, "dot"), operand(L, 2, "dot")));
  return 1;
}

int vec3_cross(lua_State* L) {
  push_vec3(L, glm::cross(operand(L, 1, "cross"), operand(L, 2, "cross")));
  return 1;
}

int vec3_length(lua_State* L) {
  lua_pushnumber(L, glm::length(operand(L, 1, "length")));
  return 1;
}

int vec3_normalized(lua_State* L) {
  const glm::dvec3 v = operand(L, 1, "normalized");
  const double length = glm::length(v);
  push_vec3(L, length > 0.0 ? v / length : v);
  return 1;
}

}  // namespace

void push_vec3(lua_State* L, const glm::dvec3& v) {
  lua_createtable(L, 0, 3);
  for (int i = 0; i < 3; ++i) {
    lua_pushnumber(L, v[i]);
    lua_setfield(L, -2, kComponents[i]);
  }
  luaL_setmetatable(L, kVec3Metatable);
}

bool to_vec3(lua_State* L, int index, glm::dvec3& out) {
  if (lua_type(L, index) != LUA_TTABLE) return false;
  index = lua_absindex(L, index);
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!read_component(L, index, i, v[i])) return false;
  }
  out = v;
  return true;
}

glm::dvec3 check_vec3(lua_State* L, int index, const char* what) {
  glm::dvec3 v;
  if (!to_vec3(L, index, v)) {
    luaL_error(L, "%s must be a vec3 or a table {x, y, z} of numbers, got %s", what, luaL_typename(L, index));
  }
  return v;
}

void open_vec3(lua_State* L) {
  static const luaL_Reg kMetamethods[] = {{"__add", vec3_add},           {"__sub", vec3_sub}, {"__mul", vec3_mul},
                                          {"__div", vec3_div},           {"__unm", vec3_unm}, {"__eq", vec3_eq},
                                          {"__tostring", vec3_tostring}, {nullptr, nullptr}};
  static const luaL_Reg kMethods[] = {{"dot", vec3_dot},
                                      {"cross", vec3_cross},
                                      {"length", vec3_length},
                                      {"normalized", vec3_normalized},
                                      {nullptr, nullptr}};
  if (luaL_newmetatable(L, kVec3Metatable)) {
    luaL_setfuncs(L, kMetamethods, 0);
    luaL_newlib(L, kMethods);
    lua_setfield(L, -2, "__index");
    lua_pushliteral(L, "vec3");
    lua_setfield(L, -2, "__name");
    lua_pushliteral(L, "vec3");
    lua_setfield(L, -2, "__metatable");  // getmetatable(v) gives a string: scripts cannot change the methods
  }
  lua_pop(L, 1);
  lua_pushcfunction(L, vec3_new);
  lua_setfield(L, -2, "vec3");
}

}  // namespace meshedit
