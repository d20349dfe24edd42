// Meshes and element handles as Lua values, for the modules that read them off a Lua stack or push them (exercises,
// lessons, the grader): the userdata layouts, the argument checks with Lua's usual messages, and `guarded`. The
// rest of the `meshedit` module's internals are engine/script's own (internal/binding_support.h).
//
// Invariants:
// - A MeshBox holds a shared_ptr to its HalfedgeMesh that never changes after the box is made (restore and undo
//   replace the mesh's contents, never the pointer), and the BindingState of its own Lua state, which outlives every
//   handle made on the box.
// - A Handle is plain data: the MeshBox it points to is the userdata stored as the handle's user value 1, so the box
//   (and with it the mesh) lives at least as long as the handle. A handle whose element is dead or past the end is
//   refused by check_alive ("attempt to use dead halfedge h37"), never read out of range.
// - No C++ exception crosses into Lua: every lua_CFunction registered by a module is wrapped in guarded<>.
#pragma once

#include <cstdint>
#include <exception>
#include <iterator>
#include <memory>
#include <string>

#include <lua.hpp>

#include "core/halfedge_mesh.h"
#include "core/ids.h"
#include "script/exception_text.h"

namespace meshedit {

inline constexpr const char* kMeshType = "mesh";

struct BindingState;

struct MeshBox {
  const std::shared_ptr<HalfedgeMesh> mesh;
  BindingState* const state;  // the BindingState of the Lua state the box lives in (nullptr if it has none)
};

struct Handle {
  MeshBox* box;    // the box in the handle's user value 1 (which keeps it alive)
  uint32_t index;  // the slot (no boundary bit)
  ElementKind kind;

  const std::shared_ptr<HalfedgeMesh>& mesh() const { return box->mesh; }
  HalfedgeMesh& m() const { return *box->mesh; }
  ElementRef ref() const { return ElementRef(kind, index); }
  std::string name() const { return format_id(ref()); }
};

// Every kind in ElementKind order: a handle metatable's place among them is its kind's value (handle_fields.cpp).
inline constexpr ElementKind kAllKinds[] = {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge,
                                            ElementKind::Face, ElementKind::Boundary};
static_assert(std::size(kAllKinds) == kElementKindCount);
static_assert([] {
  for (int k = 0; k < kElementKindCount; ++k) {
    if (kAllKinds[k] != static_cast<ElementKind>(k)) return false;
  }
  return true;
}());

// Runs a binding with C++ exceptions turned into Lua errors. The message is copied out of the handler so the
// Lua error (itself a C++ throw in this build of Lua, not a std::exception) starts after the C++ one is done. Memory
// running out is noted in the runtime (LuaRuntime::note_out_of_memory), so its error is known for what it is.
template <lua_CFunction F>
int guarded(lua_State* L) {
  std::string message;
  try {
    return F(L);
  } catch (const std::exception& e) {
    message = lua_error_text(L, e);  // std::bad_alloc: "memory ran out"
  }
  return luaL_error(L, "%s", message.c_str());
}

// ---- handles (handle_bindings.cpp) ----------------------------------------------------------------------
// Pushes a handle for `ref` of `mesh` (making a MeshBox for it: for a few handles, not for loops), or nil when ref is
// invalid.
void push_handle(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, ElementRef ref);
// The handle at `index`, or nullptr for anything else.
Handle* test_handle(lua_State* L, int index);

// True if a slot of kind `wanted` takes an element of kind `got` (a face slot takes boundary loops too).
inline bool accepts(ElementKind wanted, ElementKind got) {
  return wanted == got || (wanted == ElementKind::Face && got == ElementKind::Boundary);
}
// Argument `arg` must be a handle of kind `wanted`: "bad argument #1 to 'flip' (edge expected, got vertex)".
Handle& check_handle(lua_State* L, int arg, ElementKind wanted);
// Argument `arg` must be a handle of any kind: "bad argument #1 to 'delete' (element expected, got nil)".
Handle& check_any_handle(lua_State* L, int arg);
// "attempt to use dead halfedge h37" unless the handle's element is alive.
void check_alive(lua_State* L, const Handle& h);
// Argument `arg` must be a mesh: "bad argument #1 to 'flip' (mesh expected, got nil)".
MeshBox& check_mesh(lua_State* L, int arg);

}  // namespace meshedit
