// Element handles in Lua: printing and comparing them, reading and writing their fields, set_neighbors, and the
// per-element methods (degree, is_boundary, prev, and iterators around faces and vertices).
//
// Handle API (h a halfedge, v a vertex, e an edge, f a face or boundary loop):
//   tostring(x) -> "h37"; x == y; x.id (number, also for dead elements); x.kind ("halfedge"...); x.mesh
//   h.next h.twin h.vertex h.edge h.face   v.halfedge v.position (a vec3)   e.halfedge   f.halfedge
//   writable: the same fields; a pointer takes a live element of the same mesh or nil, a position a vec3 or
//   {x, y, z}; h:set_neighbors(next, twin, vertex, edge, face) (all five given; nil allowed)
//   v:degree() f:degree()   x:is_boundary()   h:prev()
//   for h in f:halfedges() / v:halfedges() (outgoing), for w in f:vertices() / v:neighbors()
// Invariants: every write goes through make_change (so it is journaled and recorded); walks stop after
// halfedge_capacity() steps and check every id before following it; a walk that does not close raises an
// error saying so instead of returning part of the answer.
#include <cstring>
#include <string>
#include <vector>

#include "core/edit_log.h"
#include "script/binding_state.h"
#include "script/binding_support.h"
#include "script/mesh_bindings.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

// Key of the handle kind in each handle metatable (its address is the key).
const char kHandleKindKey = 0;

constexpr uint8_t bit(ElementKind kind) { return uint8_t(1u << static_cast<unsigned>(kind)); }
constexpr uint8_t kFaces = uint8_t(bit(ElementKind::Face) | bit(ElementKind::Boundary));
constexpr uint8_t kVertexOrFaces = uint8_t(bit(ElementKind::Vertex) | kFaces);
constexpr uint8_t kAllKindBits = uint8_t(kVertexOrFaces | bit(ElementKind::Halfedge) | bit(ElementKind::Edge));

// ---- reading and writing pointer fields -------------------------------------------------------------------

// The kind a pointer field refers to; false if `key` is not a pointer field of elements of `kind`.
bool pointer_field(ElementKind kind, const char* key, ElementKind& target) {
  if (kind == ElementKind::Halfedge) {
    if (!std::strcmp(key, "next") || !std::strcmp(key, "twin")) target = ElementKind::Halfedge;
    else if (!std::strcmp(key, "vertex")) target = ElementKind::Vertex;
    else if (!std::strcmp(key, "edge")) target = ElementKind::Edge;
    else if (!std::strcmp(key, "face")) target = ElementKind::Face;
    else return false;
    return true;
  }
  if (std::strcmp(key, "halfedge") != 0) return false;
  target = ElementKind::Halfedge;
  return true;
}

// The stored value of pointer field `key` (pointer_field said it exists).
ElementRef read_pointer(const HalfedgeMesh& m, const Handle& h, const char* key) {
  switch (h.kind) {
    case ElementKind::Halfedge: {
      const HalfedgeId id(h.index);
      switch (key[0]) {
        case 'n': return m.next(id);
        case 't': return m.twin(id);
        case 'v': return m.vertex(id);
        case 'e': return m.edge(id);
        default: return m.face(id);
      }
    }
    case ElementKind::Vertex: return m.halfedge(VertexId(h.index));
    case ElementKind::Edge: return m.halfedge(EdgeId(h.index));
    case ElementKind::Face:
    case ElementKind::Boundary: return m.halfedge(h.ref().face_id());
  }
  return {};
}

// The element in Lua slot `index` as a value for a pointer of kind `wanted`: invalid for nil, else a live handle
// of `owner`'s mesh ("bad argument #2 to 'set_neighbors' (halfedge expected, got vertex)").
ElementRef pointer_value(lua_State* L, int index, const Handle& owner, ElementKind wanted) {
  if (lua_isnil(L, index)) return ElementRef(wanted, kInvalidIndex);
  Handle& value = check_handle(L, index, wanted);
  check_storable(L, owner.mesh, value);
  return value.ref();
}

