// The core's operations as mesh methods: flip, split, collapse, loop_subdivide and triangulate.
//
//   mesh:flip(e) -> e | nil, reason        mesh:split(e) -> new vertex | nil, reason
//   mesh:collapse(e) -> surviving vertex | nil, reason      mesh:loop_subdivide() -> true | nil, reason
//   mesh:triangulate() -> number of polygons split | nil, reason (the mesh is rebuilt: core/triangulate.h)
// Invariants: a refused operation changes nothing and answers nil and the core's reason (a dead or broken edge
// included: the core checks every pointer before following it); an accepted one is an undo point and is
// recorded as one Operation edit. Operations run in C++ out of the instruction hook's reach, so they are
// refused when they would pass MeshLimits::elements_per_kind or the face cap below.
#include <string>

#include <lua.hpp>

#include "core/edit_log.h"
#include "core/loop_subdivision.h"
#include "core/mesh_ops.h"
#include "core/triangulate.h"
#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"

namespace meshedit {
namespace {

// Ids one flip, split or collapse makes at most, of any kind.
constexpr size_t kMaxIdsPerOperation = 6;

template <class Result, Result (*Operation)(HalfedgeMesh&, EdgeId)>
int run_edge_operation(lua_State* L, const char* name) {
  MeshBox& box = check_mesh(L, 1);
  Handle& e = check_handle(L, 2, ElementKind::Edge);
  check_same_mesh(L, box.mesh, e);
  if (const std::string full = room_refusal(L, *box.mesh, kMaxIdsPerOperation); !full.empty()) {
    return push_refusal(L, full);
  }
  begin_change(L, box.mesh, true);
  const Result result = Operation(*box.mesh, EdgeId(e.index));
  if (!result.ok()) return push_refusal(L, result.check.reason);
  end_change(L, box.mesh, operation_edit(name, e.ref(), ElementRef(result.value)));
  push_handle_at(L, 1, result.value);
  return 1;
}

int mesh_collapse(lua_State* L) { return run_edge_operation<OpResult<VertexId>, collapse>(L, "collapse"); }

int mesh_loop_subdivide(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  HalfedgeMesh& m = *box.mesh;
  const size_t faces_after = 4 * m.num_faces();
  if (faces_after > kMaxSubdividedFaces) {
    return push_refusal(L, "loop subdivision would make " + std::to_string(faces_after) +
                               " faces; scripts may make at most " + std::to_string(kMaxSubdividedFaces));
  }
  // New halfedges, the most numerous new ids: two per new edge (E + 3F of them).
  if (const std::string full = room_refusal(L, m, 2 * (m.num_edges() + 3 * m.num_faces())); !full.empty()) {
    return push_refusal(L, full);
  }
  begin_change(L, box.mesh, true);
  const Check check = loop_subdivide(m);
  if (!check.ok) return push_refusal(L, check.reason);
  end_change(L, box.mesh, operation_edit("loop_subdivide", ElementRef(), ElementRef()));
  lua_pushboolean(L, 1);
  return 1;
}

int mesh_triangulate(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  HalfedgeMesh& m = *box.mesh;
  size_t triangles = 0, polygons = 0;
  for (FaceId f : m.faces()) {
    triangles += m.degree(f) > 2 ? m.degree(f) - 2 : 0;
    polygons += m.degree(f) > 3 ? 1 : 0;
  }
  if (polygons == 0) {  // nothing to split: no undo point, nothing recorded
    lua_pushinteger(L, 0);
    return 1;
  }
  const uint32_t cap = binding_state(L).limits.elements_per_kind;
  if (3 * triangles > cap) {
    return push_refusal(L, "triangulating would make " + std::to_string(3 * triangles) +
                               " halfedges; scripts may make at most " + std::to_string(cap));
  }
  begin_change(L, box.mesh, true);
  const OpResult<TriangulationReport> done = triangulate_mesh(m);
  if (!done.ok()) return push_refusal(L, done.check.reason);
  end_change(L, box.mesh, operation_edit("triangulate", ElementRef(), ElementRef()));
  lua_pushinteger(L, static_cast<lua_Integer>(done.value.polygons_split));
  return 1;
}

}  // namespace

RecordedEdit operation_edit(const char* name, ElementRef element, ElementRef result) {
  RecordedEdit edit;
  edit.what = EditKind::Operation;
  edit.element = element;
  edit.field = name;
  edit.value.element = result;
  return edit;
}

int mesh_flip(lua_State* L) { return run_edge_operation<OpResult<EdgeId>, flip>(L, "flip"); }
int mesh_split(lua_State* L) { return run_edge_operation<OpResult<VertexId>, split>(L, "split"); }

void add_operation_methods(lua_State* L) {
  const luaL_Reg methods[] = {{"flip", guarded<mesh_flip>},
                              {"split", guarded<mesh_split>},
                              {"collapse", guarded<mesh_collapse>},
                              {"loop_subdivide", guarded<mesh_loop_subdivide>},
                              {"triangulate", guarded<mesh_triangulate>},
                              {nullptr, nullptr}};
  luaL_setfuncs(L, methods, 0);
}

}  // namespace meshedit
