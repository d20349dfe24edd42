// __index and __newindex of element handles, and the pointer reads and writes they share with set_neighbors
// (see handle_fields.h for the fields and the invariants).
//
// How a key is found: the two accessors are C closures shared by the handle metatables. Upvalue 1 is the
// state's HandleContext (handle_context.h), which holds the addresses of the interned key strings ("next",
// "twin", ... and the method names; a key is compared by address first); the next kElementKindCount upvalues are
// the handle metatables in kAllKinds order, which a new handle of each kind gets without a lookup by name; __index's
// upvalues after them are the methods, as closures over the same context, in handle_methods() order.
#include "script/internal/handle_fields.h"

#include <cstring>
#include <iterator>
#include <string>

#include "core/edit_log.h"
#include "script/internal/binding_state.h"
#include "script/internal/handle_context.h"
#include "script/internal/handle_methods.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

// The keys, in this order: the six pointer fields (a pointer field's Key is its PointerField), then these, then the
// methods. pointer_key reads the halfedge's fields as the keys below kHalfedgeKey, and field_name reads kKeyNames by
// PointerField: the asserts hold PointerField to that order.
enum Key : int { kHalfedgeKey = static_cast<int>(PointerField::Halfedge), kPosition, kId, kKind, kMesh, kFirstMethod };
constexpr const char* kKeyNames[] = {"next",     "twin",     "vertex", "edge", "face",
                                     "halfedge", "position", "id",     "kind", "mesh"};
static_assert(std::size(kKeyNames) == kFirstMethod);
static_assert(static_cast<int>(PointerField::Next) == 0 && static_cast<int>(PointerField::Twin) == 1 &&
                  static_cast<int>(PointerField::Vertex) == 2 && static_cast<int>(PointerField::Edge) == 3 &&
                  static_cast<int>(PointerField::Face) == 4 && static_cast<int>(PointerField::Halfedge) == 5,
              "PointerField is in the order of kKeyNames, with the halfedge's own fields before Halfedge");
constexpr int kFirstMetatable = 2;  // upvalue of kAllKinds[0]'s metatable
constexpr int kFirstMethodUpvalue = kFirstMetatable + kElementKindCount;

int metatable_upvalue(ElementKind kind) { return lua_upvalueindex(kFirstMetatable + static_cast<int>(kind)); }

// Argument 1 of __index and __newindex. The VM calls them only for values whose metatable is a handle
// metatable (the closures are reachable from nowhere else: the metatables are protected and there is no debug
// library), so that value is a handle; the null test only keeps a misuse from C++ from reading garbage.
Handle* accessor_self(lua_State* L) {
  auto* h = static_cast<Handle*>(lua_touserdata(L, 1));
  if (!h) luaL_typeerror(L, 1, "element");
  return h;
}

// The Key of the key at `index`, or -1. Raises as luaL_checkstring does for a key that is neither a string
// nor a number (a number is turned into its text in place, for the error message).
int find_key(lua_State* L, const HandleContext& c, int index) {
  const char* key = lua_tolstring(L, index, nullptr);
  if (!key) {
    luaL_checkstring(L, index);
    return -1;
  }
  for (int i = 0; i < c.key_count; ++i) {
    if (c.keys[i] == key) return i;
  }
  for (int i = 0; i < c.key_count; ++i) {  // never expected: every short string is interned
    if (!std::strcmp(c.keys[i], key)) return i;
  }
  return -1;
}

// The pointer field `key` names for elements of `kind`, or false.
bool pointer_key(ElementKind kind, int key, PointerField& field) {
  const bool ok = kind == ElementKind::Halfedge ? key >= 0 && key < kHalfedgeKey : key == kHalfedgeKey;
  if (ok) field = static_cast<PointerField>(key);
  return ok;
}

RecordedEdit set_edit(const Handle& h, const char* field, EditValue before, EditValue value) {
  return RecordedEdit{EditKind::Set, h.ref(), field, before, value, nullptr, {}};
}

int handle_index(lua_State* L) {
  const HandleContext& c = handle_context(L);
  Handle* h = accessor_self(L);
  const int key = find_key(L, c, 2);
  if (key == kId) {
    lua_pushinteger(L, h->index);
    return 1;
  }
  if (key == kKind) {
    lua_pushstring(L, kind_name(h->kind));
    return 1;
  }
  check_alive(L, *h);
  const HalfedgeMesh& m = h->m();
  PointerField field;
  if (pointer_key(h->kind, key, field)) {
    const ElementRef ref = read_pointer(m, *h, field);
    push_sibling_handle(L, *h, 1, ref, ref.valid() ? metatable_upvalue(ref.kind) : 0);
    return 1;
  }
  if (key == kPosition && h->kind == ElementKind::Vertex) {
    push_vec3(L, m.position(VertexId(h->index)));
    return 1;
  }
  if (key == kMesh) {
    lua_getiuservalue(L, 1, 1);
    return 1;
  }
  if (key >= kFirstMethod) {
    const HandleMethod& method = handle_methods()[static_cast<size_t>(key - kFirstMethod)];
    if (method.kinds & kind_bit(h->kind)) {
      lua_pushvalue(L, lua_upvalueindex(kFirstMethodUpvalue + key - kFirstMethod));
      return 1;
    }
  }
  return luaL_error(L, "%s has no field '%s'", h->name().c_str(), lua_tostring(L, 2));
}