RecordedEdit set_edit(const Handle& h, const char* field, EditValue before, EditValue value) {
  RecordedEdit edit;
  edit.what = EditKind::Set;
  edit.element = h.ref();
  edit.field = field;
  edit.before = before;
  edit.value = value;
  return edit;
}

// ---- metamethods ----------------------------------------------------------------------------------------

int handle_gc(lua_State* L) {
  static_cast<Handle*>(lua_touserdata(L, 1))->~Handle();
  return 0;
}

int handle_tostring(lua_State* L) {
  const Handle* h = test_handle(L, 1);
  lua_pushstring(L, h ? h->name().c_str() : "?");
  return 1;
}

int handle_eq(lua_State* L) {
  const Handle* a = test_handle(L, 1);
  const Handle* b = test_handle(L, 2);
  lua_pushboolean(L, a && b && a->mesh == b->mesh && a->kind == b->kind && a->index == b->index);
  return 1;
}

struct Method {
  const char* name;
  lua_CFunction function;
  uint8_t kinds;  // bit(kind) of the kinds that have it
};

// ---- methods --------------------------------------------------------------------------------------------

// `self` of an element method: a live handle of one of `kinds`.
Handle& check_self(lua_State* L, uint8_t kinds, const char* expected) {
  Handle* h = test_handle(L, 1);
  if (!h || !(kinds & bit(h->kind))) luaL_typeerror(L, 1, expected);
  check_alive(L, *h);
  return *h;
}

int element_degree(lua_State* L) {
  Handle& h = check_self(L, kVertexOrFaces, "vertex or face");
  const HalfedgeMesh& m = *h.mesh;
  lua_pushinteger(L, h.kind == ElementKind::Vertex ? m.degree(VertexId(h.index)) : m.degree(h.ref().face_id()));
  return 1;
}

int element_is_boundary(lua_State* L) {
  Handle& h = check_self(L, kAllKindBits, "element");
  const HalfedgeMesh& m = *h.mesh;
  bool result = false;
  switch (h.kind) {
    case ElementKind::Vertex: result = m.is_boundary(VertexId(h.index)); break;
    case ElementKind::Halfedge: result = m.is_boundary(HalfedgeId(h.index)); break;
    case ElementKind::Edge: result = m.is_boundary(EdgeId(h.index)); break;
    case ElementKind::Face: result = false; break;
    case ElementKind::Boundary: result = true; break;
  }
  lua_pushboolean(L, result);
  return 1;
}

int halfedge_set_neighbors(lua_State* L) {
  Handle& h = check_self(L, bit(ElementKind::Halfedge), "halfedge");
  luaL_checkany(L, 6);  // all five are required (nil is a value): a forgotten face is an error, not a null
  const ElementRef values[] = {pointer_value(L, 2, h, ElementKind::Halfedge),
                               pointer_value(L, 3, h, ElementKind::Halfedge),
                               pointer_value(L, 4, h, ElementKind::Vertex), pointer_value(L, 5, h, ElementKind::Edge),
                               pointer_value(L, 6, h, ElementKind::Face)};
  const char* fields[] = {"next", "twin", "vertex", "edge", "face"};
  for (int i = 0; i < 5; ++i) {
    make_change(L, h.mesh, set_edit(h, fields[i], {read_pointer(*h.mesh, h, fields[i]), {}}, {values[i], {}}));
  }
  return 0;
}

int halfedge_prev(lua_State* L) {
  Handle& h = check_self(L, bit(ElementKind::Halfedge), "halfedge");
  const HalfedgeId prev = h.mesh->prev(HalfedgeId(h.index));
  if (!prev.valid()) return luaL_error(L, "the next-cycle from %s does not come back to it", h.name().c_str());
  push_handle(L, h.mesh, prev);
  return 1;
}

