// live, plot, arrow, curve_t, curve_points and patch_uv (see lesson_displays.h).
#include "lesson/internal/lesson_displays.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <lua.hpp>

#include "core/palette.h"
#include "core/value_format.h"
#include "lesson/internal/lesson_api_support.h"
#include "script/lua_runtime.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

constexpr int kDefaultSamples = 100;
constexpr int kMaxSamples = 2000;
constexpr size_t kMaxCurves = 12;

// The colours a plot's curves take in turn when they name none: the palette's swatches that read on both themes.
const glm::vec3 kCurveColours[] = {kDarkSwatches.blue,           kDarkSwatches.orange,   kDarkSwatches.bluish_green,
                                   kDarkSwatches.reddish_purple, kDarkSwatches.sky_blue, kDarkSwatches.vermillion,
                                   kDarkSwatches.yellow};

// Whether `message` starts with "name:LINE:", as Lua's own errors do.
bool has_place(const std::string& message) {
  const size_t colon = message.find(':');
  if (colon == std::string::npos || colon == 0) return false;
  size_t i = colon + 1;
  while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) ++i;
  return i > colon + 1 && i < message.size() && message[i] == ':';
}

// The error on top of L as text, placed at `where` when Lua gave it no place.
std::string error_at(lua_State* L, const std::string& where) {
  std::string message = error_value_text(L, -1);
  if (!has_place(message) && !where.empty()) message = where + ": " + message;
  return message;
}

// Calls the function at index 1 and leaves its value as text, or the value itself when it is a table of languages
// with a string `en` (read raw: a table with metamethods is turned into text).
int call_to_text(lua_State* L) {
  lua_call(L, 0, 1);
  if (lua_istable(L, -1) && !lua_getmetatable(L, -1)) {
    lua_pushliteral(L, "en");
    const bool english = lua_rawget(L, -2) == LUA_TSTRING;
    lua_pop(L, 1);
    if (english) return 1;
  }
  luaL_tolstring(L, -1, nullptr);
  return 1;
}

// Calls the function at index 1 and leaves its value, which must be nil or a finite number.
int call_to_number(lua_State* L) {
  lua_call(L, 0, 1);
  if (lua_isnil(L, -1)) return 1;
  if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1))) {
    return luaL_error(L, "plot: the marker must return a number or nil, got %s", luaL_typename(L, -1));
  }
  return 1;
}

// Runs `helper` on the function `ref` in phase Live; true when it succeeded (its value on top), else the error.
bool call_live(lua_State* L, LessonScript& script, lua_CFunction helper, int ref) {
  const LessonScript::Phase before = script.phase;
  script.phase = LessonScript::Phase::Live;
  lua_pushcfunction(L, helper);
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int status = lua_pcall(L, 1, 1, 0);
  script.phase = before;
  return status == LUA_OK;
}

// ---- the globals --------------------------------------------------------------------------------------------------

int api_live(lua_State* L) {
  require_step(L, "live()");
  if (!lua_isfunction(L, 1)) {
    raise(L, "live: expected function() return \"text\" end (evaluated every frame), got " + type_name(L, 1));
  }
  LessonScript& script = script_of(L);
  LessonLive live;
  live.where = caller_where(L);
  lua_pushvalue(L, 1);
  live.function_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  evaluate_live(L, script, live);
  script.lives.push_back(std::move(live));
  script.blocks.push_back({LessonBlock::Kind::Live, script.lives.size() - 1});
  return 0;
}

// Two finite increasing numbers {lo, hi} in field `name` of the table at index 1.
std::optional<glm::dvec2> read_range(lua_State* L, const char* name) {
  lua_getfield(L, 1, name);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return std::nullopt;
  }
  glm::dvec2 range{};
  bool ok = lua_istable(L, -1) && luaL_len(L, -1) == 2;
  for (int i = 0; ok && i < 2; ++i) {
    lua_geti(L, -1, i + 1);
    ok = lua_type(L, -1) == LUA_TNUMBER && std::isfinite(lua_tonumber(L, -1));
    range[i] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  if (!ok || !(range[0] < range[1])) {
    raise(L, std::string("plot: ") + name + " must be two increasing numbers like {0, 1}");
  }
  lua_pop(L, 1);
  return range;
}

