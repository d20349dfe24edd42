// The expect table: C++ checks that record into a TestRecorder (see expectations.h).
#include "grade/expectations.h"

#include <cmath>
#include <optional>
#include <sstream>

#include <glm/geometric.hpp>
#include <lua.hpp>

#include "core/mesh_compare.h"
#include "core/translation.h"
#include "core/validate.h"
#include "core/value_format.h"
#include "grade/exercise_expectation.h"
#include "script/lua_handles.h"
#include "script/mesh_bindings.h"

namespace meshedit {
namespace {

constexpr size_t kMaxListed = 3;  // violations or differences quoted in one message

TestRecorder& recorder(lua_State* L) { return current_recorder(L); }

// The optional message argument at `index` ("" when absent).
std::string message_at(lua_State* L, int index) {
  if (lua_isnoneornil(L, index)) return "";
  size_t len = 0;
  const char* s = luaL_checklstring(L, index, &len);
  return std::string(s, len);
}

std::string join(const std::string& message, const std::string& detail) { return join_message(message, detail); }

int record(lua_State* L, bool passed, const std::string& text) {
  lua_pushboolean(L, recorder(L).record(passed, text));
  return 1;
}

// A point read raw from a table {x=, y=, z=} or {x, y, z} of numbers, without running any metamethod.
std::optional<glm::dvec3> raw_point(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TTABLE) return std::nullopt;
  index = lua_absindex(L, index);
  glm::dvec3 p;
  const char* names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    lua_pushstring(L, names[i]);
    if (lua_rawget(L, index) == LUA_TNIL) {
      lua_pop(L, 1);
      lua_rawgeti(L, index, i + 1);
    }
    int ok = 0;
    p[i] = lua_tonumberx(L, -1, &ok);
    const bool is_number = lua_type(L, -1) == LUA_TNUMBER;
    lua_pop(L, 1);
    if (!ok || !is_number) return std::nullopt;
  }
  return p;
}

bool is_list(lua_State* L, int index) { return lua_type(L, index) == LUA_TTABLE && !raw_point(L, index); }

std::string quote(const char* s, size_t len) {
  constexpr size_t kMax = 60;
  std::string out = "\"";
  out.append(s, std::min(len, kMax));
  if (len > kMax) out += "...";
  return out + "\"";
}

std::string describe_number(lua_State* L, int index) {
  if (lua_isinteger(L, index)) return std::to_string(lua_tointeger(L, index));
  return format_number(lua_tonumber(L, index));
}

}  // namespace

TestRecorder& current_recorder(lua_State* L) {
  auto* const* current = static_cast<TestRecorder* const*>(lua_touserdata(L, lua_upvalueindex(1)));
  if (!current || !*current) luaL_error(L, "expect can only be used while a test runs");
  return **current;
}

std::string join_message(const std::string& message, const std::string& detail) {
  if (message.empty()) return detail;
  if (detail.empty()) return message;
  return message + ": " + detail;
}

std::string first_items(const std::vector<std::string>& items, size_t total) {
  std::string out;
  for (size_t i = 0; i < items.size() && i < kMaxListed; ++i) {
    out = i == 0 ? items[i] : tr_format("{list}; {item}", {{"list", out}, {"item", items[i]}});
  }
  if (total > kMaxListed) {
    out = tr_format("{list}; ... ({count} in all)", {{"list", out}, {"count", std::to_string(total)}});
  }
  return out;
}

bool TestRecorder::record(bool passed, std::string message, size_t headline, std::optional<FailingCase> failing_case) {
  run_.checks.push_back({passed, std::move(message), headline, std::move(failing_case)});
  return passed;
}

void TestRecorder::note_touches(const std::shared_ptr<const HalfedgeMesh>& mesh, const TouchCount& count) {
  for (auto& [watched, touched] : touches_) {
    if (watched.lock() == mesh) {
      touched = count;
      return;
    }
  }
  touches_.emplace_back(mesh, count);
}

