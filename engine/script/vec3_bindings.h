// vec3: the point/vector type scripts use for positions and Bézier points.
//
// A vec3 is a plain Lua table {x=, y=, z=} carrying a shared metatable, so students can write
// `(a + b) * 0.5`, `v:dot(w)`, `tostring(p)` -> "(1, 2, 3)". Plain tables {x, y, z} or {x=, y=, z=} (without
// the metatable) are accepted wherever a point is expected.
//
// Invariants:
// - Every vec3 pushed from C++ is a fresh table: changing it never changes the element or curve it came from.
// - Arithmetic never raises for non-finite numbers (NaN propagates); it raises a Lua error naming the
//   operation and the offending type for non-vectors ("vec3 '+': expected a vec3, got nil").
// - normalized() of a zero-length vector returns the zero vector (no NaN from a division by zero).
#pragma once

#include <glm/vec3.hpp>

struct lua_State;

namespace meshedit {

// Registers the metatable and sets `vec3` in the table at the top of the stack (the `meshedit` module).
void open_vec3(lua_State* L);
// Pushes a new vec3 table.
void push_vec3(lua_State* L, const glm::dvec3& v);
// Reads a vec3 or a plain table {x, y, z} / {x=, y=, z=} of numbers at `index`; false (and `out` unchanged)
// for anything else. Never raises.
bool to_vec3(lua_State* L, int index, glm::dvec3& out);
// Like to_vec3, but raises "<what> must be a vec3 or a table {x, y, z} of numbers, got <type>".
glm::dvec3 check_vec3(lua_State* L, int index, const char* what);

}  // namespace meshedit
