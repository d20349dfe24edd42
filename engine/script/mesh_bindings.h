// The `meshedit` Lua module: meshes, element handles, vec3, edits and their recording. The Lua API is listed
// in mesh_bindings.cpp's header comment; the C++ recorder a host uses is in edit_recorder.h.
//
// Invariants:
// - A mesh userdata holds a shared_ptr to its HalfedgeMesh, and every handle keeps the mesh userdata it was made
//   from alive (binding_support.h), so a handle keeps its mesh alive and is never dangling; a handle whose
//   element is dead (or past the end) raises "attempt to use dead halfedge h37" when used, never reads out of
//   range.
// - Reads of pointer fields return the stored id as a handle even when that id is dead (a broken mesh stays
//   inspectable); an invalid id reads as nil. Writes accept live handles of the same mesh, or nil.
// - Nothing a script does to a mesh (any pointer written anywhere) makes a binding crash or hang: every walk
//   is bounded and every id is checked before it is followed.
// - C++ mesh storage is outside Lua's memory cap, so it has its own limits (MeshLimits), enforced with clear
//   Lua errors.
// - Every binding converts C++ exceptions (MeshError, FileError, bad_alloc...) into Lua errors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "core/halfedge_mesh.h"

struct lua_State;

namespace meshedit {

struct MeshLimits {
  // Ids of each kind one mesh may reach through new_* and the operations (2^24: 16.7 million).
  uint32_t elements_per_kind = uint32_t(1) << 24;
  // C++ memory held by the mesh copies a script made (copy, snapshot, load, primitives, from_polygons).
  size_t storage_bytes = size_t(1) << 30;
};

// Sets the global `meshedit` table in L (call once per state).
void open_mesh_bindings(lua_State* L);
// Pushes a new mesh userdata sharing `mesh`.
void push_mesh(lua_State* L, std::shared_ptr<HalfedgeMesh> mesh);
// The mesh of the mesh userdata at `index`, or nullptr if it is not one.
std::shared_ptr<HalfedgeMesh> to_mesh(lua_State* L, int index);

// Replaces the limits of L's state (open_mesh_bindings sets the defaults above).
void set_mesh_limits(lua_State* L, const MeshLimits& limits);

}  // namespace meshedit
