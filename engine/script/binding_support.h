// What the files of the `meshedit` module share (internal to engine/script): the userdata layouts of meshes
// and element handles, the argument checks with Lua's usual messages, and `guarded`.
//
// Invariants:
// - A MeshBox holds a shared_ptr to its HalfedgeMesh that never changes after the box is made (restore and
//   undo replace the mesh's contents, never the pointer), and the BindingState of its own Lua state, which
//   outlives every handle made on the box (the state's BindingState is made first and finalized last), so making
//   a handle tells the state's touch recorders without a registry lookup.
// - A Handle is plain data (no destructor, no __gc): the MeshBox it points to is the userdata stored as the
//   handle's user value 1, so the box (and with it the mesh) lives at least as long as the handle, and
//   `box` never dangles while the handle can be reached. A handle whose element is dead or past the end is
//   refused by check_alive ("attempt to use dead halfedge h37"), never read out of range.
// - Two handles are the same element when their meshes (not their boxes) and refs are equal: one mesh may
//   have several boxes (push_mesh makes a new one each time).
// - A handle's metatable carries its kind under a private key, so test_handle is one lookup and a table or
//   another library's userdata is never mistaken for a handle.
// - No C++ exception crosses into Lua: every lua_CFunction registered by the module is wrapped in guarded<>.
#pragma once

#include <cstddef>
#include <exception>
#include <iterator>
#include <memory>
#include <string>

#include <lua.hpp>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"
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

// ---- handles (handle_bindings.cpp; fields: handle_fields.h; methods: handle_methods.h) ---------------------
// Registers the five handle metatables (call once per state, before any handle is pushed).
void open_handle_metatables(lua_State* L);
// Pushes a handle for `ref` of the mesh whose MeshBox userdata is at stack index `box`, or nil when ref is
// invalid (a null pointer). `metatable`: the stack index of ref.kind's handle metatable, or 0 to look it up.
void push_handle_at(lua_State* L, int box, ElementRef ref, int metatable = 0);
// A handle for `ref` on the mesh of `h`, the handle at stack index `handle` (anchored to h's box).
void push_sibling_handle(lua_State* L, const Handle& h, int handle, ElementRef ref, int metatable = 0);
// The same for a mesh with no box at hand: makes a MeshBox for it first (slower; not for loops).
void push_handle(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, ElementRef ref);
// Pushes the handle metatable of `kind`.
void push_handle_metatable(lua_State* L, ElementKind kind);
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
// "h1 belongs to another mesh" unless `value` is an element of `mesh`.
void check_same_mesh(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value);
// A value to store in a pointer: a live handle of `mesh`; kind and nil are the caller's business.
void check_storable(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value);

// ---- meshes (mesh_bindings.cpp) -------------------------------------------------------------------------
MeshBox& check_mesh(lua_State* L, int arg);
// Pushes `nil, reason`, the way every refused operation answers; returns 2.
int push_refusal(lua_State* L, const std::string& reason);
// Sets t[key] = value on the table on top of the stack.
void set_string_field(lua_State* L, const char* key, const std::string& value);

// The most faces one whole-mesh subdivision call from a script may make (Loop, Catmull-Clark, linear, the reference
// upsample): such a call runs in C++, out of the instruction hook's reach, so it is refused past this instead.
inline constexpr size_t kMaxSubdividedFaces = size_t(1) << 22;
// The record of one core operation a script ran (flip, split, collapse, a subdivision...), for the journal and the
// recorders: an Operation edit named `name` on `element` (none for whole-mesh ones), which returned `result`.
RecordedEdit operation_edit(const char* name, ElementRef element, ElementRef result);

// The method groups of the mesh metatable, each adding its functions to the table on top of the stack.
void add_edit_methods(lua_State* L);       // edit_bindings.cpp: new_*, delete, record
void add_operation_methods(lua_State* L);  // operation_bindings.cpp: flip, split, collapse, loop_subdivide
// subdivision_bindings.cpp: catmull_clark, linear_subdivide, subdivision_phases
void add_subdivision_methods(lua_State* L);
// mesh:flip(e) and mesh:split(e) as C functions of (mesh, e), recorded and journaled like every change a script makes
// (the reference flip_edge and split_edge are these).
int mesh_flip(lua_State* L);
int mesh_split(lua_State* L);
void add_history_methods(lua_State* L);  // history_bindings.cpp: snapshot, restore, undo, redo, diff
void add_table_methods(lua_State* L);    // table_bindings.cpp: tables
// Module functions (module_bindings.cpp): load, cube, ..., grid, from_polygons; added to the table on top.
void add_module_functions(lua_State* L);

}  // namespace meshedit
