// HandleContext (internal to engine/script): what the C functions of element handles in one Lua state share,
// reached as their upvalue 1 (no registry lookup on the way): the state's BindingState, the addresses of the
// five handle metatables, and the interned key strings __index and __newindex compare keys with.
//
// Invariants:
// - One context per state, made by open_handle_metatables; it lives as long as any handle function (they all
//   hold it as an upvalue), and the metatables and key strings it points to are kept alive beside it (the
//   metatables in the registry, the strings in the context's user value), so its addresses never dangle.
// - A value is a handle exactly when it is a userdata whose metatable is one of the five: nothing else gets those
//   metatables (they are protected by __metatable), so context_handle's pointer compares make the bytes a Handle.
// - __index and __newindex are reachable only as metamethods of the handle metatables (scripts cannot read those,
//   and there is no debug library), so the VM calls them with a handle as argument 1 and they skip
//   context_handle for it. Every other argument, and `self` of every method (which a script can call with
//   anything), goes through context_handle.
#pragma once

#include <lua.hpp>

#include "script/internal/binding_support.h"

namespace meshedit {

struct BindingState;

inline constexpr int kMaxHandleKeys = 32;

struct HandleContext {
  BindingState* state;
  const void* metatables[kElementKindCount];  // by ElementKind
  int key_count;
  const char* keys[kMaxHandleKeys];  // interned text (see handle_fields.cpp for which)
};

// The context of the running handle function (its upvalue 1).
inline const HandleContext& handle_context(lua_State* L) {
  return *static_cast<const HandleContext*>(lua_touserdata(L, lua_upvalueindex(1)));
}

// The handle at `index`, or nullptr for anything else.
inline Handle* context_handle(lua_State* L, const HandleContext& c, int index) {
  if (lua_type(L, index) != LUA_TUSERDATA || !lua_getmetatable(L, index)) return nullptr;
  const void* metatable = lua_topointer(L, -1);
  lua_settop(L, -2);
  for (const void* known : c.metatables) {
    if (metatable == known) return static_cast<Handle*>(lua_touserdata(L, index));
  }
  return nullptr;
}

// Sets __index and __newindex on the handle metatables at stack indices first .. first + kElementKindCount - 1
// (kAllKinds order), with the context at `context` (handle_fields.cpp; it fills the context's keys).
void set_handle_accessors(lua_State* L, int context, int first);

}  // namespace meshedit
