// mesh:tables(): every live element and its stored pointers as plain Lua tables, the data behind pointer tables
// in lessons and in scripts that print them.
//
//   mesh:tables() -> {vertices = {{id="v0", halfedge="h0", position=vec3}, ...},
//                     halfedges = {{id="h0", next="h1", twin="h5", vertex="v0", edge="e0", face="f0"}, ...},
//                     edges = {{id="e0", halfedge="h0"}, ...}, faces = {{id="f0", halfedge="h0"}, ...},
//                     boundaries = {{id="b0", halfedge="h6"}, ...}}
// Invariants: lists hold live elements in id order; a pointer is the stored id as format_id prints it, dead or
// not ("-" when null); nothing is followed, so any mesh, however broken, gives its tables.
#include <lua.hpp>

#include "script/internal/binding_support.h"
#include "script/touch_recorder.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

void set_id(lua_State* L, const char* key, ElementRef ref) { set_string_field(L, key, format_id(ref)); }

template <class Range, class Fill>
void push_list(lua_State* L, const char* name, const Range& range, Fill fill) {
  lua_newtable(L);
  lua_Integer n = 0;
  for (const auto id : range) {
    lua_createtable(L, 0, 6);
    set_id(L, "id", id);
    fill(id);
    lua_rawseti(L, -2, ++n);
  }
  lua_setfield(L, -2, name);
}

int mesh_tables(lua_State* L) {
  const HalfedgeMesh& m = *check_mesh(L, 1).mesh;
  note_whole_mesh_read(L, &m, "mesh:tables()");
  lua_createtable(L, 0, 5);
  push_list(L, "vertices", m.vertices(), [&](VertexId v) {
    set_id(L, "halfedge", m.halfedge(v));
    push_vec3(L, m.position(v));
    lua_setfield(L, -2, "position");
  });
  push_list(L, "halfedges", m.halfedges(), [&](HalfedgeId h) {
    set_id(L, "next", m.next(h));
    set_id(L, "twin", m.twin(h));
    set_id(L, "vertex", m.vertex(h));
    set_id(L, "edge", m.edge(h));
    set_id(L, "face", m.face(h));
  });
  push_list(L, "edges", m.edges(), [&](EdgeId e) { set_id(L, "halfedge", m.halfedge(e)); });
  push_list(L, "faces", m.faces(), [&](FaceId f) { set_id(L, "halfedge", m.halfedge(f)); });
  push_list(L, "boundaries", m.boundaries(), [&](FaceId b) { set_id(L, "halfedge", m.halfedge(b)); });
  return 1;
}

}  // namespace

void add_table_methods(lua_State* L) {
  lua_pushcfunction(L, guarded<mesh_tables>);
  lua_setfield(L, -2, "tables");
}

}  // namespace meshedit
