// Bézier curves and patches for scripts (see bezier_bindings.h for the API and its invariants). Every result
// comes from core/bezier.h unchanged; this file only converts between Lua tables and glm vectors.
#include "script/bezier_bindings.h"

#include <exception>
#include <new>
#include <span>
#include <string>

#include <lua.hpp>

#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "script/internal/binding_support.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

constexpr const char* kCurveType = "curve";  // also the type name in "curve expected" messages
constexpr const char* kPatchType = "patch";

struct CurveBox {
  std::vector<glm::dvec3> points;
};
struct PatchBox {
  BezierPatch patch;
};

// ---- conversions ------------------------------------------------------------------------------------

void push_points(lua_State* L, std::span<const glm::dvec3> points) {
  lua_createtable(L, static_cast<int>(points.size()), 0);
  for (size_t i = 0; i < points.size(); ++i) {
    push_vec3(L, points[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

void push_levels(lua_State* L, const std::vector<std::vector<glm::dvec3>>& levels) {
  lua_createtable(L, static_cast<int>(levels.size()), 0);
  for (size_t k = 0; k < levels.size(); ++k) {
    push_points(L, levels[k]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
}

// The list of points at argument `arg` (raw reads: a table's metamethods never run here). Raises a
// "bad argument" error naming the first point that is not a point, or a list longer than `max_points`.
std::vector<glm::dvec3> check_points(lua_State* L, int arg, size_t max_points) {
  luaL_checktype(L, arg, LUA_TTABLE);
  const lua_Unsigned n = lua_rawlen(L, arg);
  if (n > max_points) {
    const std::string message =
        "at most " + std::to_string(max_points) + " points are allowed, got " + std::to_string(n);
    luaL_argerror(L, arg, message.c_str());
  }
  std::vector<glm::dvec3> points;
  points.reserve(n);
  for (lua_Unsigned i = 1; i <= n; ++i) {
    lua_rawgeti(L, arg, static_cast<lua_Integer>(i));
    glm::dvec3 p;
    if (!to_vec3(L, -1, p)) {
      const std::string message =
          "point " + std::to_string(i) + " must be a vec3 or a table {x, y, z} of numbers, got " + luaL_typename(L, -1);
      luaL_argerror(L, arg, message.c_str());
    }
    lua_pop(L, 1);
    points.push_back(p);
  }
  return points;
}

CurveBox& check_curve(lua_State* L, int arg) { return *static_cast<CurveBox*>(luaL_checkudata(L, arg, kCurveType)); }
PatchBox& check_patch(lua_State* L, int arg) { return *static_cast<PatchBox*>(luaL_checkudata(L, arg, kPatchType)); }

// ---- curves -----------------------------------------------------------------------------------------

int module_curve(lua_State* L) {
  std::vector<glm::dvec3> points = check_points(L, 1, kMaxCurvePoints);
  luaL_argcheck(L, !points.empty(), 1, "a curve needs at least one control point");
  push_curve(L, points);
  return 1;
}

int curve_evaluate(lua_State* L) {
  const CurveBox& c = check_curve(L, 1);
  push_vec3(L, evaluate_curve(std::span<const glm::dvec3>(c.points), luaL_checknumber(L, 2)));
  return 1;
}

int curve_levels(lua_State* L) {
  const CurveBox& c = check_curve(L, 1);
  push_levels(L, de_casteljau_levels(std::span<const glm::dvec3>(c.points), luaL_checknumber(L, 2)));
  return 1;
}

int curve_step(lua_State* L) {
  check_curve(L, 1);
  const std::vector<glm::dvec3> points = check_points(L, 2, kMaxCurvePoints);
  push_points(L, de_casteljau_step(std::span<const glm::dvec3>(points), luaL_checknumber(L, 3)));
  return 1;
}

int curve_split(lua_State* L) {
  const CurveBox& c = check_curve(L, 1);
  const CurveSplit<glm::dvec3> halves = split_curve(std::span<const glm::dvec3>(c.points), luaL_checknumber(L, 2));
  push_curve(L, halves.left);
  push_curve(L, halves.right);
  return 2;
}

int curve_index(lua_State* L) {
  const CurveBox& c = check_curve(L, 1);
  const char* key = luaL_checkstring(L, 2);
  if (std::string(key) == "points") {
    push_points(L, c.points);
    return 1;
  }
  lua_getmetatable(L, 1);
  lua_getfield(L, -1, "methods");
  if (lua_getfield(L, -1, key) != LUA_TNIL) return 1;
  return luaL_error(L, "curve has no field '%s'", key);
}

int curve_len(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(check_curve(L, 1).points.size()));
  return 1;
}

int curve_tostring(lua_State* L) {
  const size_t n = check_curve(L, 1).points.size();
  lua_pushfstring(L, "curve (%d point%s)", static_cast<int>(n), n == 1 ? "" : "s");
  return 1;
}

int curve_gc(lua_State* L) {
  static_cast<CurveBox*>(lua_touserdata(L, 1))->~CurveBox();
  return 0;
}

int module_load_curve(lua_State* L) {
  const BezierCurve curve = read_bzc(luaL_checkstring(L, 1));
  std::vector<glm::dvec3> points;
  points.reserve(curve.control_points.size());
  for (const glm::dvec2& p : curve.control_points) points.emplace_back(p.x, p.y, 0.0);
  push_curve(L, points);
  return 1;
}

// ---- patches ----------------------------------------------------------------------------------------

int module_patch(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  const lua_Unsigned n = lua_rawlen(L, 1);
  if (n != 16) {
    const std::string message = "a patch needs 16 control points (4 rows of 4), got " + std::to_string(n);
    luaL_argerror(L, 1, message.c_str());
  }
  const std::vector<glm::dvec3> points = check_points(L, 1, 16);
  BezierPatch patch;
  for (size_t i = 0; i < 16; ++i) patch.points[i] = points[i];
  push_patch(L, patch);
  return 1;
}

int patch_evaluate(lua_State* L) {
  const PatchBox& p = check_patch(L, 1);
  push_vec3(L, evaluate_patch(p.patch, luaL_checknumber(L, 2), luaL_checknumber(L, 3)));
  return 1;
}

int patch_rows(lua_State* L) {
  const PatchBox& p = check_patch(L, 1);
  // evaluate_patch_steps at v = 0 computes the rows exactly as evaluate does.
  push_points(L, evaluate_patch_steps(p.patch, luaL_checknumber(L, 2), 0.0).row_points);
  return 1;
}

int patch_evaluation(lua_State* L) {
  const PatchBox& p = check_patch(L, 1);
  const PatchEvaluation e = evaluate_patch_steps(p.patch, luaL_checknumber(L, 2), luaL_checknumber(L, 3));
  lua_createtable(L, 0, 3);
  push_points(L, e.row_points);
  lua_setfield(L, -2, "rows");
  push_levels(L, e.column_levels);
  lua_setfield(L, -2, "column_levels");
  push_vec3(L, e.point);
  lua_setfield(L, -2, "point");
  return 1;
}

int patch_index(lua_State* L) {
  const PatchBox& p = check_patch(L, 1);
  const char* key = luaL_checkstring(L, 2);
  if (std::string(key) == "points") {
    push_points(L, p.patch.points);
    return 1;
  }
  lua_getmetatable(L, 1);
  lua_getfield(L, -1, "methods");
  if (lua_getfield(L, -1, key) != LUA_TNIL) return 1;
  return luaL_error(L, "patch has no field '%s'", key);
}

int patch_tostring(lua_State* L) {
  check_patch(L, 1);
  lua_pushliteral(L, "patch");
  return 1;
}

int module_load_patches(lua_State* L) {
  const std::vector<BezierPatch> patches = read_bez(luaL_checkstring(L, 1));
  lua_createtable(L, static_cast<int>(patches.size()), 0);
  for (size_t i = 0; i < patches.size(); ++i) {
    push_patch(L, patches[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

// Creates a metatable `name` with the given metamethods and a `methods` table its __index reads.
void register_type(lua_State* L, const char* name, const luaL_Reg* metamethods, const luaL_Reg* methods) {
  if (!luaL_newmetatable(L, name)) {  // already registered in this state
    lua_pop(L, 1);
    return;
  }
  luaL_setfuncs(L, metamethods, 0);
  lua_newtable(L);
  luaL_setfuncs(L, methods, 0);
  lua_setfield(L, -2, "methods");
  lua_pushboolean(L, 0);
  lua_setfield(L, -2, "__metatable");  // scripts cannot reach or change the methods
  lua_pop(L, 1);
}

}  // namespace

void push_curve(lua_State* L, const std::vector<glm::dvec3>& points) {
  if (points.size() > kMaxCurvePoints) {
    luaL_error(L, "a curve may have at most %d control points, got %d", static_cast<int>(kMaxCurvePoints),
               static_cast<int>(points.size()));
  }
  auto* box = static_cast<CurveBox*>(lua_newuserdatauv(L, sizeof(CurveBox), 0));
  new (box) CurveBox{points};
  luaL_setmetatable(L, kCurveType);
}

const std::vector<glm::dvec3>* to_curve(lua_State* L, int index) {
  auto* box = static_cast<CurveBox*>(luaL_testudata(L, index, kCurveType));
  return box ? &box->points : nullptr;
}

void push_patch(lua_State* L, const BezierPatch& patch) {
  auto* box = static_cast<PatchBox*>(lua_newuserdatauv(L, sizeof(PatchBox), 0));
  new (box) PatchBox{patch};
  luaL_setmetatable(L, kPatchType);
}

const BezierPatch* to_patch(lua_State* L, int index) {
  auto* box = static_cast<PatchBox*>(luaL_testudata(L, index, kPatchType));
  return box ? &box->patch : nullptr;
}

void open_bezier_bindings(lua_State* L) {
  const luaL_Reg curve_meta[] = {{"__index", guarded<curve_index>},
                                 {"__len", guarded<curve_len>},
                                 {"__tostring", guarded<curve_tostring>},
                                 {"__gc", curve_gc},
                                 {nullptr, nullptr}};
  const luaL_Reg curve_methods[] = {{"evaluate", guarded<curve_evaluate>},
                                    {"levels", guarded<curve_levels>},
                                    {"step", guarded<curve_step>},
                                    {"split", guarded<curve_split>},
                                    {nullptr, nullptr}};
  const luaL_Reg patch_meta[] = {
      {"__index", guarded<patch_index>}, {"__tostring", guarded<patch_tostring>}, {nullptr, nullptr}};
  const luaL_Reg patch_methods[] = {{"evaluate", guarded<patch_evaluate>},
                                    {"rows", guarded<patch_rows>},
                                    {"evaluation", guarded<patch_evaluation>},
                                    {nullptr, nullptr}};
  register_type(L, kCurveType, curve_meta, curve_methods);
  register_type(L, kPatchType, patch_meta, patch_methods);

  const luaL_Reg functions[] = {{"curve", guarded<module_curve>},
                                {"patch", guarded<module_patch>},
                                {"load_curve", guarded<module_load_curve>},
                                {"load_patches", guarded<module_load_patches>},
                                {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
}

}  // namespace meshedit
