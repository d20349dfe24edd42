// The `meshedit` Lua module: meshes and element handles (the API is listed in mesh_bindings.cpp's header
// comment and in the issue-4 note).
//
// Invariants:
// - A mesh userdata and every handle hold a shared_ptr to the same HalfedgeMesh, so a handle keeps its mesh
//   alive and a handle is never dangling; a handle whose element is dead (or past the end) raises
//   "attempt to use dead halfedge h37" when used, never reads out of range.
// - Reads of pointer fields return the stored id as a handle even when that id is dead (a broken mesh stays
//   inspectable); an invalid id reads as nil. Writes accept handles of the same mesh, or nil.
// - Every binding converts C++ exceptions (MeshError, FileError, bad_alloc...) into Lua errors.
#pragma once

#include <memory>

#include "core/halfedge_mesh.h"

struct lua_State;

namespace meshedit {

// Sets the global `meshedit` table in L (call once per state).
void open_mesh_bindings(lua_State* L);
// Pushes a new mesh userdata sharing `mesh`.
void push_mesh(lua_State* L, std::shared_ptr<HalfedgeMesh> mesh);
// The mesh of the mesh userdata at `index`, or nullptr if it is not one.
std::shared_ptr<HalfedgeMesh> to_mesh(lua_State* L, int index);

}  // namespace meshedit
