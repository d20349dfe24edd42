// The `meshedit` Lua module: its registration, and the mesh methods that read (iteration, lookup, counts,
// validate, save, copy). The whole Lua API, by file:
//
// module (module_bindings.cpp, vec3_bindings.cpp)
//   meshedit.load(path) meshedit.cube() meshedit.tetrahedron() meshedit.icosahedron() meshedit.grid(nx, ny)
//   meshedit.from_polygons(positions, polygons)   positions: list of points; polygons: lists of 1-based indices
//                                                 into positions (positions[k] becomes v(k-1), polygons[k] f(k-1))
//   meshedit.vec3(x, y, z)                        points: + - * / unary -, ==, tostring, :dot :cross :length
//                                                 :normalized; plain {x, y, z} / {x=, y=, z=} tables are accepted
// reading (this file)
//   mesh:halfedges() :vertices() :edges() :faces() :boundaries()   iterators over live elements (end fixed)
//   mesh:halfedge(i) :vertex(i) :edge(i) :face(i) :boundary(i)     handle by id (may be dead; error past the end)
//   mesh:element("h37")                                            the same, from a printed id
//   mesh:num_vertices() :num_halfedges() :num_edges() :num_faces() :num_boundaries()
//   mesh:validate() -> ok, {summary=, total=, violations={{element=, invariant=, message=}...}}
//   mesh:save(path)   mesh:copy()   mesh:alive(element) -> boolean
// tables (table_bindings.cpp)
//   mesh:tables() -> {vertices={{id="v0", halfedge="h0", position=vec3}...}, halfedges={{id=, next=, twin=,
//                    vertex=, edge=, face=}...}, edges={{id=, halfedge=}...}, faces=..., boundaries=...}
// handles (handle_bindings.cpp; fields in handle_fields.cpp, methods in handle_methods.cpp)
//   tostring(x) -> "h37"; ==; x.id x.kind x.mesh; h.next h.twin h.vertex h.edge h.face; v.halfedge v.position;
//   e.halfedge; f.halfedge; v:degree() f:degree(); x:is_boundary(); h:prev(); f:halfedges() f:vertices()
//   v:halfedges() v:neighbors() (iterators); writable: every pointer field and v.position;
//   h:set_neighbors(next, twin, vertex, edge, face)
// edits (edit_bindings.cpp)
//   mesh:new_vertex([position]) :new_halfedge() :new_edge() :new_face() :new_boundary()  -> the new element
//   mesh:delete(element)
//   mesh:record(fn) -> list of {what=, element=, field=, before=, after=, where="file.lua:12"} for every change
//                      fn made to this mesh (what: "set" "new" "delete" "operation")
// operations (operation_bindings.cpp)
//   mesh:flip(e) -> e | nil, reason      mesh:split(e) -> new vertex | nil, reason
//   mesh:collapse(e) -> surviving vertex | nil, reason    mesh:loop_subdivide() -> true | nil, reason
// history (history_bindings.cpp)
//   mesh:snapshot() -> snapshot    mesh:restore(snapshot)
//   mesh:diff(snapshot_or_mesh) -> list of {element="h3", field="next", before="h4", after="h7"}
//   mesh:undo() / mesh:redo() -> what was undone ("flip e3") | nil; whole operations (flip, split, collapse,
//                                loop_subdivide, restore) are the steps
// Invariants: see mesh_bindings.h.
#include "script/mesh_bindings.h"

#include <optional>
#include <string>

#include <lua.hpp>

#include "core/mesh_build.h"
#include "core/validate.h"
#include "io/mesh_file.h"
#include "script/bezier_bindings.h"
#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"
#include "script/touch_recorder.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

int mesh_gc(lua_State* L) {
  static_cast<MeshBox*>(lua_touserdata(L, 1))->~MeshBox();
  return 0;
}

int mesh_tostring(lua_State* L) {
  const HalfedgeMesh& m = *check_mesh(L, 1).mesh;
  lua_pushfstring(L, "mesh (%d vertices, %d edges, %d faces)", int(m.num_vertices()), int(m.num_edges()),
                  int(m.num_faces()));
  return 1;
}

int mesh_eq(lua_State* L) {
  auto* a = static_cast<MeshBox*>(luaL_testudata(L, 1, kMeshType));
  auto* b = static_cast<MeshBox*>(luaL_testudata(L, 2, kMeshType));
  lua_pushboolean(L, a && b && a->mesh == b->mesh);
  return 1;
}

