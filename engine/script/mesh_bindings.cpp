// The `meshedit` Lua module. Lua API (positions are tables {x=, y=, z=}; writes also accept {x, y, z}):
//   meshedit.load(path) meshedit.cube() meshedit.tetrahedron() meshedit.icosahedron() meshedit.grid(nx, ny)
//   mesh:halfedges() :vertices() :edges() :faces() :boundaries()   iterators over live elements (end fixed)
//   mesh:halfedge(i) :vertex(i) :edge(i) :face(i) :boundary(i)     handle by id (may be dead; error past the end)
//   mesh:num_vertices() :num_halfedges() :num_edges() :num_faces() :num_boundaries()
//   mesh:flip(e) -> e | nil, reason      mesh:split(e) -> new vertex | nil, reason
//   mesh:collapse(e) -> surviving vertex | nil, reason    mesh:loop_subdivide() -> true | nil, reason
//   mesh:validate() -> ok, {summary=, total=, violations={{element=, invariant=, message=}...}}
//   mesh:save(path)   mesh:copy()   mesh:alive(element) -> boolean
//   handles: tostring -> "h37"; ==; h.id h.mesh; h.next h.twin h.vertex h.edge h.face; v.halfedge v.position;
//   e.halfedge; f.halfedge (faces and boundary loops); v:degree() f:degree(); v/e/f/h:is_boundary();
//   writable: h.next h.twin h.vertex h.edge h.face v.halfedge v.position e.halfedge f.halfedge (nil clears);
//   h:set_neighbors(next, twin, vertex, edge, face).
// Invariants: see mesh_bindings.h.
#include "script/mesh_bindings.h"

#include <cmath>
#include <exception>
#include <string>

#include <lua.hpp>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/loop_subdivision.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "io/mesh_file.h"

namespace meshedit {
namespace {

constexpr const char* kMeshType = "mesh";

struct MeshBox {
  std::shared_ptr<HalfedgeMesh> mesh;
};

struct Handle {
  std::shared_ptr<HalfedgeMesh> mesh;
  ElementKind kind;
  uint32_t index;  // the slot (no boundary bit)
};

const ElementKind kAllKinds[] = {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face,
                                 ElementKind::Boundary};

// Runs a binding with C++ exceptions turned into Lua errors. The message is copied out of the handler so
// the Lua error (itself a C++ throw in this build of Lua) starts after the C++ exception is finished.
template <lua_CFunction F>
int guarded(lua_State* L) {
  std::string message;
  try {
    return F(L);
  } catch (const std::exception& e) {
    message = e.what();
  }
  return luaL_error(L, "%s", message.c_str());
}

// ---- handles --------------------------------------------------------------------------------------

void push_handle(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, ElementRef ref) {
  if (!ref.valid()) {
    lua_pushnil(L);
    return;
  }
  auto* h = static_cast<Handle*>(lua_newuserdatauv(L, sizeof(Handle), 0));
  new (h) Handle{mesh, ref.kind, ref.index};
  luaL_setmetatable(L, kind_name(ref.kind));
}

Handle* test_handle(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TUSERDATA) return nullptr;
  for (ElementKind kind : kAllKinds) {
    if (void* p = luaL_testudata(L, index, kind_name(kind))) return static_cast<Handle*>(p);
  }
  return nullptr;
}

ElementRef ref_of(const Handle& h) { return ElementRef(h.kind, h.index); }
std::string name_of(const Handle& h) { return format_id(ref_of(h)); }

bool accepts(ElementKind wanted, ElementKind got) {
  return wanted == got || (wanted == ElementKind::Face && got == ElementKind::Boundary);
}

// Argument `arg` must be a handle of kind `wanted` (a face slot accepts boundary loops too).
Handle& check_handle(lua_State* L, int arg, ElementKind wanted) {
  Handle* h = test_handle(L, arg);
  if (!h || !accepts(wanted, h->kind)) luaL_typeerror(L, arg, kind_name(wanted));
  return *h;
}

void check_alive(lua_State* L, const Handle& h) {
  if (!h.mesh->alive(ref_of(h))) {
    luaL_error(L, "attempt to use dead %s %s", kind_name(h.kind), name_of(h).c_str());
  }
}

// A live handle of the expected kind, for `self` of element methods.
Handle& check_self(lua_State* L, ElementKind wanted) {
  Handle& h = check_handle(L, 1, wanted);
  check_alive(L, h);
  return h;
}

void check_same_mesh(lua_State* L, const Handle& owner, const Handle& value) {
  if (owner.mesh != value.mesh) luaL_error(L, "%s belongs to another mesh", name_of(value).c_str());
}

void push_position(lua_State* L, const glm::dvec3& p) {
  lua_createtable(L, 0, 3);
  lua_pushnumber(L, p.x);
  lua_setfield(L, -2, "x");
  lua_pushnumber(L, p.y);
  lua_setfield(L, -2, "y");
  lua_pushnumber(L, p.z);
  lua_setfield(L, -2, "z");
}

glm::dvec3 check_position(lua_State* L, int index, const char* what) {
  if (lua_type(L, index) != LUA_TTABLE) luaL_error(L, "%s must be a table {x=, y=, z=}", what);
  glm::dvec3 p;
  const char* names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (lua_getfield(L, index, names[i]) == LUA_TNIL) {
      lua_pop(L, 1);
      lua_geti(L, index, i + 1);
    }
    int is_number = 0;
    p[i] = lua_tonumberx(L, -1, &is_number);
    lua_pop(L, 1);
    if (!is_number) luaL_error(L, "%s must be a table {x=, y=, z=} of numbers", what);
  }
  return p;
}