std::optional<TouchCount> TestRecorder::touches_of(const HalfedgeMesh* mesh) const {
  for (const auto& [watched, touched] : touches_) {
    if (!watched.expired() && watched.lock().get() == mesh) return touched;
  }
  return std::nullopt;
}

std::string describe_value(lua_State* L, int index) {
  index = lua_absindex(L, index);
  switch (lua_type(L, index)) {
    case LUA_TNIL:
    case LUA_TNONE: return "nil";
    case LUA_TBOOLEAN: return lua_toboolean(L, index) ? "true" : "false";
    case LUA_TNUMBER: return describe_number(L, index);
    case LUA_TSTRING: {
      size_t len = 0;
      const char* s = lua_tolstring(L, index, &len);
      return quote(s, len);
    }
    case LUA_TUSERDATA: {
      if (const Handle* h = test_handle(L, index)) return h->name();
      if (auto mesh = to_mesh(L, index)) {
        return tr_format("a mesh ({vertices} vertices, {edges} edges, {faces} faces)",
                         {{"vertices", std::to_string(mesh->num_vertices())},
                          {"edges", std::to_string(mesh->num_edges())},
                          {"faces", std::to_string(mesh->num_faces())}});
      }
      return tr("a userdata value");
    }
    case LUA_TTABLE: {
      if (auto p = raw_point(L, index)) return format_position(*p);
      const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
      if (n == 0) {
        lua_pushnil(L);
        const bool empty = lua_next(L, index) == 0;
        if (!empty) lua_pop(L, 2);
        return empty ? "{}" : tr("a table");
      }
      std::string out = "{";
      const lua_Integer shown = std::min<lua_Integer>(n, 6);
      for (lua_Integer i = 1; i <= shown; ++i) {
        lua_rawgeti(L, index, i);
        out += (i > 1 ? ", " : "") + describe_value(L, -1);
        lua_pop(L, 1);
      }
      if (n > shown) out += ", ... (" + std::to_string(n) + " items)";
      return out + "}";
    }
    default: return std::string("a ") + lua_typename(L, lua_type(L, index));
  }
}