// Iterator closure: upvalues mesh userdata, kind, next slot, end slot, the kind's handle metatable.
int mesh_iterate_step(lua_State* L) {
  const auto& mesh = static_cast<MeshBox*>(lua_touserdata(L, lua_upvalueindex(1)))->mesh;
  const auto kind = static_cast<ElementKind>(lua_tointeger(L, lua_upvalueindex(2)));
  auto i = static_cast<uint32_t>(lua_tointeger(L, lua_upvalueindex(3)));
  const auto end = static_cast<uint32_t>(lua_tointeger(L, lua_upvalueindex(4)));
  while (i < end && !mesh->alive(ElementRef(kind, i))) ++i;
  if (i >= end) return 0;
  lua_pushinteger(L, i + 1);
  lua_replace(L, lua_upvalueindex(3));
  push_handle_at(L, lua_upvalueindex(1), ElementRef(kind, i), lua_upvalueindex(5));
  return 1;
}

template <ElementKind K>
int mesh_iterate(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  lua_pushvalue(L, 1);
  lua_pushinteger(L, static_cast<lua_Integer>(K));
  lua_pushinteger(L, 0);
  lua_pushinteger(L, box.mesh->capacity(K));
  push_handle_metatable(L, K);
  lua_pushcclosure(L, mesh_iterate_step, 5);
  return 1;
}

// The element of `box` (the mesh at 1) of `kind` and id `i`.
int push_element(lua_State* L, const MeshBox& box, ElementKind kind, lua_Integer i) {
  const uint32_t capacity = box.mesh->capacity(kind);
  if (i < 0 || i >= lua_Integer(capacity)) {
    return luaL_error(L, "no %s with id %I in this mesh (%s ids go from 0 to %d)", kind_name(kind), i, kind_name(kind),
                      int(capacity) - 1);
  }
  push_handle_at(L, 1, ElementRef(kind, static_cast<uint32_t>(i)));
  return 1;
}

template <ElementKind K>
int mesh_element(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  return push_element(L, box, K, luaL_checkinteger(L, 2));
}

// mesh:element("h37").
int mesh_element_by_name(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  const char* text = luaL_checkstring(L, 2);
  const std::optional<ElementRef> ref = parse_element(text);
  if (!ref) {
    return luaL_argerror(L, 2, lua_pushfstring(L, "expected an id such as \"h37\" or \"b0\", got \"%s\"", text));
  }
  return push_element(L, box, ref->kind, ref->index);
}

template <ElementKind K>
int mesh_count(lua_State* L) {
  const HalfedgeMesh& m = *check_mesh(L, 1).mesh;
  size_t n = 0;
  switch (K) {
    case ElementKind::Vertex: n = m.num_vertices(); break;
    case ElementKind::Halfedge: n = m.num_halfedges(); break;
    case ElementKind::Edge: n = m.num_edges(); break;
    case ElementKind::Face: n = m.num_faces(); break;
    case ElementKind::Boundary: n = m.num_boundaries(); break;
  }
  lua_pushinteger(L, static_cast<lua_Integer>(n));
  return 1;
}

int mesh_validate(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  note_whole_mesh_read(L, box.mesh.get(), "mesh:validate()");
  const ValidationReport report = validate(*box.mesh);
  lua_pushboolean(L, report.ok());
  lua_createtable(L, 0, 3);
  set_string_field(L, "summary", report.summary());
  lua_pushinteger(L, static_cast<lua_Integer>(report.total));
  lua_setfield(L, -2, "total");
  lua_createtable(L, static_cast<int>(report.violations.size()), 0);
  for (size_t i = 0; i < report.violations.size(); ++i) {
    const Violation& v = report.violations[i];
    lua_createtable(L, 0, 3);
    push_handle_at(L, 1, v.element);
    lua_setfield(L, -2, "element");
    lua_pushstring(L, invariant_name(v.invariant));
    lua_setfield(L, -2, "invariant");
    set_string_field(L, "message", v.message);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "violations");
  return 2;
}

int mesh_save(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  save_mesh(luaL_checkstring(L, 2), to_polygon_mesh(*box.mesh));
  return 0;
}

