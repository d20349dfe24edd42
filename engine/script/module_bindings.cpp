// The functions of the `meshedit` table that make meshes: load, the primitives, grid and from_polygons.
//
// Invariants: every mesh made here is a script-made copy charged to the state's storage budget
// (binding_state.h); from_polygons checks the Lua tables itself and names the offending entry in Lua's 1-based
// terms ("polygons[3][2] is 7, but there are only 4 positions"); the builder's own refusals (non-manifold
// input) keep its 0-based face and vertex numbers, which are the new mesh's ids, and say how they map.
#include <string>

#include <lua.hpp>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "script/binding_state.h"
#include "script/binding_support.h"
#include "script/mesh_bindings.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

int module_load(lua_State* L) {
  push_mesh(L, own_mesh(L, build_halfedge_mesh(load_mesh(luaL_checkstring(L, 1)))));
  return 1;
}

template <PolygonMesh (*Make)()>
int module_primitive(lua_State* L) {
  push_mesh(L, own_mesh(L, build_halfedge_mesh(Make())));
  return 1;
}

int module_grid(lua_State* L) {
  const lua_Integer nx = luaL_checkinteger(L, 1);
  const lua_Integer ny = luaL_checkinteger(L, 2);
  luaL_argcheck(L, nx >= 1 && nx <= 1000, 1, "must be between 1 and 1000");
  luaL_argcheck(L, ny >= 1 && ny <= 1000, 2, "must be between 1 and 1000");
  push_mesh(L, own_mesh(L, build_halfedge_mesh(make_grid(static_cast<uint32_t>(nx), static_cast<uint32_t>(ny)))));
  return 1;
}

// The corners of polygons[i] (the table on top of the stack), as 0-based vertex indices.
void read_polygon(lua_State* L, lua_Integer i, lua_Integer num_positions, PolygonMesh& out) {
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
  if (n < 3) luaL_error(L, "from_polygons: polygons[%I] has %I corners; a polygon needs at least 3", i, n);
  std::vector<uint32_t> corners;
  corners.reserve(static_cast<size_t>(n));
  for (lua_Integer j = 1; j <= n; ++j) {
    lua_rawgeti(L, -1, j);
    int is_integer = 0;
    const lua_Integer k = lua_tointegerx(L, -1, &is_integer);
    if (!is_integer) {
      luaL_error(L, "from_polygons: polygons[%I][%I] must be an index into positions, got %s", i, j,
                 luaL_typename(L, -1));
    }
    if (k < 1 || k > num_positions) {
      luaL_error(L, "from_polygons: polygons[%I][%I] is %I, but positions go from 1 to %I", i, j, k, num_positions);
    }
    corners.push_back(static_cast<uint32_t>(k - 1));
    lua_pop(L, 1);
  }
  out.add_face(corners);
}

// meshedit.from_polygons(positions, polygons).
int module_from_polygons(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  luaL_checktype(L, 2, LUA_TTABLE);
  PolygonMesh polygons;
  const auto num_positions = static_cast<lua_Integer>(lua_rawlen(L, 1));
  if (num_positions >= lua_Integer(kInvalidIndex / 2)) luaL_error(L, "from_polygons: too many positions");
  for (lua_Integer k = 1; k <= num_positions; ++k) {
    lua_rawgeti(L, 1, k);
    const std::string what = "from_polygons: positions[" + std::to_string(k) + "]";
    polygons.add_vertex(check_vec3(L, -1, what.c_str()));
    lua_pop(L, 1);
  }
  const auto num_polygons = static_cast<lua_Integer>(lua_rawlen(L, 2));
  for (lua_Integer i = 1; i <= num_polygons; ++i) {
    if (lua_rawgeti(L, 2, i) != LUA_TTABLE) {
      luaL_error(L, "from_polygons: polygons[%I] must be a list of indices into positions, got %s", i,
                 luaL_typename(L, -1));
    }
    read_polygon(L, i, num_positions, polygons);
    lua_pop(L, 1);
  }
  HalfedgeMesh mesh;
  try {
    mesh = build_halfedge_mesh(polygons);
  } catch (const MeshError& e) {
    throw MeshError(std::string("from_polygons: ") + e.what() +
                        " (face k is polygons[k+1], vertex k is positions[k+1])",
                    e.element());
  }
  push_mesh(L, own_mesh(L, std::move(mesh)));
  return 1;
}

}  // namespace

void add_module_functions(lua_State* L) {
  const luaL_Reg functions[] = {{"load", guarded<module_load>},
                                {"cube", guarded<module_primitive<make_cube>>},
                                {"tetrahedron", guarded<module_primitive<make_tetrahedron>>},
                                {"icosahedron", guarded<module_primitive<make_icosahedron>>},
                                {"grid", guarded<module_grid>},
                                {"from_polygons", guarded<module_from_polygons>},
                                {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
}

}  // namespace meshedit