int handle_gc(lua_State* L) {
  static_cast<Handle*>(lua_touserdata(L, 1))->~Handle();
  return 0;
}

int handle_tostring(lua_State* L) {
  const Handle* h = test_handle(L, 1);
  lua_pushstring(L, h ? name_of(*h).c_str() : "?");
  return 1;
}

int handle_eq(lua_State* L) {
  const Handle* a = test_handle(L, 1);
  const Handle* b = test_handle(L, 2);
  lua_pushboolean(L, a && b && a->mesh == b->mesh && a->kind == b->kind && a->index == b->index);
  return 1;
}

int element_degree(lua_State* L) {
  Handle* h = test_handle(L, 1);
  if (h && h->kind == ElementKind::Vertex) {
    check_alive(L, *h);
    lua_pushinteger(L, h->mesh->degree(VertexId(h->index)));
    return 1;
  }
  Handle& f = check_self(L, ElementKind::Face);
  lua_pushinteger(L, f.mesh->degree(ref_of(f).face_id()));
  return 1;
}

int element_is_boundary(lua_State* L) {
  Handle* h = test_handle(L, 1);
  if (!h) return luaL_typeerror(L, 1, "element");
  check_alive(L, *h);
  const HalfedgeMesh& m = *h->mesh;
  bool result = false;
  switch (h->kind) {
    case ElementKind::Vertex: result = m.is_boundary(VertexId(h->index)); break;
    case ElementKind::Halfedge: result = m.is_boundary(HalfedgeId(h->index)); break;
    case ElementKind::Edge: result = m.is_boundary(EdgeId(h->index)); break;
    case ElementKind::Face: result = false; break;
    case ElementKind::Boundary: result = true; break;
  }
  lua_pushboolean(L, result);
  return 1;
}

