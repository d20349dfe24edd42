// The reference solutions handed to student code, so that one part does not punish a mistake in another ("upsample
// uses the reference flip and split"): by a grading suite (`reference = {...}`) and by the window for the exercise
// that builds on them (exercise_api in student_api.h), the same functions in both.
//
// Invariants:
// - Every reference is a C function calling the core (mesh_ops.h, loop_subdivision.h, bezier.h, normals.h):
//   student code can call it but never read it (no string.dump of C functions, no debug library). flip_edge and
//   split_edge are mesh:flip and mesh:split themselves, so their changes are recorded (the window's replay) alike.
// - Each keeps the student-facing signature of its exercise: flip_edge(mesh, e) -> e | nil,
//   split_edge(mesh, e) -> new vertex | nil, upsample(mesh), vertex_normal(v) -> vec3,
//   evaluate_step(points, t) -> points, evaluate(patch, u, v) -> vec3 (patch.points: 16, row-major).
#pragma once

#include <string>
#include <vector>

struct lua_State;

namespace meshedit {

// The names a suite may list in `reference = {...}`.
const std::vector<std::string>& reference_function_names();
bool is_reference_function(const std::string& name);
// Sets the global `name` of L to the reference. Returns false for an unknown name (nothing is set).
bool install_reference_function(lua_State* L, const std::string& name);

}  // namespace meshedit