// The curve at the top of the stack (curve number `number`), sampled at samples + 1 points of `x`.
LessonPlotCurve read_curve(lua_State* L, int number, glm::dvec2 x, int samples) {
  const int curve = lua_gettop(L);
  const std::string which = "curve " + std::to_string(number);
  if (!lua_istable(L, curve)) {
    raise(L, "plot: " + which + " must be a table like {label = \"B0\", fn = function(x) ... end}, got " +
                 type_name(L, curve));
  }
  check_fields(L, curve, ("plot: " + which).c_str(), {"label", "fn", "colour", "color"});
  LessonPlotCurve out;
  lua_getfield(L, curve, "label");
  if (!lua_isnil(L, -1) && !is_text(L, -1)) raise(L, "plot: " + which + "'s label must be text");
  out.label = lua_isnil(L, -1) ? which : read_text(L, -1, "plot", which + "'s label");
  lua_pop(L, 1);
  lua_getfield(L, curve, "colour");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_getfield(L, curve, "color");
  }
  out.colour =
      lua_isnil(L, -1) ? kCurveColours[size_t(number - 1) % std::size(kCurveColours)] : read_colour(L, lua_gettop(L));
  lua_pop(L, 1);
  lua_getfield(L, curve, "fn");
  if (!lua_isfunction(L, -1)) {
    raise(L, "plot: " + which + " ('" + out.label + "') needs fn = function(x) return y end, got " + type_name(L, -1));
  }
  const int fn = lua_gettop(L);
  out.points.reserve(size_t(samples) + 1);
  for (int k = 0; k <= samples; ++k) {
    const double at = k == samples ? x[1] : x[0] + (x[1] - x[0]) * double(k) / double(samples);
    lua_pushvalue(L, fn);
    lua_pushnumber(L, at);
    lua_call(L, 1, 1);
    if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1))) {
      const std::string got = lua_type(L, -1) == LUA_TNUMBER ? format_rounded(lua_tonumber(L, -1)) : type_name(L, -1);
      raise(L,
            "plot: '" + out.label + "' gave " + got + " at x = " + format_rounded(at) + " (fn must return a number)");
    }
    out.points.emplace_back(at, lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return out;
}

int api_plot(lua_State* L) {
  require_step(L, "plot()");
  if (!lua_istable(L, 1)) {
    raise(L, "plot: expected a table like {title = \"...\", x = {0, 1}, curves = {{label =, fn =}, ...}}, got " +
                 type_name(L, 1));
  }
  check_fields(L, 1, "plot", {"title", "x", "y", "samples", "curves", "marker"});
  LessonScript& script = script_of(L);
  LessonPlot plot;
  plot.where = caller_where(L);
  lua_getfield(L, 1, "title");
  if (!lua_isnil(L, -1) && !is_text(L, -1)) raise(L, "plot: title must be text");
  if (!lua_isnil(L, -1)) plot.title = read_text(L, -1, "plot", "the title");
  lua_pop(L, 1);
  plot.x_range = read_range(L, "x").value_or(glm::dvec2(0.0, 1.0));
  const std::optional<glm::dvec2> y = read_range(L, "y");
  int samples = kDefaultSamples;
  lua_getfield(L, 1, "samples");
  if (!lua_isnil(L, -1)) {
    if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < 2 || lua_tointeger(L, -1) > kMaxSamples) {
      raise(L, "plot: samples must be a whole number from 2 to " + std::to_string(kMaxSamples));
    }
    samples = int(lua_tointeger(L, -1));
  }
  lua_pop(L, 1);
  lua_getfield(L, 1, "marker");
  if (!lua_isnil(L, -1) && !lua_isfunction(L, -1)) {
    raise(L, "plot: marker must be function() return x end, got " + type_name(L, -1));
  }
  lua_pop(L, 1);
  lua_getfield(L, 1, "curves");
  if (!lua_istable(L, -1) || luaL_len(L, -1) == 0) {
    raise(L, "plot: curves must be a list like {{label = \"B0\", fn = function(x) ... end}, ...}");
  }
  const lua_Integer n = luaL_len(L, -1);
  if (size_t(n) > kMaxCurves) raise(L, "plot: at most " + std::to_string(kMaxCurves) + " curves in one plot");
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, -1, i);
    plot.curves.push_back(read_curve(L, int(i), plot.x_range, samples));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (y) {
    plot.y_range = *y;
  } else {
    double lo = plot.curves[0].points[0].y, hi = lo;
    for (const LessonPlotCurve& curve : plot.curves) {
      for (const glm::dvec2& p : curve.points) {
        lo = std::min(lo, p.y);
        hi = std::max(hi, p.y);
      }
    }
    plot.y_range = lo < hi ? glm::dvec2(lo, hi) : glm::dvec2(lo - 0.5, hi + 0.5);
  }
  lua_getfield(L, 1, "marker");
  if (lua_isfunction(L, -1)) {
    plot.marker_ref = luaL_ref(L, LUA_REGISTRYINDEX);
    evaluate_marker(L, script, plot);
  } else {
    lua_pop(L, 1);
  }
  script.plots.push_back(std::move(plot));
  script.blocks.push_back({LessonBlock::Kind::Plot, script.plots.size() - 1});
  return 0;
}