int halfedge_set_neighbors(lua_State* L) {
  Handle& h = check_self(L, ElementKind::Halfedge);
  Handle& next = check_handle(L, 2, ElementKind::Halfedge);
  Handle& twin = check_handle(L, 3, ElementKind::Halfedge);
  Handle& vertex = check_handle(L, 4, ElementKind::Vertex);
  Handle& edge = check_handle(L, 5, ElementKind::Edge);
  Handle& face = check_handle(L, 6, ElementKind::Face);
  for (Handle* value : {&next, &twin, &vertex, &edge, &face}) check_same_mesh(L, h, *value);
  h.mesh->set_neighbors(HalfedgeId(h.index), HalfedgeId(next.index), HalfedgeId(twin.index), VertexId(vertex.index),
                        EdgeId(edge.index), ref_of(face).face_id());
  return 0;
}

// The pointer read by `h.<key>` etc.; returns false if the key is not a pointer field of that kind.
bool read_pointer(const HalfedgeMesh& m, const Handle& h, const std::string& key, ElementRef& out) {
  switch (h.kind) {
    case ElementKind::Halfedge: {
      const HalfedgeId id(h.index);
      if (key == "next") out = m.next(id);
      else if (key == "twin") out = m.twin(id);
      else if (key == "vertex") out = m.vertex(id);
      else if (key == "edge") out = m.edge(id);
      else if (key == "face") out = m.face(id);
      else return false;
      return true;
    }
    case ElementKind::Vertex:
      if (key != "halfedge") return false;
      out = m.halfedge(VertexId(h.index));
      return true;
    case ElementKind::Edge:
      if (key != "halfedge") return false;
      out = m.halfedge(EdgeId(h.index));
      return true;
    case ElementKind::Face:
    case ElementKind::Boundary:
      if (key != "halfedge") return false;
      out = m.halfedge(ref_of(h).face_id());
      return true;
  }
  return false;
}

int handle_index(lua_State* L) {
  Handle* h = test_handle(L, 1);
  if (!h) return luaL_typeerror(L, 1, "element");
  const std::string key = luaL_checkstring(L, 2);
  if (key == "id") {
    lua_pushinteger(L, h->index);
    return 1;
  }
  check_alive(L, *h);
  ElementRef target;
  if (read_pointer(*h->mesh, *h, key, target)) {
    // A write may have stored an id of another kind's range; a pointer always reads as its own kind.
    push_handle(L, h->mesh, target);
    return 1;
  }
  if (h->kind == ElementKind::Vertex && key == "position") {
    push_position(L, h->mesh->position(VertexId(h->index)));
    return 1;
  }
  if (key == "mesh") {
    push_mesh(L, h->mesh);
    return 1;
  }
  if (key == "is_boundary") {
    lua_pushcfunction(L, guarded<element_is_boundary>);
    return 1;
  }
  if (key == "degree" && h->kind != ElementKind::Halfedge && h->kind != ElementKind::Edge) {
    lua_pushcfunction(L, guarded<element_degree>);
    return 1;
  }
  if (key == "set_neighbors" && h->kind == ElementKind::Halfedge) {
    lua_pushcfunction(L, guarded<halfedge_set_neighbors>);
    return 1;
  }
  return luaL_error(L, "%s has no field '%s'", name_of(*h).c_str(), key.c_str());
}

// The value being written (argument 3) as an id of kind `wanted`, or invalid for nil.
ElementRef pointer_value(lua_State* L, const Handle& owner, const std::string& key, ElementKind wanted) {
  if (lua_isnil(L, 3)) return ElementRef(wanted, kInvalidIndex);
  Handle* value = test_handle(L, 3);
  if (!value || !accepts(wanted, value->kind)) {
    luaL_error(L, "%s.%s must be a %s or nil, got %s", name_of(owner).c_str(), key.c_str(), kind_name(wanted),
               value ? kind_name(value->kind) : luaL_typename(L, 3));
  }
  check_same_mesh(L, owner, *value);
  return ref_of(*value);
}