// Iterator over the list at upvalue 1; upvalue 2 is the position.
int list_step(lua_State* L) {
  const lua_Integer i = lua_tointeger(L, lua_upvalueindex(2)) + 1;
  if (lua_rawgeti(L, lua_upvalueindex(1), i) == LUA_TNIL) return 1;
  lua_pushinteger(L, i);
  lua_replace(L, lua_upvalueindex(2));
  return 1;
}

// Pushes an iterator over `refs` as handles.
int push_iterator(lua_State* L, const Handle& owner, const std::vector<ElementRef>& refs) {
  lua_createtable(L, static_cast<int>(refs.size()), 0);
  for (size_t i = 0; i < refs.size(); ++i) {
    push_handle(L, owner.mesh, refs[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, list_step, 2);
  return 1;
}

// The outgoing halfedges of v (h, twin(h).next, ...); false if the fan does not close through live halfedges
// that leave v and have live twins.
bool outgoing(const HalfedgeMesh& m, VertexId v, std::vector<HalfedgeId>& out) {
  const HalfedgeId start = m.halfedge(v);
  HalfedgeId h = start;
  for (uint32_t steps = 0; steps <= m.halfedge_capacity(); ++steps) {
    if (!m.alive(h) || m.vertex(h) != v || !m.alive(m.twin(h))) return false;
    out.push_back(h);
    h = m.next(m.twin(h));
    if (h == start) return true;
  }
  return false;
}

// f:halfedges() f:vertices() v:halfedges() v:neighbors().
template <bool Vertices>
int element_walk(lua_State* L) {
  Handle& h = check_self(L, kVertexOrFaces, "vertex or face");
  const HalfedgeMesh& m = *h.mesh;
  std::vector<ElementRef> refs;
  if (h.kind == ElementKind::Vertex) {
    std::vector<HalfedgeId> fan;
    if (!outgoing(m, VertexId(h.index), fan)) {
      return luaL_error(L, "the halfedges around %s do not close into a fan (twin, next, ... never comes back)",
                        h.name().c_str());
    }
    for (HalfedgeId o : fan) refs.push_back(Vertices ? ElementRef(m.vertex(m.twin(o))) : ElementRef(o));
  } else {
    const bool closed = m.for_each_face_halfedge(h.ref().face_id(), [&](HalfedgeId x) {
      refs.push_back(Vertices ? ElementRef(m.vertex(x)) : ElementRef(x));
    });
    if (!closed) return luaL_error(L, "the next-cycle of %s does not close", h.name().c_str());
  }
  return push_iterator(L, h, refs);
}

const Method kMethods[] = {
    {"degree", guarded<element_degree>, kVertexOrFaces},
    {"is_boundary", guarded<element_is_boundary>, kAllKindBits},
    {"set_neighbors", guarded<halfedge_set_neighbors>, bit(ElementKind::Halfedge)},
    {"prev", guarded<halfedge_prev>, bit(ElementKind::Halfedge)},
    {"halfedges", guarded<element_walk<false>>, kVertexOrFaces},
    {"vertices", guarded<element_walk<true>>, kFaces},
    {"neighbors", guarded<element_walk<true>>, bit(ElementKind::Vertex)},
    {nullptr, nullptr, 0}};


// ---- __index and __newindex ------------------------------------------------------------------------------

int handle_index(lua_State* L) {
  Handle* h = test_handle(L, 1);
  if (!h) return luaL_typeerror(L, 1, "element");
  const char* key = luaL_checkstring(L, 2);
  if (!std::strcmp(key, "id")) {
    lua_pushinteger(L, h->index);
    return 1;
  }
  if (!std::strcmp(key, "kind")) {
    lua_pushstring(L, kind_name(h->kind));
    return 1;
  }
  check_alive(L, *h);
  const HalfedgeMesh& m = *h->mesh;
  ElementKind target;
  if (pointer_field(h->kind, key, target)) {
    push_handle(L, h->mesh, read_pointer(m, *h, key));
    return 1;
  }
  if (h->kind == ElementKind::Vertex && !std::strcmp(key, "position")) {
    push_vec3(L, m.position(VertexId(h->index)));
    return 1;
  }
  if (!std::strcmp(key, "mesh")) {
    push_mesh(L, h->mesh);
    return 1;
  }
  for (const Method* method = kMethods; method->name; ++method) {
    if ((method->kinds & bit(h->kind)) && !std::strcmp(key, method->name)) {
      lua_pushcfunction(L, method->function);
      return 1;
    }
  }
  return luaL_error(L, "%s has no field '%s'", h->name().c_str(), key);
}

int handle_newindex(lua_State* L) {
  Handle* h = test_handle(L, 1);
  if (!h) return luaL_typeerror(L, 1, "element");
  const char* key = luaL_checkstring(L, 2);
  check_alive(L, *h);
  ElementKind target;
  if (pointer_field(h->kind, key, target)) {
    ElementRef value(target, kInvalidIndex);
    if (!lua_isnil(L, 3)) {
      Handle* given = test_handle(L, 3);
      if (!given || !accepts(target, given->kind)) {
        return luaL_error(L, "%s.%s must be a %s or nil, got %s", h->name().c_str(), key, kind_name(target),
                          given ? kind_name(given->kind) : luaL_typename(L, 3));
      }
      check_storable(L, h->mesh, *given);
      value = given->ref();
    }
    make_change(L, h->mesh, set_edit(*h, key, {read_pointer(*h->mesh, *h, key), {}}, {value, {}}));
    return 0;
  }
  if (h->kind == ElementKind::Vertex && !std::strcmp(key, "position")) {
    const std::string what = h->name() + ".position";
    const glm::dvec3 p = check_vec3(L, 3, what.c_str());
    const glm::dvec3 old = h->mesh->position(VertexId(h->index));
    make_change(L, h->mesh, set_edit(*h, "position", {{}, old}, {{}, p}));
    return 0;
  }
  return luaL_error(L, "cannot set field '%s' of %s", key, h->name().c_str());
}

}  // namespace

void open_handle_metatables(lua_State* L) {
  const luaL_Reg meta[] = {{"__gc", handle_gc},
                           {"__tostring", handle_tostring},
                           {"__eq", handle_eq},
                           {"__index", guarded<handle_index>},
                           {"__newindex", guarded<handle_newindex>},
                           {nullptr, nullptr}};
  for (ElementKind kind : kAllKinds) {
    luaL_newmetatable(L, kind_name(kind));  // also sets __name, which Lua's "bad argument" messages show
    luaL_setfuncs(L, meta, 0);
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
    lua_pushinteger(L, static_cast<lua_Integer>(kind));
    lua_rawsetp(L, -2, &kHandleKindKey);
    lua_pop(L, 1);
  }
}

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
  if (lua_type(L, index) != LUA_TUSERDATA || !lua_getmetatable(L, index)) return nullptr;
  const bool is_handle = lua_rawgetp(L, -1, &kHandleKindKey) == LUA_TNUMBER;
  lua_pop(L, 2);
  return is_handle ? static_cast<Handle*>(lua_touserdata(L, index)) : nullptr;
}

Handle& check_handle(lua_State* L, int arg, ElementKind wanted) {
  Handle* h = test_handle(L, arg);
  if (!h || !accepts(wanted, h->kind)) luaL_typeerror(L, arg, kind_name(wanted));
  return *h;
}

Handle& check_any_handle(lua_State* L, int arg) {
  Handle* h = test_handle(L, arg);
  if (!h) luaL_typeerror(L, arg, "element");
  return *h;
}

void check_alive(lua_State* L, const Handle& h) {
  if (!h.mesh->alive(h.ref())) luaL_error(L, "attempt to use dead %s %s", kind_name(h.kind), h.name().c_str());
}

void check_same_mesh(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value) {
  if (value.mesh != mesh) luaL_error(L, "%s belongs to another mesh", value.name().c_str());
}

void check_storable(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, const Handle& value) {
  check_same_mesh(L, mesh, value);
  check_alive(L, value);
}

}  // namespace meshedit
