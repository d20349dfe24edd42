// The functions of the `meshedit` table that make meshes: load, the primitives, grid, from_polygons and repair.
//
//   meshedit.load(path [, {repair = true}]) -> mesh [, report]
//   meshedit.repair(positions, polygons) -> mesh, report        report = {summary = "...", changes = {"...", ...}}
// With repair, the polygons go through repair_polygons (core/mesh_repair.h) before building; the report's numbers
// are the file's (0-based) or, for repair(), the tables' entries minus one, as from_polygons' messages say.
//
// Invariants: every mesh made here is a script-made copy charged to the state's storage budget
// (binding_state.h); from_polygons checks the Lua tables itself and names the offending entry in Lua's 1-based
// terms ("polygons[3][2] is 7, but there are only 4 positions"); the builder's own refusals (non-manifold
// input) keep its 0-based face and vertex numbers, which are the new mesh's ids, and say how they map.
#include <string>

#include <lua.hpp>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"
#include "script/mesh_bindings.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

// Pushes the repair report as {summary = "...", changes = {"...", ...}}.
void push_repair_report(lua_State* L, const RepairReport& report) {
  lua_createtable(L, 0, 2);
  lua_pushstring(L, report.summary().c_str());
  lua_setfield(L, -2, "summary");
  lua_createtable(L, static_cast<int>(report.changes.size()), 0);
  for (size_t i = 0; i < report.changes.size(); ++i) {
    lua_pushstring(L, report.changes[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "changes");
}

// Repairs, builds and pushes the mesh and its report; a build refusal after repair names `what`.
int push_repaired(lua_State* L, const PolygonMesh& polygons, const std::string& what) {
  const RepairResult repaired = repair_polygons(polygons);
  HalfedgeMesh mesh;
  try {
    mesh = build_halfedge_mesh(repaired.polygons);
  } catch (const MeshError& e) {
    throw MeshError(what + ": still not a manifold after repair (" + repaired.report.summary() + "): " + e.what());
  }
  push_mesh(L, own_mesh(L, std::move(mesh)));
  push_repair_report(L, repaired.report);
  return 2;
}

int module_load(lua_State* L) {
  const char* path = luaL_checkstring(L, 1);
  bool repair = false;
  if (!lua_isnoneornil(L, 2)) {
    luaL_checktype(L, 2, LUA_TTABLE);
    lua_getfield(L, 2, "repair");
    repair = lua_toboolean(L, -1);
    lua_pop(L, 1);
  }
  if (repair) return push_repaired(L, load_mesh(path), path);
  push_mesh(L, own_mesh(L, build_halfedge_mesh(load_mesh(path))));
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

// The polygons of from_polygons' and repair's two tables (checked, with 1-based messages).
PolygonMesh read_polygons(lua_State* L) {
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
  return polygons;
}

// meshedit.from_polygons(positions, polygons).
int module_from_polygons(lua_State* L) {
  const PolygonMesh polygons = read_polygons(L);
  HalfedgeMesh mesh;
  try {
    mesh = build_halfedge_mesh(polygons);
  } catch (const MeshError& e) {
    throw MeshError(
        std::string("from_polygons: ") + e.what() + " (face k is polygons[k+1], vertex k is positions[k+1])",
        e.element());
  }
  push_mesh(L, own_mesh(L, std::move(mesh)));
  return 1;
}

// meshedit.repair(positions, polygons).
int module_repair(lua_State* L) { return push_repaired(L, read_polygons(L), "repair"); }

}  // namespace

void add_module_functions(lua_State* L) {
  const luaL_Reg functions[] = {{"load", guarded<module_load>},
                                {"cube", guarded<module_primitive<make_cube>>},
                                {"tetrahedron", guarded<module_primitive<make_tetrahedron>>},
                                {"icosahedron", guarded<module_primitive<make_icosahedron>>},
                                {"grid", guarded<module_grid>},
                                {"from_polygons", guarded<module_from_polygons>},
                                {"repair", guarded<module_repair>},
                                {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
}

}  // namespace meshedit