int handle_newindex(lua_State* L) {
  Handle* h = test_handle(L, 1);
  if (!h) return luaL_typeerror(L, 1, "element");
  const std::string key = luaL_checkstring(L, 2);
  check_alive(L, *h);
  HalfedgeMesh& m = *h->mesh;
  const auto halfedge_value = [&] { return HalfedgeId(pointer_value(L, *h, key, ElementKind::Halfedge).index); };
  if (h->kind == ElementKind::Halfedge) {
    const HalfedgeId id(h->index);
    if (key == "next") return m.set_next(id, halfedge_value()), 0;
    if (key == "twin") return m.set_twin(id, halfedge_value()), 0;
    if (key == "vertex") return m.set_vertex(id, VertexId(pointer_value(L, *h, key, ElementKind::Vertex).index)), 0;
    if (key == "edge") return m.set_edge(id, EdgeId(pointer_value(L, *h, key, ElementKind::Edge).index)), 0;
    if (key == "face") {
      const ElementRef f = pointer_value(L, *h, key, ElementKind::Face);
      return m.set_face(id, f.valid() ? f.face_id() : FaceId()), 0;
    }
  } else if (key == "halfedge") {
    const HalfedgeId value = halfedge_value();
    if (h->kind == ElementKind::Vertex) m.set_halfedge(VertexId(h->index), value);
    else if (h->kind == ElementKind::Edge) m.set_halfedge(EdgeId(h->index), value);
    else m.set_halfedge(ref_of(*h).face_id(), value);
    return 0;
  } else if (key == "position" && h->kind == ElementKind::Vertex) {
    const std::string what = name_of(*h) + ".position";
    m.set_position(VertexId(h->index), check_position(L, 3, what.c_str()));
    return 0;
  }
  return luaL_error(L, "cannot set field '%s' of %s", key.c_str(), name_of(*h).c_str());
}

// ---- meshes ---------------------------------------------------------------------------------------

MeshBox& check_mesh(lua_State* L, int arg) { return *static_cast<MeshBox*>(luaL_checkudata(L, arg, kMeshType)); }

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

// Iterator closure: upvalues mesh userdata, kind, next slot, end slot.
int mesh_iterate_step(lua_State* L) {
  const auto& mesh = static_cast<MeshBox*>(lua_touserdata(L, lua_upvalueindex(1)))->mesh;
  const auto kind = static_cast<ElementKind>(lua_tointeger(L, lua_upvalueindex(2)));
  auto i = static_cast<uint32_t>(lua_tointeger(L, lua_upvalueindex(3)));
  const auto end = static_cast<uint32_t>(lua_tointeger(L, lua_upvalueindex(4)));
  while (i < end && !mesh->alive(ElementRef(kind, i))) ++i;
  if (i >= end) return 0;
  lua_pushinteger(L, i + 1);
  lua_replace(L, lua_upvalueindex(3));
  push_handle(L, mesh, ElementRef(kind, i));
  return 1;
}

template <ElementKind K>
int mesh_iterate(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  lua_pushvalue(L, 1);
  lua_pushinteger(L, static_cast<lua_Integer>(K));
  lua_pushinteger(L, 0);
  lua_pushinteger(L, box.mesh->capacity(K));
  lua_pushcclosure(L, mesh_iterate_step, 4);
  return 1;
}

