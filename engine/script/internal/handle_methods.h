// The methods of element handles (internal to engine/script), listed for __index (handle_fields.cpp):
//
//   v:degree() f:degree()   x:is_boundary()   h:prev()   h:set_neighbors(next, twin, vertex, edge, face)
//   for h in f:halfedges() / v:halfedges() (outgoing), for w in f:vertices() / v:neighbors()
// Invariants: see handle_methods.cpp.
#pragma once

#include <cstdint>
#include <span>

#include <lua.hpp>

#include "core/ids.h"

namespace meshedit {

constexpr uint8_t kind_bit(ElementKind kind) { return uint8_t(1u << static_cast<unsigned>(kind)); }

struct HandleMethod {
  const char* name;
  lua_CFunction function;  // wrapped in guarded<>; upvalue 1 is the state's HandleContext (handle_context.h)
  uint8_t kinds;           // kind_bit of the kinds that have it
};

std::span<const HandleMethod> handle_methods();

}  // namespace meshedit