// mesh:alive(element): false for a dead element of this mesh (the one query a dead handle allows).
int mesh_alive(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  Handle& h = check_any_handle(L, 2);
  check_same_mesh(L, box.mesh, h);
  lua_pushboolean(L, box.mesh->alive(h.ref()));
  return 1;
}

int mesh_copy(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  note_whole_mesh_read(L, box.mesh.get(), "mesh:copy()");
  push_mesh(L, copy_mesh(L, *box.mesh));
  return 1;
}

void open_mesh_metatable(lua_State* L) {
  const luaL_Reg methods[] = {{"halfedges", guarded<mesh_iterate<ElementKind::Halfedge>>},
                              {"vertices", guarded<mesh_iterate<ElementKind::Vertex>>},
                              {"edges", guarded<mesh_iterate<ElementKind::Edge>>},
                              {"faces", guarded<mesh_iterate<ElementKind::Face>>},
                              {"boundaries", guarded<mesh_iterate<ElementKind::Boundary>>},
                              {"halfedge", guarded<mesh_element<ElementKind::Halfedge>>},
                              {"vertex", guarded<mesh_element<ElementKind::Vertex>>},
                              {"edge", guarded<mesh_element<ElementKind::Edge>>},
                              {"face", guarded<mesh_element<ElementKind::Face>>},
                              {"boundary", guarded<mesh_element<ElementKind::Boundary>>},
                              {"element", guarded<mesh_element_by_name>},
                              {"num_halfedges", guarded<mesh_count<ElementKind::Halfedge>>},
                              {"num_vertices", guarded<mesh_count<ElementKind::Vertex>>},
                              {"num_edges", guarded<mesh_count<ElementKind::Edge>>},
                              {"num_faces", guarded<mesh_count<ElementKind::Face>>},
                              {"num_boundaries", guarded<mesh_count<ElementKind::Boundary>>},
                              {"validate", guarded<mesh_validate>},
                              {"save", guarded<mesh_save>},
                              {"copy", guarded<mesh_copy>},
                              {"alive", guarded<mesh_alive>},
                              {nullptr, nullptr}};
  luaL_newmetatable(L, kMeshType);
  lua_pushcfunction(L, mesh_gc);
  lua_setfield(L, -2, "__gc");
  lua_pushcfunction(L, guarded<mesh_tostring>);
  lua_setfield(L, -2, "__tostring");
  lua_pushcfunction(L, mesh_eq);
  lua_setfield(L, -2, "__eq");
  lua_pushboolean(L, 0);
  lua_setfield(L, -2, "__metatable");
  luaL_newlib(L, methods);
  add_edit_methods(L);
  add_operation_methods(L);
  add_subdivision_methods(L);
  add_history_methods(L);
  add_table_methods(L);
  lua_setfield(L, -2, "__index");
  lua_pop(L, 1);
}

int open_module(lua_State* L) {
  lua_newtable(L);
  add_module_functions(L);
  open_vec3(L);
  open_bezier_bindings(L);
  return 1;
}

}  // namespace

MeshBox& check_mesh(lua_State* L, int arg) { return *static_cast<MeshBox*>(luaL_checkudata(L, arg, kMeshType)); }

int push_refusal(lua_State* L, const std::string& reason) {
  lua_pushnil(L);
  lua_pushstring(L, reason.c_str());
  return 2;
}

void set_string_field(lua_State* L, const char* key, const std::string& value) {
  lua_pushlstring(L, value.data(), value.size());
  lua_setfield(L, -2, key);
}

void push_mesh(lua_State* L, std::shared_ptr<HalfedgeMesh> mesh) {
  auto* box = static_cast<MeshBox*>(lua_newuserdatauv(L, sizeof(MeshBox), 0));
  new (box) MeshBox{std::move(mesh), find_binding_state(L)};
  luaL_setmetatable(L, kMeshType);
}

std::shared_ptr<HalfedgeMesh> to_mesh(lua_State* L, int index) {
  auto* box = static_cast<MeshBox*>(luaL_testudata(L, index, kMeshType));
  return box ? box->mesh : nullptr;
}

void open_mesh_bindings(lua_State* L) {
  open_binding_state(L);
  open_handle_metatables(L);
  open_mesh_metatable(L);
  // Registered as a loaded module too, so Lua's messages name functions "meshedit.grid" even through pcall.
  luaL_requiref(L, "meshedit", open_module, 1);
  lua_pop(L, 1);
}

}  // namespace meshedit