template <ElementKind K>
int mesh_element(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  const lua_Integer i = luaL_checkinteger(L, 2);
  const uint32_t capacity = box.mesh->capacity(K);
  if (i < 0 || i >= lua_Integer(capacity)) {
    return luaL_error(L, "no %s with id %I in this mesh (%s ids go from 0 to %d)", kind_name(K), i, kind_name(K),
                      int(capacity) - 1);
  }
  push_handle(L, box.mesh, ElementRef(K, static_cast<uint32_t>(i)));
  return 1;
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

int push_refusal(lua_State* L, const Check& check) {
  lua_pushnil(L);
  lua_pushstring(L, check.reason.c_str());
  return 2;
}

Handle& check_edge_of(lua_State* L, MeshBox& box) {
  Handle& e = check_handle(L, 2, ElementKind::Edge);
  if (e.mesh != box.mesh) luaL_error(L, "%s belongs to another mesh", name_of(e).c_str());
  return e;
}

// mesh:flip(e), mesh:split(e), mesh:collapse(e): the element the core returns, or nil and the reason.
template <class Operation>
int run_edge_operation(lua_State* L, Operation operation) {
  MeshBox& box = check_mesh(L, 1);
  Handle& e = check_edge_of(L, box);
  const auto result = operation(*box.mesh, EdgeId(e.index));
  if (!result.ok()) return push_refusal(L, result.check);
  push_handle(L, box.mesh, result.value);
  return 1;
}

int mesh_flip(lua_State* L) {
  return run_edge_operation(L, [](HalfedgeMesh& mesh, EdgeId e) { return flip(mesh, e); });
}
int mesh_split(lua_State* L) {
  return run_edge_operation(L, [](HalfedgeMesh& mesh, EdgeId e) { return split(mesh, e); });
}
int mesh_collapse(lua_State* L) {
  return run_edge_operation(L, [](HalfedgeMesh& mesh, EdgeId e) { return collapse(mesh, e); });
}

// One loop_subdivide call runs in C++, out of the instruction hook's reach, and quadruples the faces; past
// this many faces it is refused so that a script repeating it cannot exhaust memory or time inside one call.
constexpr size_t kMaxSubdividedFaces = size_t(1) << 22;

int mesh_loop_subdivide(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  const size_t faces_after = 4 * box.mesh->num_faces();
  if (faces_after > kMaxSubdividedFaces) {
    return push_refusal(L, Check::no("loop subdivision would make " + std::to_string(faces_after) +
                                     " faces; scripts may make at most " + std::to_string(kMaxSubdividedFaces)));
  }
  const Check check = loop_subdivide(*box.mesh);
  if (!check.ok) return push_refusal(L, check);
  lua_pushboolean(L, 1);
  return 1;
}

int mesh_validate(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  const ValidationReport report = validate(*box.mesh);
  lua_pushboolean(L, report.ok());
  lua_createtable(L, 0, 3);
  lua_pushstring(L, report.summary().c_str());
  lua_setfield(L, -2, "summary");
  lua_pushinteger(L, static_cast<lua_Integer>(report.total));
  lua_setfield(L, -2, "total");
  lua_createtable(L, static_cast<int>(report.violations.size()), 0);
  for (size_t i = 0; i < report.violations.size(); ++i) {
    const Violation& v = report.violations[i];
    lua_createtable(L, 0, 3);
    push_handle(L, box.mesh, v.element);
    lua_setfield(L, -2, "element");
    lua_pushstring(L, invariant_name(v.invariant));
    lua_setfield(L, -2, "invariant");
    lua_pushstring(L, v.message.c_str());
    lua_setfield(L, -2, "message");
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
  Handle* h = test_handle(L, 2);
  if (!h) return luaL_typeerror(L, 2, "element");
  if (h->mesh != box.mesh) return luaL_error(L, "%s belongs to another mesh", name_of(*h).c_str());
  lua_pushboolean(L, box.mesh->alive(ref_of(*h)));
  return 1;
}

int mesh_copy(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  push_mesh(L, std::make_shared<HalfedgeMesh>(*box.mesh));
  return 1;
}

// ---- module functions ------------------------------------------------------------------------------

int module_load(lua_State* L) {
  push_mesh(L, std::make_shared<HalfedgeMesh>(build_halfedge_mesh(load_mesh(luaL_checkstring(L, 1)))));
  return 1;
}

template <PolygonMesh (*Make)()>
int module_primitive(lua_State* L) {
  push_mesh(L, std::make_shared<HalfedgeMesh>(build_halfedge_mesh(Make())));
  return 1;
}

int module_grid(lua_State* L) {
  const lua_Integer nx = luaL_checkinteger(L, 1);
  const lua_Integer ny = luaL_checkinteger(L, 2);
  luaL_argcheck(L, nx >= 1 && nx <= 1000, 1, "must be between 1 and 1000");
  luaL_argcheck(L, ny >= 1 && ny <= 1000, 2, "must be between 1 and 1000");
  push_mesh(L, std::make_shared<HalfedgeMesh>(
                   build_halfedge_mesh(make_grid(static_cast<uint32_t>(nx), static_cast<uint32_t>(ny)))));
  return 1;
}

}  // namespace

void push_mesh(lua_State* L, std::shared_ptr<HalfedgeMesh> mesh) {
  auto* box = static_cast<MeshBox*>(lua_newuserdatauv(L, sizeof(MeshBox), 0));
  new (box) MeshBox{std::move(mesh)};
  luaL_setmetatable(L, kMeshType);
}

std::shared_ptr<HalfedgeMesh> to_mesh(lua_State* L, int index) {
  auto* box = static_cast<MeshBox*>(luaL_testudata(L, index, kMeshType));
  return box ? box->mesh : nullptr;
}

void open_mesh_bindings(lua_State* L) {
  const luaL_Reg handle_meta[] = {{"__gc", handle_gc},
                                  {"__tostring", handle_tostring},
                                  {"__eq", handle_eq},
                                  {"__index", guarded<handle_index>},
                                  {"__newindex", guarded<handle_newindex>},
                                  {nullptr, nullptr}};
  for (ElementKind kind : kAllKinds) {
    luaL_newmetatable(L, kind_name(kind));  // also sets __name, which Lua's "bad argument" messages show
    luaL_setfuncs(L, handle_meta, 0);
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);
  }

  const luaL_Reg mesh_methods[] = {
      {"halfedges", guarded<mesh_iterate<ElementKind::Halfedge>>},
      {"vertices", guarded<mesh_iterate<ElementKind::Vertex>>},
      {"edges", guarded<mesh_iterate<ElementKind::Edge>>},
      {"faces", guarded<mesh_iterate<ElementKind::Face>>},
      {"boundaries", guarded<mesh_iterate<ElementKind::Boundary>>},
      {"halfedge", guarded<mesh_element<ElementKind::Halfedge>>},
      {"vertex", guarded<mesh_element<ElementKind::Vertex>>},
      {"edge", guarded<mesh_element<ElementKind::Edge>>},
      {"face", guarded<mesh_element<ElementKind::Face>>},
      {"boundary", guarded<mesh_element<ElementKind::Boundary>>},
      {"num_halfedges", guarded<mesh_count<ElementKind::Halfedge>>},
      {"num_vertices", guarded<mesh_count<ElementKind::Vertex>>},
      {"num_edges", guarded<mesh_count<ElementKind::Edge>>},
      {"num_faces", guarded<mesh_count<ElementKind::Face>>},
      {"num_boundaries", guarded<mesh_count<ElementKind::Boundary>>},
      {"flip", guarded<mesh_flip>},
      {"split", guarded<mesh_split>},
      {"collapse", guarded<mesh_collapse>},
      {"loop_subdivide", guarded<mesh_loop_subdivide>},
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
  luaL_newlib(L, mesh_methods);
  lua_setfield(L, -2, "__index");
  lua_pop(L, 1);

  // Registered as a loaded module too, so Lua's messages name functions "meshedit.grid" even through pcall.
  luaL_requiref(
      L, "meshedit",
      [](lua_State* state) {
        const luaL_Reg functions[] = {{"load", guarded<module_load>},
                                      {"cube", guarded<module_primitive<make_cube>>},
                                      {"tetrahedron", guarded<module_primitive<make_tetrahedron>>},
                                      {"icosahedron", guarded<module_primitive<make_icosahedron>>},
                                      {"grid", guarded<module_grid>},
                                      {nullptr, nullptr}};
        luaL_newlib(state, functions);
        return 1;
      },
      1);
  lua_pop(L, 1);
}

}  // namespace meshedit
