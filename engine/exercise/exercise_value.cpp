// The values of an exercise on points or a patch: see exercise_value.h for the contract.
#include "exercise/exercise_value.h"

#include <algorithm>
#include <utility>

#include <lua.hpp>

#include "core/translation.h"
#include "core/value_format.h"
#include "script/bezier_bindings.h"
#include "script/lua_args.h"
#include "script/lua_handles.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

std::string other_description(lua_State* L, int index) {
  switch (lua_type(L, index)) {
    case LUA_TBOOLEAN: return lua_toboolean(L, index) ? "true" : "false";
    case LUA_TSTRING: return "a string";
    case LUA_TFUNCTION: return "a function";
    case LUA_TUSERDATA: {
      if (to_curve(L, index)) return "a curve";
      if (to_patch(L, index)) return "a patch";
      return "a userdata";
    }
    default: return std::string("a ") + lua_typename(L, lua_type(L, index));
  }
}

ExerciseValue other(std::string what) {
  ExerciseValue v;
  v.kind = ExerciseValue::Kind::Other;
  v.other = std::move(what);
  return v;
}

ExerciseValue read_value(lua_State* L, int index, size_t depth, size_t& items) {
  index = lua_absindex(L, index);
  switch (lua_type(L, index)) {
    case LUA_TNONE:
    case LUA_TNIL: return {};
    case LUA_TNUMBER: return ExerciseValue::of_number(lua_tonumber(L, index));
    case LUA_TTABLE: break;
    default: return other(other_description(L, index));
  }
  glm::dvec3 p;
  if (to_vec3(L, index, p)) return ExerciseValue::of_point(p);
  if (depth >= kMaxValueDepth) return other("a table nested deeper than " + std::to_string(kMaxValueDepth) + " levels");
  const lua_Unsigned n = lua_rawlen(L, index);
  if (n > kMaxValueItems - std::min(items, kMaxValueItems)) {
    return other("a list of " + std::to_string(n) + " values (more than " + std::to_string(kMaxValueItems) +
                 " values in all)");
  }
  items += n;
  if (!lua_checkstack(L, 4)) return other("a table nested too deep to read");
  std::vector<ExerciseValue> list;
  list.reserve(n);
  for (lua_Unsigned i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, static_cast<lua_Integer>(i));
    list.push_back(read_value(L, -1, depth + 1, items));
    lua_pop(L, 1);
  }
  return ExerciseValue::of_list(std::move(list));
}

// Whether every item of the list is of `kind`.
bool all_of_kind(const ExerciseValue& list, ExerciseValue::Kind kind) {
  return std::all_of(list.items.begin(), list.items.end(), [&](const ExerciseValue& v) { return v.kind == kind; });
}

// The first Other in `value` (itself or an item at any depth), or nullptr.
const ExerciseValue* first_other(const ExerciseValue& value) {
  if (value.kind == ExerciseValue::Kind::Other) return &value;
  for (const ExerciseValue& item : value.items) {
    if (const ExerciseValue* found = first_other(item)) return found;
  }
  return nullptr;
}

}  // namespace

ExerciseValue ExerciseValue::of_number(double x) {
  ExerciseValue v;
  v.kind = Kind::Number;
  v.number = x;
  return v;
}

ExerciseValue ExerciseValue::of_point(const glm::dvec3& p) {
  ExerciseValue v;
  v.kind = Kind::Point;
  v.point = p;
  return v;
}

ExerciseValue ExerciseValue::of_list(std::vector<ExerciseValue> items) {
  ExerciseValue v;
  v.kind = Kind::List;
  v.items = std::move(items);
  return v;
}

ExerciseValue ExerciseValue::of_points(const std::vector<glm::dvec3>& points) {
  std::vector<ExerciseValue> items;
  items.reserve(points.size());
  for (const glm::dvec3& p : points) items.push_back(of_point(p));
  return of_list(std::move(items));
}

ExerciseValue read_exercise_value(lua_State* L, int index) {
  size_t items = 0;
  return read_value(L, index, 0, items);
}