int handle_newindex(lua_State* L) {
  const HandleContext& c = handle_context(L);
  Handle* h = accessor_self(L);
  const int key = find_key(L, c, 2);
  check_alive(L, *h);
  PointerField field;
  if (pointer_key(h->kind, key, field)) {
    const ElementKind target = field_target(field);
    ElementRef value(target, kInvalidIndex);
    if (!lua_isnil(L, 3)) {
      const Handle* given = context_handle(L, c, 3);
      if (!given || !accepts(target, given->kind)) {
        return luaL_error(L, "%s.%s must be a %s or nil, got %s", h->name().c_str(), field_name(field),
                          kind_name(target), given ? kind_name(given->kind) : luaL_typename(L, 3));
      }
      check_storable(L, h->mesh(), *given);
      value = given->ref();
    }
    write_pointer(L, *c.state, *h, field, value);
    return 0;
  }
  if (key == kPosition && h->kind == ElementKind::Vertex) {
    const std::string what = h->name() + ".position";
    const glm::dvec3 p = check_vec3(L, 3, what.c_str());
    const glm::dvec3 old = h->m().position(VertexId(h->index));
    make_change(L, *c.state, h->mesh(), set_edit(*h, "position", {{}, old}, {{}, p}));
    return 0;
  }
  return luaL_error(L, "cannot set field '%s' of %s", lua_tostring(L, 2), h->name().c_str());
}

}  // namespace

const char* field_name(PointerField field) { return kKeyNames[static_cast<int>(field)]; }

ElementKind field_target(PointerField field) {
  switch (field) {
    case PointerField::Next:
    case PointerField::Twin:
    case PointerField::Halfedge: return ElementKind::Halfedge;
    case PointerField::Vertex: return ElementKind::Vertex;
    case PointerField::Edge: return ElementKind::Edge;
    case PointerField::Face: return ElementKind::Face;
  }
  return ElementKind::Halfedge;
}

ElementRef read_pointer(const HalfedgeMesh& m, const Handle& h, PointerField field) {
  switch (h.kind) {
    case ElementKind::Halfedge: {
      const HalfedgeId id(h.index);
      switch (field) {
        case PointerField::Next: return m.next(id);
        case PointerField::Twin: return m.twin(id);
        case PointerField::Vertex: return m.vertex(id);
        case PointerField::Edge: return m.edge(id);
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

void write_pointer(lua_State* L, BindingState& state, const Handle& h, PointerField field, ElementRef value) {
  make_change(L, state, h.mesh(), set_edit(h, field_name(field), {read_pointer(h.m(), h, field), {}}, {value, {}}));
}

void set_handle_accessors(lua_State* L, int context, int first) {
  context = lua_absindex(L, context);
  first = lua_absindex(L, first);
  auto* c = static_cast<HandleContext*>(lua_touserdata(L, context));
  lua_createtable(L, kMaxHandleKeys, 0);  // keeps the key strings alive
  const auto add_key = [&](const char* name) {
    if (c->key_count == kMaxHandleKeys) luaL_error(L, "too many handle keys");
    c->keys[c->key_count] = lua_pushstring(L, name);
    lua_rawseti(L, -2, ++c->key_count);
  };
  for (const char* name : kKeyNames) add_key(name);
  for (const HandleMethod& method : handle_methods()) add_key(method.name);
  lua_setiuservalue(L, context, 1);

  const auto push_upvalues = [&] {
    lua_pushvalue(L, context);
    for (int k = 0; k < kElementKindCount; ++k) lua_pushvalue(L, first + k);
  };
  push_upvalues();
  for (const HandleMethod& method : handle_methods()) {
    lua_pushvalue(L, context);
    lua_pushcclosure(L, method.function, 1);
  }
  lua_pushcclosure(L, guarded<handle_index>, kFirstMethodUpvalue - 1 + static_cast<int>(handle_methods().size()));
  push_upvalues();
  lua_pushcclosure(L, guarded<handle_newindex>, kFirstMethodUpvalue - 1);
  for (int k = 0; k < kElementKindCount; ++k) {
    lua_pushvalue(L, -1);
    lua_setfield(L, first + k, "__newindex");
    lua_pushvalue(L, -2);
    lua_setfield(L, first + k, "__index");
  }
  lua_pop(L, 2);
}

}  // namespace meshedit