namespace {

// The place a difference is at, before its message: "[2].position: ", or "" at the top.
std::string place(const std::string& path) { return path.empty() ? "" : path + ": "; }

std::optional<std::string> difference(lua_State* L, int a, int b, const std::string& path, int depth);

// "expected X, got Y" for actual (a) and expected (b).
std::string mismatch(lua_State* L, int a, int b, const std::string& path) {
  return place(path) + tr_format("expected {expected}, got {actual}",
                                 {{"expected", describe_value(L, b)}, {"actual", describe_value(L, a)}});
}

// "expected 3 items, got 2": a list's length, `n` expected, `got` there.
std::string length_mismatch(lua_Integer n, lua_Integer got) {
  const MessageParts parts = {{"count", std::to_string(n)}, {"actual", std::to_string(got)}};
  return n == 1 ? tr_format("expected {count} item, got {actual}", parts)
                : tr_format("expected {count} items, got {actual}", parts);
}

// Handles are equal when they name the same element of the same mesh, meshes when they are the same mesh.
std::optional<std::string> userdata_difference(lua_State* L, int a, int b, const std::string& path) {
  const Handle* ha = test_handle(L, a);
  const Handle* hb = test_handle(L, b);
  if (ha || hb) {
    if (!ha || !hb || ha->mesh() != hb->mesh() || ha->ref() != hb->ref()) return mismatch(L, a, b, path);
    return std::nullopt;
  }
  auto ma = to_mesh(L, a);
  auto mb = to_mesh(L, b);
  if (ma || mb) {
    if (ma != mb) return place(path) + tr("expected the same mesh, got another one");
    return std::nullopt;
  }
  if (!lua_rawequal(L, a, b)) return mismatch(L, a, b, path);
  return std::nullopt;
}

// How the key below the top value reads after a path: ".name", "[3]", "[true]".
std::string key_text(lua_State* L) {
  if (lua_type(L, -3) == LUA_TSTRING) return std::string(".") + lua_tostring(L, -3);
  if (lua_type(L, -3) == LUA_TNUMBER) return "[" + describe_number(L, -3) + "]";
  return "[" + describe_value(L, -3) + "]";
}

// Points compare as points, lists by length first; then every key of expected must be in actual with an equal
// value, and actual must have no key expected lacks.
std::optional<std::string> table_difference(lua_State* L, int a, int b, const std::string& path, int depth) {
  auto pa = raw_point(L, a);
  auto pb = raw_point(L, b);
  if (pa && pb) {
    if (*pa != *pb) return mismatch(L, a, b, path);
    return std::nullopt;
  }
  if (lua_rawequal(L, a, b)) return std::nullopt;
  const lua_Integer na = static_cast<lua_Integer>(lua_rawlen(L, a));
  const lua_Integer nb = static_cast<lua_Integer>(lua_rawlen(L, b));
  if (na != nb && nb > 0) return place(path) + length_mismatch(nb, na);
  luaL_checkstack(L, 6, "comparing tables");
  lua_pushnil(L);
  while (lua_next(L, b) != 0) {
    lua_pushvalue(L, -2);
    lua_rawget(L, a);
    auto d = difference(L, -1, -2, path + key_text(L), depth + 1);
    lua_pop(L, 2);
    if (d) {
      lua_pop(L, 1);
      return d;
    }
  }
  lua_pushnil(L);
  while (lua_next(L, a) != 0) {
    lua_pushvalue(L, -2);
    const bool missing = lua_rawget(L, b) == LUA_TNIL;
    lua_pop(L, 1);
    if (missing) {
      const std::string key = describe_value(L, -2);
      lua_pop(L, 2);
      return place(path) + tr_format("unexpected key {key}", {{"key", key}});
    }
    lua_pop(L, 1);
  }
  return std::nullopt;
}

// The first difference between actual (a) and expected (b), or nullopt when they are equal.
std::optional<std::string> difference(lua_State* L, int a, int b, const std::string& path, int depth) {
  a = lua_absindex(L, a);
  b = lua_absindex(L, b);
  const int ta = lua_type(L, a);
  const int tb = lua_type(L, b);
  if (ta != tb) return mismatch(L, a, b, path);
  if (depth > 32) return place(path) + tr("tables nested too deep to compare");
  switch (ta) {
    case LUA_TNIL: return std::nullopt;
    case LUA_TUSERDATA: return userdata_difference(L, a, b, path);
    case LUA_TTABLE: return table_difference(L, a, b, path, depth);
    default:  // numbers, booleans, strings, functions, threads
      if (!lua_rawequal(L, a, b)) return mismatch(L, a, b, path);
      return std::nullopt;
  }
}

std::optional<std::string> near_difference(lua_State* L, int a, int b, double tolerance, const std::string& path,
                                           int depth) {
  a = lua_absindex(L, a);
  b = lua_absindex(L, b);
  const std::string where = place(path);
  std::ostringstream tol;
  tol << tolerance;
  if (lua_type(L, b) == LUA_TNUMBER) {
    if (lua_type(L, a) != LUA_TNUMBER) return mismatch(L, a, b, path);
    const double x = lua_tonumber(L, a);
    const double y = lua_tonumber(L, b);
    if (!(std::abs(x - y) <= tolerance)) {
      return where + tr_format("expected {expected}, got {actual}, off by {distance} (tolerance {tolerance})",
                               {{"expected", describe_value(L, b)},
                                {"actual", describe_value(L, a)},
                                {"distance", format_number(std::abs(x - y))},
                                {"tolerance", tol.str()}});
    }
    return std::nullopt;
  }
  if (auto pb = raw_point(L, b)) {
    auto pa = raw_point(L, a);
    if (!pa) {
      return where + tr_format("expected the point {expected}, got {actual}",
                               {{"expected", format_position(*pb)}, {"actual", describe_value(L, a)}});
    }
    const double d = glm::length(*pa - *pb);
    if (!(d <= tolerance)) {
      return where + tr_format("expected {expected}, got {actual}, {distance} away (tolerance {tolerance})",
                               {{"expected", format_position(*pb)},
                                {"actual", format_position(*pa)},
                                {"distance", format_number(d)},
                                {"tolerance", tol.str()}});
    }
    return std::nullopt;
  }
  if (is_list(L, b) && depth <= 32) {
    if (!is_list(L, a)) {
      return where + tr_format("expected a list of {count}, got {actual}",
                               {{"count", std::to_string(lua_rawlen(L, b))}, {"actual", describe_value(L, a)}});
    }
    const lua_Integer na = static_cast<lua_Integer>(lua_rawlen(L, a));
    const lua_Integer nb = static_cast<lua_Integer>(lua_rawlen(L, b));
    if (na != nb) return where + length_mismatch(nb, na);
    luaL_checkstack(L, 4, "comparing lists");
    for (lua_Integer i = 1; i <= nb; ++i) {
      lua_rawgeti(L, a, i);
      lua_rawgeti(L, b, i);
      auto d = near_difference(L, -2, -1, tolerance, path + "[" + std::to_string(i) + "]", depth + 1);
      lua_pop(L, 2);
      if (d) return d;
    }
    return std::nullopt;
  }
  return difference(L, a, b, path, depth);
}

// `expected` is the message's template: "expected a mesh, got {actual}".
std::shared_ptr<HalfedgeMesh> mesh_or_fail(lua_State* L, int index, const std::string& message, const char* expected,
                                           bool& failed) {
  auto mesh = to_mesh(L, index);
  if (!mesh) {
    recorder(L).record(false, join(message, tr_format(expected, {{"actual", describe_value(L, index)}})));
    failed = true;
  }
  return mesh;
}

// ---- the functions --------------------------------------------------------------------------------------

int expect_truthy(lua_State* L) {
  return record(L, lua_toboolean(L, 1),
                join(message_at(L, 2), lua_toboolean(L, 1) ? ""
                                                           : tr_format("expected a true value, got {actual}",
                                                                       {{"actual", describe_value(L, 1)}})));
}

int expect_call(lua_State* L) {  // expect(value, message): argument 1 is the table itself
  lua_remove(L, 1);
  return expect_truthy(L);
}

int expect_falsy(lua_State* L) {
  const bool ok = !lua_toboolean(L, 1);
  return record(L, ok,
                join(message_at(L, 2),
                     ok ? "" : tr_format("expected nil or false, got {actual}", {{"actual", describe_value(L, 1)}})));
}

int expect_is_nil(lua_State* L) {
  const bool ok = lua_isnoneornil(L, 1);
  return record(
      L, ok,
      join(message_at(L, 2), ok ? "" : tr_format("expected nil, got {actual}", {{"actual", describe_value(L, 1)}})));
}

int expect_equal(lua_State* L) {
  lua_settop(L, 3);
  const std::string message = message_at(L, 3);
  auto d = difference(L, 1, 2, "", 0);
  return record(L, !d, join(message, d ? *d : ""));
}

int expect_near(lua_State* L) {
  lua_settop(L, 4);
  const double tolerance = luaL_checknumber(L, 3);
  const std::string message = message_at(L, 4);
  auto d = near_difference(L, 1, 2, tolerance, "", 0);
  return record(L, !d, join(message, d ? *d : ""));
}

int expect_valid(lua_State* L) {
  const std::string message = message_at(L, 2);
  bool failed = false;
  auto mesh = mesh_or_fail(L, 1, message, "expected a mesh, got {actual}", failed);
  if (failed) return lua_pushboolean(L, 0), 1;
  const ValidationReport report = validate(*mesh, 20);
  if (report.ok()) return record(L, true, join(message, tr("the mesh is valid")));
  std::vector<std::string> items;
  for (const auto& v : report.violations) items.push_back(format_id(v.element) + ": " + v.message);
  return record(
      L, false,
      join(message, tr_format("the mesh is not valid: {problems}", {{"problems", first_items(items, report.total)}})));
}

template <bool Exact>
int expect_compare(lua_State* L) {
  lua_settop(L, 4);
  const double tolerance = lua_isnil(L, 3) ? 1e-9 : luaL_checknumber(L, 3);
  const std::string message = message_at(L, 4);
  bool failed = false;
  auto yours = mesh_or_fail(L, 1, message, "expected your mesh, got {actual}", failed);
  if (failed) return lua_pushboolean(L, 0), 1;
  auto reference = mesh_or_fail(L, 2, message, "expected the reference mesh, got {actual}", failed);
  if (failed) return lua_pushboolean(L, 0), 1;
  CompareOptions options;
  options.position_tolerance = tolerance;
  options.max_differences = kMaxListed;
  const MeshComparison c =
      Exact ? compare_meshes_exact(*yours, *reference, options) : compare_meshes(*yours, *reference, options);
  if (c.equal) {
    return record(L, true, join(message, tr(Exact ? "same pointers as the reference" : "same mesh as the reference")));
  }
  return record(L, false, join(message, first_items(c.differences, c.total_differences)));
}

int expect_counts(lua_State* L) {
  const std::string message = message_at(L, 3);
  bool failed = false;
  auto mesh = mesh_or_fail(L, 1, message, "expected a mesh, got {actual}", failed);
  if (failed) return lua_pushboolean(L, 0), 1;
  luaL_checktype(L, 2, LUA_TTABLE);
  struct Count {
    const char* name;
    size_t value;
  };
  const Count counts[] = {{"vertices", mesh->num_vertices()},
                          {"edges", mesh->num_edges()},
                          {"faces", mesh->num_faces()},
                          {"halfedges", mesh->num_halfedges()},
                          {"boundaries", mesh->num_boundaries()}};
  std::vector<std::string> wrong;
  for (const auto& c : counts) {
    if (lua_getfield(L, 2, c.name) != LUA_TNIL) {
      const lua_Integer want = luaL_checkinteger(L, -1);
      if (want != lua_Integer(c.value)) {
        wrong.push_back(
            tr_format("{name}: expected {expected}, got {actual}",
                      {{"name", c.name}, {"expected", std::to_string(want)}, {"actual", std::to_string(c.value)}}));
      }
    }
    lua_pop(L, 1);
  }
  return record(
      L, wrong.empty(),
      join(message, wrong.empty() ? std::string(tr("counts as expected")) : first_items(wrong, wrong.size())));
}

int expect_pass(lua_State* L) { return record(L, true, message_at(L, 1)); }
int expect_fail(lua_State* L) { return record(L, false, message_at(L, 1)); }

int expect_score(lua_State* L) {
  const double f = luaL_checknumber(L, 1);
  luaL_argcheck(L, f >= 0.0 && f <= 1.0, 1, "must be between 0 and 1");
  recorder(L).set_fraction(f);
  const std::string message = message_at(L, 2);
  if (!message.empty()) recorder(L).record(f >= 1.0, message);
  lua_pushboolean(L, f >= 1.0);
  return 1;
}

}  // namespace

void push_expect_table(lua_State* L, TestRecorder* const* current) {
  const luaL_Reg functions[] = {{"truthy", expect_truthy},
                                {"falsy", expect_falsy},
                                {"is_nil", expect_is_nil},
                                {"equal", expect_equal},
                                {"near", expect_near},
                                {"valid", guarded<expect_valid>},
                                {"mesh_equal", guarded<expect_compare<false>>},
                                {"same_pointers", guarded<expect_compare<true>>},
                                {"counts", guarded<expect_counts>},
                                {"pass", expect_pass},
                                {"fail", expect_fail},
                                {"score", expect_score},
                                {"exercise", guarded<expect_exercise>},
                                {nullptr, nullptr}};
  lua_newtable(L);
  lua_pushlightuserdata(L, const_cast<TestRecorder**>(current));
  luaL_setfuncs(L, functions, 1);
  lua_createtable(L, 0, 1);
  lua_pushlightuserdata(L, const_cast<TestRecorder**>(current));
  lua_pushcclosure(L, expect_call, 1);
  lua_setfield(L, -2, "__call");
  lua_setmetatable(L, -2);
}

}  // namespace meshedit