void push_exercise_value(lua_State* L, const ExerciseValue& value) {
  if (!lua_checkstack(L, 3)) {  // deeper than kMaxValueDepth never comes here: reading stops there
    lua_pushnil(L);
    return;
  }
  switch (value.kind) {
    case ExerciseValue::Kind::Number: lua_pushnumber(L, value.number); return;
    case ExerciseValue::Kind::Point: push_vec3(L, value.point); return;
    case ExerciseValue::Kind::List:
      lua_createtable(L, static_cast<int>(std::min<size_t>(value.items.size(), kMaxValueItems)), 0);
      for (size_t i = 0; i < value.items.size(); ++i) {
        push_exercise_value(L, value.items[i]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      return;
    default: lua_pushnil(L); return;
  }
}

// In the window's language (what `other` says is translated when the catalog has it: "a string").
std::string describe(const ExerciseValue& value) {
  switch (value.kind) {
    case ExerciseValue::Kind::Nil: return "nil";
    case ExerciseValue::Kind::Number:
      return tr_format("the number {number}", {{"number", format_number(value.number)}});
    case ExerciseValue::Kind::Point: return format_position(value.point);
    case ExerciseValue::Kind::Other: return tr(value.other);
    case ExerciseValue::Kind::List: break;
  }
  const size_t n = value.items.size();
  if (n == 0) return tr("an empty list");
  const MessageParts count = {{"count", std::to_string(n)}};
  if (all_of_kind(value, ExerciseValue::Kind::Point)) {
    return tr_format(n == 1 ? "a list of {count} point" : "a list of {count} points", count);
  }
  if (all_of_kind(value, ExerciseValue::Kind::Number)) {
    return tr_format(n == 1 ? "a list of {count} number" : "a list of {count} numbers", count);
  }
  if (all_of_kind(value, ExerciseValue::Kind::List)) {
    return tr_format(n == 1 ? "a list of {count} list" : "a list of {count} lists", count);
  }
  return tr_format(n == 1 ? "a list of {count} value" : "a list of {count} values", count);
}

std::string value_text(const ExerciseValue& value) {
  switch (value.kind) {
    case ExerciseValue::Kind::Nil: return "nil";
    case ExerciseValue::Kind::Number: return format_number(value.number);
    case ExerciseValue::Kind::Point: return format_position(value.point);
    case ExerciseValue::Kind::Other: return "[" + value.other + "]";
    case ExerciseValue::Kind::List: break;
  }
  std::string text = "{";
  for (size_t i = 0; i < value.items.size(); ++i) text += (i == 0 ? "" : ", ") + value_text(value.items[i]);
  return text + "}";
}

const char* item_word(const ExerciseValue& value) {
  switch (value.kind) {
    case ExerciseValue::Kind::Number: return "number";
    case ExerciseValue::Kind::Point: return "point";
    case ExerciseValue::Kind::List: return "list";
    default: return "value";
  }
}

std::string read_control_points(lua_State* L, int index, std::vector<glm::dvec3>& out) {
  index = lua_absindex(L, index);
  if (!lua_istable(L, index)) return "must be a list of points like {{0, 0}, {1, 2}}, got " + type_name(L, index);
  out.clear();
  const lua_Unsigned n = lua_rawlen(L, index);
  if (n == 0) return "must hold at least one point, got an empty list";
  if (n > kMaxCurvePoints) {
    return "must hold at most " + std::to_string(kMaxCurvePoints) + " points, got " + std::to_string(n);
  }
  for (lua_Unsigned i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, static_cast<lua_Integer>(i));
    glm::dvec3 p(0.0);
    const bool ok = read_point(L, -1, p) || to_vec3(L, -1, p);
    const std::string what = ok ? "" : type_name(L, -1);
    lua_pop(L, 1);
    if (!ok) return "point " + std::to_string(i) + " must be a point {x, y} or {x, y, z}, got " + what;
    out.push_back(p);
  }
  return "";
}

std::string read_patch_points(lua_State* L, int index, BezierPatch& out) {
  index = lua_absindex(L, index);
  if (const BezierPatch* patch = to_patch(L, index)) {
    out = *patch;
    return "";
  }
  constexpr const char* kShape = "must be 16 points row by row, 4 rows of 4 points, or meshedit.patch(...)";
  if (!lua_istable(L, index)) return std::string(kShape) + ", got " + type_name(L, index);
  lua_getfield(L, index, "points");  // {points = {...}}, as student code receives a patch
  const bool wrapped = lua_istable(L, -1);
  if (!wrapped) lua_pop(L, 1);
  const int list = wrapped ? lua_gettop(L) : index;
  std::vector<glm::dvec3> points;
  std::string problem;
  const lua_Unsigned n = lua_rawlen(L, list);
  const bool rows = n == 4 && lua_rawgeti(L, list, 1) == LUA_TTABLE && lua_rawlen(L, -1) == 4;
  if (n == 4) lua_pop(L, 1);
  for (lua_Unsigned i = 1; i <= n && problem.empty(); ++i) {
    lua_rawgeti(L, list, static_cast<lua_Integer>(i));
    std::vector<glm::dvec3> row;
    if (rows) {
      problem = read_control_points(L, -1, row);
      if (problem.empty() && row.size() != 4) problem = "must hold 4 points, got " + std::to_string(row.size());
      if (!problem.empty()) problem = "row " + std::to_string(i) + " " + problem;
    } else {
      glm::dvec3 p(0.0);
      if (read_point(L, -1, p) || to_vec3(L, -1, p)) row.push_back(p);
      else problem = "point " + std::to_string(i) + " must be a point {x, y} or {x, y, z}, got " + type_name(L, -1);
    }
    lua_pop(L, 1);
    points.insert(points.end(), row.begin(), row.end());
  }
  if (wrapped) lua_pop(L, 1);
  if (!problem.empty()) return problem;
  if (points.size() != 16) return std::string(kShape) + ", got " + plural(points.size(), "point", "points");
  std::copy(points.begin(), points.end(), out.points.begin());
  return "";
}

std::string read_argument_values(lua_State* L, int index, std::vector<ExerciseValue>& out) {
  index = lua_absindex(L, index);
  out.clear();
  if (lua_isnil(L, index)) return "";
  if (!lua_istable(L, index)) return "must be a list of the values passed after the input, got " + type_name(L, index);
  const lua_Unsigned n = lua_rawlen(L, index);
  for (lua_Unsigned i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, static_cast<lua_Integer>(i));
    ExerciseValue v = read_exercise_value(L, -1);
    lua_pop(L, 1);
    if (v.kind == ExerciseValue::Kind::Nil) return "[" + std::to_string(i) + "] must be a value, got nil";
    if (const ExerciseValue* bad = first_other(v)) {
      return "[" + std::to_string(i) + "] must be a number, a point or a list of them, got " +
             (bad == &v ? "" : "a list holding ") + bad->other;
    }
    out.push_back(std::move(v));
  }
  return "";
}

}  // namespace meshedit
