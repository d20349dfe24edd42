// The per-element methods of handles: degree, is_boundary, prev, set_neighbors, and the iterators around faces
// and vertices (see handle_methods.h for the list).
//
// Invariants: `self` must be a live handle of a kind that has the method; set_neighbors writes each of its
// five fields through write_pointer (so each is journaled and recorded); walks stop after halfedge_capacity()
// steps and check every id before following it; a walk that does not close raises an error saying so instead
// of returning part of the answer.
#include "script/internal/handle_methods.h"

#include <iterator>
#include <vector>

#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"
#include "script/internal/handle_context.h"
#include "script/internal/handle_fields.h"

namespace meshedit {
namespace {

constexpr uint8_t kFaces = uint8_t(kind_bit(ElementKind::Face) | kind_bit(ElementKind::Boundary));
constexpr uint8_t kVertexOrFaces = uint8_t(kind_bit(ElementKind::Vertex) | kFaces);
constexpr uint8_t kAllKindBits =
    uint8_t(kVertexOrFaces | kind_bit(ElementKind::Halfedge) | kind_bit(ElementKind::Edge));

// `self` of an element method: a live handle of one of `kinds`.
Handle& check_self(lua_State* L, uint8_t kinds, const char* expected) {
  Handle* h = context_handle(L, handle_context(L), 1);
  if (!h || !(kinds & kind_bit(h->kind))) luaL_typeerror(L, 1, expected);
  check_alive(L, *h);
  return *h;
}

// The element in Lua slot `index` as a value for a pointer of kind `wanted`: invalid for nil, else a live handle
// of `owner`'s mesh ("bad argument #2 to 'set_neighbors' (halfedge expected, got vertex)").
ElementRef pointer_value(lua_State* L, int index, const Handle& owner, ElementKind wanted) {
  if (lua_isnil(L, index)) return ElementRef(wanted, kInvalidIndex);
  Handle* value = context_handle(L, handle_context(L), index);
  if (!value || !accepts(wanted, value->kind)) luaL_typeerror(L, index, kind_name(wanted));
  check_storable(L, owner.mesh(), *value);
  return value->ref();
}

int element_degree(lua_State* L) {
  Handle& h = check_self(L, kVertexOrFaces, "vertex or face");
  const HalfedgeMesh& m = h.m();
  lua_pushinteger(L, h.kind == ElementKind::Vertex ? m.degree(VertexId(h.index)) : m.degree(h.ref().face_id()));
  return 1;
}

int element_is_boundary(lua_State* L) {
  Handle& h = check_self(L, kAllKindBits, "element");
  const HalfedgeMesh& m = h.m();
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
  Handle& h = check_self(L, kind_bit(ElementKind::Halfedge), "halfedge");
  luaL_checkany(L, 6);  // all five are required (nil is a value): a forgotten face is an error, not a null
  const ElementRef values[] = {pointer_value(L, 2, h, ElementKind::Halfedge),
                               pointer_value(L, 3, h, ElementKind::Halfedge),
                               pointer_value(L, 4, h, ElementKind::Vertex), pointer_value(L, 5, h, ElementKind::Edge),
                               pointer_value(L, 6, h, ElementKind::Face)};
  const PointerField fields[] = {PointerField::Next, PointerField::Twin, PointerField::Vertex, PointerField::Edge,
                                 PointerField::Face};
  BindingState& state = *handle_context(L).state;
  for (size_t i = 0; i < std::size(fields); ++i) write_pointer(L, state, h, fields[i], values[i]);
  return 0;
}

int halfedge_prev(lua_State* L) {
  Handle& h = check_self(L, kind_bit(ElementKind::Halfedge), "halfedge");
  const HalfedgeId prev = h.m().prev(HalfedgeId(h.index));
  if (!prev.valid()) return luaL_error(L, "the next-cycle from %s does not come back to it", h.name().c_str());
  push_sibling_handle(L, h, 1, prev);
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

// Pushes an iterator over `refs` (all of kind `kind`, or invalid) as handles on the mesh of `owner` (at 1).
int push_iterator(lua_State* L, const Handle& owner, ElementKind kind, const std::vector<ElementRef>& refs) {
  push_handle_metatable(L, kind);
  const int metatable = lua_gettop(L);
  lua_createtable(L, static_cast<int>(refs.size()), 0);
  for (size_t i = 0; i < refs.size(); ++i) {
    push_sibling_handle(L, owner, 1, refs[i], metatable);
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
  const HalfedgeMesh& m = h.m();
  std::vector<ElementRef> refs;
  if (h.kind == ElementKind::Vertex) {
    std::vector<HalfedgeId> fan;
    if (!outgoing(m, VertexId(h.index), fan)) {
      return luaL_error(L, "the halfedges around %s do not close into a fan (twin, next, ... never comes back)",
                        h.name().c_str());
    }
    for (HalfedgeId o : fan) refs.push_back(Vertices ? ElementRef(m.vertex(m.twin(o))) : ElementRef(o));
  } else {
    const bool closed = m.for_each_face_halfedge(
        h.ref().face_id(), [&](HalfedgeId x) { refs.push_back(Vertices ? ElementRef(m.vertex(x)) : ElementRef(x)); });
    if (!closed) return luaL_error(L, "the next-cycle of %s does not close", h.name().c_str());
  }
  return push_iterator(L, h, Vertices ? ElementKind::Vertex : ElementKind::Halfedge, refs);
}

const HandleMethod kMethods[] = {
    {"degree", guarded<element_degree>, kVertexOrFaces},
    {"is_boundary", guarded<element_is_boundary>, kAllKindBits},
    {"set_neighbors", guarded<halfedge_set_neighbors>, kind_bit(ElementKind::Halfedge)},
    {"prev", guarded<halfedge_prev>, kind_bit(ElementKind::Halfedge)},
    {"halfedges", guarded<element_walk<false>>, kVertexOrFaces},
    {"vertices", guarded<element_walk<true>>, kFaces},
    {"neighbors", guarded<element_walk<true>>, kind_bit(ElementKind::Vertex)},
};

}  // namespace

std::span<const HandleMethod> handle_methods() { return kMethods; }

}  // namespace meshedit
