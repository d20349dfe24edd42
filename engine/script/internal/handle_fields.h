// The fields of element handles (internal to engine/script): __index and __newindex (set_handle_accessors,
// declared in handle_context.h), and the pointer reads and writes h:set_neighbors shares with them.
//
//   x.id (integer, also for dead elements)  x.kind ("halfedge"...)  x.mesh  x:method(...) (handle_methods.h)
//   h.next h.twin h.vertex h.edge h.face   v.halfedge v.position (a fresh vec3)   e.halfedge   f.halfedge
//   writable: the same fields; a pointer takes a live element of the same mesh or nil, a position a vec3 or
//   {x, y, z}
// Invariants:
// - Every write goes through make_change, so it is journaled and recorded (with file:line) like any change.
// - Only id and kind can be read from a dead element; anything else raises "attempt to use dead halfedge h37"
//   before the key is looked at further.
// - A key means the same whichever way it is found: first by the address of its interned text (Lua keeps one
//   copy of each short string, so a key built at run time has the literal's address), failing that by its
//   characters.
#pragma once

#include <cstdint>

#include <lua.hpp>

#include "core/halfedge_mesh.h"
#include "script/internal/binding_support.h"

namespace meshedit {

struct BindingState;

// The pointer fields, in the order of their keys.
enum class PointerField : uint8_t { Next, Twin, Vertex, Edge, Face, Halfedge };
// "next" ... "halfedge".
const char* field_name(PointerField field);
// The kind of element a field points to (a face field also takes boundary loops).
ElementKind field_target(PointerField field);
// The stored value of `field` of the live element `h` (the field must belong to h's kind).
ElementRef read_pointer(const HalfedgeMesh& m, const Handle& h, PointerField field);
// Sets `field` of the live element `h` to `value` (an invalid ref of the field's kind for null) through
// make_change.
void write_pointer(lua_State* L, BindingState& state, const Handle& h, PointerField field, ElementRef value);

}  // namespace meshedit
