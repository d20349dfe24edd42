// The reference solutions as Lua C functions over the core (see reference_functions.h).
#include "script/reference_functions.h"

#include <algorithm>
#include <array>
#include <span>

#include <lua.hpp>

#include "core/bezier.h"
#include "core/loop_subdivision.h"
#include "core/normals.h"
#include "script/internal/binding_support.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

constexpr size_t kMaxPoints = 1024;

int upsample(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  if (4 * box.mesh->num_faces() > kMaxSubdividedFaces) return luaL_error(L, "upsample: the mesh is too large");
  const Check check = loop_subdivide(*box.mesh);
  if (!check.ok) return luaL_error(L, "upsample: %s", check.reason.c_str());
  return 0;
}

int vertex_normal_function(lua_State* L) {
  Handle& v = check_handle(L, 1, ElementKind::Vertex);
  check_alive(L, v);
  push_vec3(L, vertex_normal(v.m(), VertexId(v.index)));
  return 1;
}

std::vector<glm::dvec3> read_points(lua_State* L, int index, const char* what) {
  luaL_checktype(L, index, LUA_TTABLE);
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
  if (n > lua_Integer(kMaxPoints)) luaL_error(L, "%s: more than %d points", what, int(kMaxPoints));
  std::vector<glm::dvec3> points;
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, i);
    points.push_back(check_vec3(L, lua_gettop(L), what));
    lua_pop(L, 1);
  }
  return points;
}

int evaluate_step(lua_State* L) {
  const std::vector<glm::dvec3> points = read_points(L, 1, "points");
  const double t = luaL_checknumber(L, 2);
  const std::vector<glm::dvec3> next =
      points.empty() ? points : de_casteljau_step(std::span<const glm::dvec3>(points), t);
  lua_createtable(L, static_cast<int>(next.size()), 0);
  for (size_t i = 0; i < next.size(); ++i) {
    push_vec3(L, next[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int evaluate(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_getfield(L, 1, "points");
  const std::vector<glm::dvec3> points = read_points(L, lua_gettop(L), "patch.points");
  if (points.size() != 16) return luaL_error(L, "patch.points must hold 16 points, not %d", int(points.size()));
  BezierPatch patch;
  std::copy(points.begin(), points.end(), patch.points.begin());
  push_vec3(L, evaluate_patch(patch, luaL_checknumber(L, 2), luaL_checknumber(L, 3)));
  return 1;
}

struct Reference {
  const char* name;
  lua_CFunction function;
};

const std::array<Reference, 6> kReferences = {{{"flip_edge", guarded<mesh_flip>},
                                               {"split_edge", guarded<mesh_split>},
                                               {"upsample", guarded<upsample>},
                                               {"vertex_normal", guarded<vertex_normal_function>},
                                               {"evaluate_step", guarded<evaluate_step>},
                                               {"evaluate", guarded<evaluate>}}};

}  // namespace

const std::vector<std::string>& reference_function_names() {
  static const std::vector<std::string> kNames = [] {
    std::vector<std::string> v;
    for (const auto& r : kReferences) v.emplace_back(r.name);
    return v;
  }();
  return kNames;
}

bool is_reference_function(const std::string& name) {
  const auto& names = reference_function_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool install_reference_function(lua_State* L, const std::string& name) {
  for (const auto& r : kReferences) {
    if (name == r.name) {
      lua_pushcfunction(L, r.function);
      lua_setglobal(L, r.name);
      return true;
    }
  }
  return false;
}

}  // namespace meshedit
