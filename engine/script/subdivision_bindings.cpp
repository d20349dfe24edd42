// Catmull-Clark and linear subdivision as mesh methods, beside mesh:loop_subdivide (operation_bindings.cpp):
//
//   mesh:catmull_clark() -> true | nil, reason      mesh:linear_subdivide() -> true | nil, reason
// Invariants, as for the other operations: a refused call changes nothing and answers nil and the core's reason;
// an accepted one is an undo point recorded as one Operation edit named after the method. Each runs in C++ out of
// the instruction hook's reach, so it is refused when its result would pass the face cap below or
// MeshLimits::elements_per_kind.
#include <string>

#include <lua.hpp>

#include "core/catmull_clark.h"
#include "core/edit_log.h"
#include "core/linear_subdivision.h"
#include "script/binding_state.h"
#include "script/binding_support.h"

namespace meshedit {
namespace {

// Faces after one level: a triangle gives `triangle_children` (4 for linear, 3 for Catmull-Clark), an n-gon n.
size_t faces_after(const HalfedgeMesh& mesh, size_t triangle_children) {
  size_t faces = 0;
  for (FaceId f : mesh.faces()) {
    const uint32_t sides = mesh.degree(f);
    faces += sides == 3 ? triangle_children : sides;
  }
  return faces;
}

int run_subdivision(lua_State* L, const char* name, const char* scheme, size_t triangle_children,
                    Check (*subdivide)(HalfedgeMesh&, int)) {
  MeshBox& box = check_mesh(L, 1);
  HalfedgeMesh& m = *box.mesh;
  const size_t faces = faces_after(m, triangle_children);
  if (faces > kMaxSubdividedFaces) {
    return push_refusal(L, std::string(scheme) + " would make " + std::to_string(faces) +
                               " faces; scripts may make at most " + std::to_string(kMaxSubdividedFaces));
  }
  // Halfedges, the most numerous ids of the result: two per edge, and 2E + F' edges at most (each original edge
  // in two, plus at most one new edge inside an original face per child face).
  if (const std::string full = room_refusal(L, m, 2 * (2 * m.num_edges() + faces)); !full.empty()) {
    return push_refusal(L, full);
  }
  begin_change(L, box.mesh, true);
  const Check check = subdivide(m, 1);
  if (!check.ok) return push_refusal(L, check.reason);
  end_change(L, box.mesh, operation_edit(name, ElementRef(), ElementRef()));
  lua_pushboolean(L, 1);
  return 1;
}

int mesh_catmull_clark(lua_State* L) {
  return run_subdivision(L, "catmull_clark", "Catmull-Clark subdivision", 3, catmull_clark_subdivide);
}

int mesh_linear_subdivide(lua_State* L) {
  return run_subdivision(L, "linear_subdivide", "linear subdivision", 4, linear_subdivide);
}

}  // namespace

void add_subdivision_methods(lua_State* L) {
  const luaL_Reg methods[] = {{"catmull_clark", guarded<mesh_catmull_clark>},
                              {"linear_subdivide", guarded<mesh_linear_subdivide>},
                              {nullptr, nullptr}};
  luaL_setfuncs(L, methods, 0);
}

}  // namespace meshedit
