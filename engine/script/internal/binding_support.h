// What the files of the `meshedit` module share beyond lua_handles.h (internal to engine/script): the handle
// metatables, the pointer-store checks, the refusals, and the method groups of the mesh metatable.
//
// Invariants:
// - A MeshBox's BindingState is made first and finalized last in its state, so making a handle tells the state's
//   touch recorders without a registry lookup.
// - Two handles are the same element when their meshes (not their boxes) and refs are equal: one mesh may
//   have several boxes (push_mesh makes a new one each time).
// - A handle's metatable carries its kind under a private key, so test_handle is one lookup and a table or
//   another library's userdata is never mistaken for a handle.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <lua.hpp>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"
#include "script/lua_handles.h"

namespace meshedit {

// ---- handles (handle_bindings.cpp; fields: handle_fields.h; methods: handle_methods.h) ---------------------
// Registers the five handle metatables (call once per state, before any handle is pushed).
void open_handle_metatables(lua_State* L);
// Pushes a handle for `ref` of the mesh whose MeshBox userdata is at stack index `box`, or nil when ref is
// invalid (a null pointer). `metatable`: the stack index of ref.kind's handle metatable, or 0 to look it up.
void push_handle_at(lua_State* L, int box, ElementRef ref, int metatable = 0);
// A handle for `ref` on the mesh of `h`, the handle at stack index `handle` (anchored to h's box).
void push_sibling_handle(lua_State* L, const Handle& h, int handle, ElementRef ref, int metatable = 0);
// Pushes the handle metatable of `kind`.
void push_handle_metatable(lua_State* L, ElementKind kind);

// "h1 belongs to another mesh" unless `value` is an element of `mesh`.
void check_same_mesh(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value);
// A value to store in a pointer: a live handle of `mesh`; kind and nil are the caller's business.
void check_storable(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value);

// ---- meshes (mesh_bindings.cpp) -------------------------------------------------------------------------
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