glm::dvec3 check_point(lua_State* L, int index, const char* which) {
  glm::dvec3 p{};
  if (!read_point(L, index, p) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
    raise(L, std::string("arrow: the ") + which + " point must be {x, y, z} or a vec3 of finite numbers, got " +
                 type_name(L, index));
  }
  return p;
}

int api_arrow(lua_State* L) {
  require_step(L, "arrow()");
  const glm::dvec3 from = check_point(L, 1, "first (where the arrow starts)");
  const glm::dvec3 to = check_point(L, 2, "second (where it points)");
  const glm::vec3 colour = read_colour(L, 3);
  script_of(L).host->arrow(from, to, colour);
  return 0;
}

int api_curve_t(lua_State* L) {
  require_reading(L, "curve_t()");
  const std::optional<CurveReading> curve = script_of(L).host->curve_reading();
  if (curve) lua_pushnumber(L, curve->t);
  else lua_pushnil(L);
  return 1;
}

int api_curve_points(lua_State* L) {
  require_reading(L, "curve_points()");
  const std::optional<CurveReading> curve = script_of(L).host->curve_reading();
  if (!curve) {
    lua_pushnil(L);
    return 1;
  }
  lua_createtable(L, int(curve->control_points.size()), 0);
  for (size_t i = 0; i < curve->control_points.size(); ++i) {
    push_vec3(L, glm::dvec3(curve->control_points[i], 0.0));
    lua_rawseti(L, -2, lua_Integer(i + 1));
  }
  return 1;
}

int api_patch_uv(lua_State* L) {
  require_reading(L, "patch_uv()");
  const std::optional<PatchReading> patch = script_of(L).host->patch_reading();
  if (!patch) {
    lua_pushnil(L);
    return 1;
  }
  lua_pushnumber(L, patch->u);
  lua_pushnumber(L, patch->v);
  lua_pushinteger(L, static_cast<lua_Integer>(patch->selected_patch) + 1);
  return 3;
}

}  // namespace

void evaluate_live(lua_State* L, LessonScript& script, LessonLive& live) {
  if (!live.error.empty()) return;
  if (!call_live(L, script, call_to_text, live.function_ref)) {
    live.error = error_at(L, live.where);
  } else if (lua_istable(L, -1)) {
    for (const Language language : kLanguages) {
      lua_pushstring(L, language_code(language));
      live.local.texts[size_t(language)] = lua_rawget(L, -2) == LUA_TSTRING ? lua_tostring(L, -1) : "";
      lua_pop(L, 1);
    }
    live.text = live.local.english();
  } else {
    live.text = lua_tostring(L, -1);
    live.local = LocalText{};
    live.local.texts[0] = live.text;
  }
  lua_pop(L, 1);
}

void evaluate_marker(lua_State* L, LessonScript& script, LessonPlot& plot) {
  if (!plot.error.empty() || plot.marker_ref == LUA_NOREF) return;
  if (!call_live(L, script, call_to_number, plot.marker_ref)) {
    plot.error = error_at(L, plot.where);
  } else if (lua_isnil(L, -1)) {
    plot.marker.reset();
  } else {
    plot.marker = lua_tonumber(L, -1);
  }
  lua_pop(L, 1);
}

void open_lesson_displays(LuaRuntime& runtime, LessonScript& script) {
  set_globals(runtime, script,
              {{"live", lesson_guarded<api_live>},
               {"plot", lesson_guarded<api_plot>},
               {"arrow", lesson_guarded<api_arrow>},
               {"curve_t", lesson_guarded<api_curve_t>},
               {"curve_points", lesson_guarded<api_curve_points>},
               {"patch_uv", lesson_guarded<api_patch_uv>}});
}

}  // namespace meshedit
