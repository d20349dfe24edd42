// Copying Lua values from one state to another: how arguments reach the student's state and results come
// back to the suite's. The two states share nothing else.
//
// Invariants:
// - Reading the source never runs code of the source: tables are read raw (lua_next), metatables are
//   ignored except the vec3 one, and no __tostring, __index or __pairs is ever called. So a value a student
//   returns cannot run the student's code in the suite's state.
// - What crosses: nil, booleans, numbers (integers stay integers), strings, tables of those (keys: strings,
//   numbers, booleans), vec3 tables (they keep their vec3 metatable), meshes and element handles (the same
//   C++ mesh, shared), curves and patches (as userdata, or as plain tables {points = {...}} when the
//   destination is a student, so no reference evaluation reaches student code). Anything else (functions,
//   coroutines, other userdata) is refused with a message naming where it was ("result[2].f: cannot pass a
//   function"); so are values nested deeper than max_depth or holding more than max_items values.
// - Pushing on the destination may raise a Lua error there (out of memory): call copy() only where that
//   state is in protected mode. Errors of the copy itself are BridgeError (a C++ exception).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

struct lua_State;

namespace meshedit {

class BridgeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct BridgeOptions {
  bool bezier_as_tables = false;  // curves and patches become {points = {...}}
  int max_depth = 32;
  size_t max_items = size_t(1) << 20;
  size_t max_string_bytes = size_t(16) << 20;
};

class ValueBridge {
 public:
  ValueBridge(lua_State* from, lua_State* to, BridgeOptions options = {});
  // Pushes a copy of from[index] on `to`; `what` names it in errors ("argument 2", "result 1").
  void copy(int index, const std::string& what);

 private:
  void copy_value(int index, int depth, const std::string& path);
  void copy_table(int index, int depth, const std::string& path);
  void push_points_table(const void* points_begin, size_t count);

  lua_State* from_;
  lua_State* to_;
  BridgeOptions options_;
  size_t items_ = 0;
  const void* from_vec3_metatable_ = nullptr;
};

}  // namespace meshedit
