// Element handles as Lua values: their metatables and the state's HandleContext, making them, recognising them
// (test_handle, check_*), printing and comparing them. Fields are read and written in handle_fields.cpp, methods
// live in handle_methods.cpp.
//
//   tostring(x) -> "h37"; x == y (same element of the same mesh, whichever box or read made them)
// Invariants (with binding_support.h's):
// - A handle is a userdata of sizeof(Handle) bytes with one user value, the MeshBox userdata its `box` points
//   to, and one of the five handle metatables; nothing else has those metatables (they are protected by
//   __metatable), so test_handle's metatable check is what makes the bytes a Handle.
// - Handles have no __gc: making one is one allocation, and the collector frees it like a table.
// - Every handle is made by new_handle, so the touch recorders (touch_recorder.h) hear of each one.
#include <new>
#include <string>

#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"
#include "script/internal/handle_context.h"
#include "script/mesh_bindings.h"
#include "script/touch_recorder.h"

namespace meshedit {
namespace {

// Key of the handle kind in each handle metatable (its address is the key).
const char kHandleKindKey = 0;

int handle_tostring(lua_State* L) {
  const Handle* h = context_handle(L, handle_context(L), 1);
  lua_pushstring(L, h ? h->name().c_str() : "?");
  return 1;
}

int handle_eq(lua_State* L) {
  const HandleContext& c = handle_context(L);
  const Handle* a = context_handle(L, c, 1);
  const Handle* b = context_handle(L, c, 2);
  lua_pushboolean(L, a && b && a->box->mesh == b->box->mesh && a->kind == b->kind && a->index == b->index);
  return 1;
}

// Pushes a new handle of the valid `ref` on `box`, without its user value yet, and tells the touch recorders.
void new_handle(lua_State* L, MeshBox* box, ElementRef ref) {
  new (lua_newuserdatauv(L, sizeof(Handle), 1)) Handle{box, ref.index, ref.kind};
  if (box->state && !box->state->touch_recorders.empty()) note_touch(*box->state, box->mesh.get(), ref);
}

// Sets the metatable of the new handle on top: the value at `metatable`, or ref.kind's by name when 0.
void set_metatable(lua_State* L, ElementKind kind, int metatable) {
  if (metatable) lua_pushvalue(L, metatable);
  else push_handle_metatable(L, kind);
  lua_setmetatable(L, -2);
}

}  // namespace

void open_handle_metatables(lua_State* L) {
  auto* context = static_cast<HandleContext*>(lua_newuserdatauv(L, sizeof(HandleContext), 1));
  new (context) HandleContext{&binding_state(L), {}, 0, {}};
  const int context_index = lua_gettop(L);
  const lua_CFunction meta[] = {guarded<handle_tostring>, handle_eq};
  const char* meta_names[] = {"__tostring", "__eq"};
  for (ElementKind kind : kAllKinds) {
    luaL_newmetatable(L, kind_name(kind));  // also sets __name, which Lua's "bad argument" messages show
    context->metatables[static_cast<int>(kind)] = lua_topointer(L, -1);
    for (int i = 0; i < 2; ++i) {
      lua_pushvalue(L, context_index);
      lua_pushcclosure(L, meta[i], 1);
      lua_setfield(L, -2, meta_names[i]);
    }
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
    lua_pushinteger(L, static_cast<lua_Integer>(kind));
    lua_rawsetp(L, -2, &kHandleKindKey);
  }
  // The metatables are on the stack in kAllKinds order; __index and __newindex are set on each.
  set_handle_accessors(L, context_index, context_index + 1);
  lua_pop(L, 1 + kElementKindCount);  // the context and the metatables
}

void push_handle_metatable(lua_State* L, ElementKind kind) { luaL_getmetatable(L, kind_name(kind)); }

void push_handle_at(lua_State* L, int box, ElementRef ref, int metatable) {
  if (!ref.valid()) {
    lua_pushnil(L);
    return;
  }
  box = lua_absindex(L, box);
  metatable = metatable ? lua_absindex(L, metatable) : 0;
  new_handle(L, static_cast<MeshBox*>(lua_touserdata(L, box)), ref);
  lua_pushvalue(L, box);
  lua_setiuservalue(L, -2, 1);
  set_metatable(L, ref.kind, metatable);
}

void push_sibling_handle(lua_State* L, const Handle& h, int handle, ElementRef ref, int metatable) {
  if (!ref.valid()) {
    lua_pushnil(L);
    return;
  }
  handle = lua_absindex(L, handle);
  metatable = metatable ? lua_absindex(L, metatable) : 0;
  new_handle(L, h.box, ref);
  lua_getiuservalue(L, handle, 1);
  lua_setiuservalue(L, -2, 1);
  set_metatable(L, ref.kind, metatable);
}

void push_handle(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, ElementRef ref) {
  if (!ref.valid()) {
    lua_pushnil(L);
    return;
  }
  push_mesh(L, mesh);
  push_handle_at(L, -1, ref);
  lua_remove(L, -2);
}

Handle* test_handle(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TUSERDATA || !lua_getmetatable(L, index)) return nullptr;
  const bool is_handle = lua_rawgetp(L, -1, &kHandleKindKey) == LUA_TNUMBER;
  lua_pop(L, 2);
  return is_handle ? static_cast<Handle*>(lua_touserdata(L, index)) : nullptr;
}

Handle& check_handle(lua_State* L, int arg, ElementKind wanted) {
  Handle* h = test_handle(L, arg);
  if (!h || !accepts(wanted, h->kind)) luaL_typeerror(L, arg, kind_name(wanted));
  return *h;
}

Handle& check_any_handle(lua_State* L, int arg) {
  Handle* h = test_handle(L, arg);
  if (!h) luaL_typeerror(L, arg, "element");
  return *h;
}

void check_alive(lua_State* L, const Handle& h) {
  if (!h.m().alive(h.ref())) luaL_error(L, "attempt to use dead %s %s", kind_name(h.kind), h.name().c_str());
}

void check_same_mesh(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value) {
  if (value.box->mesh != mesh) luaL_error(L, "%s belongs to another mesh", value.name().c_str());
}

void check_storable(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value) {
  check_same_mesh(L, mesh, value);
  check_alive(L, value);
}

}  // namespace meshedit
