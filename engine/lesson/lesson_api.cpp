// The lesson globals (see lesson_api.h): argument checking, the calls into the host, and the small Lua
// prelude that builds wait_for and animate out of yields, so a condition or an animation frame runs inside
// the step's coroutine (its errors point at the lesson's lines, and each resume has the runtime's budget). The
// questions (lesson_questions.cpp) and what follows the view (lesson_displays.cpp) are defined from here too; what
// all of them share is lesson_api_support.h.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   the prelude                kPrelude: wait_for and animate, written in Lua over the helpers the prelude calls
//   wait_for's table           read_target, default_hint, parse_wait (a wait_for table into a LessonWait)
//   points, curves, patches    push_points_table, read_points, userdata_name, show_curve, read_patch, for_each_element
//   the globals                api_lesson, api_step, api_say, show_up_axis and api_show, api_highlight, api_label,
//                              api_clear, api_camera, api_view, api_current_mesh, api_lesson_file, api_selection
//   helpers the prelude calls  api_check_wait, api_wait, api_check_animate, api_frame: wait_for's and animate's yields
//   public functions           push_element_value, open_lesson_api, clear_step_display
#include "lesson/internal/lesson_api.h"

#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/value_format.h"
#include "lesson/internal/lesson_api_support.h"
#include "lesson/internal/lesson_displays.h"
#include "lesson/internal/lesson_questions.h"
#include "lesson/internal/lesson_your_turn.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"

namespace meshedit {
namespace {

// ---- the prelude -----------------------------------------------------------------------------------

constexpr const char* kPrelude = R"lua(local api = __lesson_api
__lesson_api = nil
local check_wait, wait, check_animate, frame, min = api.check_wait, api.wait, api.check_animate, api.frame, math.min
function wait_for(spec)
  if check_wait(spec) == "condition" then
    local condition = spec.condition
    local value = condition()
    while not value do
      wait(spec)
      value = condition()
    end
    return value
  end
  return wait(spec)
end
function animate(seconds, fn)
  check_animate(seconds, fn)
  if seconds <= 0 then
    fn(1)
    return
  end
  fn(0)
  local elapsed = 0
  while elapsed < seconds do
    elapsed = elapsed + frame(seconds, elapsed)
    fn(min(elapsed / seconds, 1))
  end
end
)lua";

// ---- wait_for's table ------------------------------------------------------------------------------

// The value of wait_for{click=...} / {selection=...}: "any", a kind name, an id, or a handle.
void read_target(lua_State* L, int index, const char* field, LessonWait& wait) {
  if (lua_type(L, index) == LUA_TSTRING) {
    const std::string text = lua_tostring(L, index);
    if (text == "any") return;
    if (std::optional<ElementKind> kind = kind_by_name(text)) {
      wait.element_kind = kind;
      return;
    }
  }
  if (std::optional<ElementRef> element = to_element(L, index)) {
    wait.element = *element;
    return;
  }
  const std::string got =
      lua_type(L, index) == LUA_TSTRING ? "'" + std::string(lua_tostring(L, index)) + "'" : "a " + type_name(L, index);
  raise(L, std::string("wait_for: ") + field +
               " must be an element kind (vertex, halfedge, edge, face, boundary), an id like \"e7\", an element or "
               "\"any\"; got " +
               got);
}

// The hint a wait shows when the lesson gives none, kept in every language (the catalog's "Press {key}"...).
std::string default_hint(lua_State* L, const LessonWait& wait) {
  const auto hint = [&](const char* english_template, std::string part) {
    const LocalText text = local_format(english_template, {{"what", std::move(part)}});
    script_of(L).texts.keep(text, caller_where(L));
    return text.english();
  };
  switch (wait.kind) {
    case LessonWait::Kind::Key: return hint("Press {what}", wait.name);
    case LessonWait::Kind::Command: return hint("Run {what}", command_place(*find_lesson_command(wait.name)));
    case LessonWait::Kind::Click: return hint("Click {what}", wait.describe().substr(std::strlen("a click on ")));
    case LessonWait::Kind::Selection:
      return hint("Select {what}", wait.describe().substr(std::strlen("the selection of ")));
    case LessonWait::Kind::Button: return hint("Press {what}", wait.name);
    default: return "";
  }
}

// Parses wait_for's table at `index` (exactly one of key, command, click, selection, condition, button; an optional
// hint) into a LessonWait, with `where` set to the lesson line.
LessonWait parse_wait(lua_State* L, int index) {
  if (!lua_istable(L, index)) {
    raise(L,
          "wait_for: expected a table like {key=\"F\"}, {command=\"catmull-clark-phase\"}, {click=\"vertex\"}, "
          "{selection=\"e7\"}, {condition=function() ... end} or {button=\"Continue\"}, got " +
              type_name(L, index));
  }
  check_fields(L, index, "wait_for", {"key", "command", "click", "selection", "condition", "button", "hint"});
  LessonWait wait;
  int kinds = 0;
  for (const char* field : {"key", "command", "click", "selection", "condition", "button"}) {
    lua_getfield(L, index, field);
    const int value = lua_gettop(L);
    if (!lua_isnil(L, value)) {
      ++kinds;
      const std::string name = field;
      if (name == "key" || name == "button") {
        const bool text = name == "key" ? lua_type(L, value) == LUA_TSTRING : is_text(L, value);
        if (!text || (lua_type(L, value) == LUA_TSTRING && lua_rawlen(L, value) == 0)) {
          raise(L, "wait_for: " + name + " must be a non-empty string, got " + type_name(L, value));
        }
        wait.kind = name == "key" ? LessonWait::Kind::Key : LessonWait::Kind::Button;
        wait.name = name == "key" ? lua_tostring(L, value) : read_text(L, value, "wait_for", "button");
      } else if (name == "command") {
        const char* command = lua_type(L, value) == LUA_TSTRING ? lua_tostring(L, value) : nullptr;
        if (!command || !find_lesson_command(command)) {
          raise(L, "wait_for: command must be one of " + lesson_command_names() + ", got " +
                       (command ? "'" + std::string(command) + "'" : "a " + type_name(L, value)));
        }
        wait.kind = LessonWait::Kind::Command;
        wait.name = command;
      } else if (name == "condition") {
        if (!lua_isfunction(L, value)) raise(L, "wait_for: condition must be a function, got " + type_name(L, value));
        wait.kind = LessonWait::Kind::Condition;
      } else {
        wait.kind = name == "click" ? LessonWait::Kind::Click : LessonWait::Kind::Selection;
        read_target(L, value, field, wait);
      }
    }
    lua_pop(L, 1);
  }
  if (kinds != 1) {
    raise(L, kinds == 0
                 ? "wait_for: say what to wait for: key, command, click, selection, condition or button"
                 : "wait_for: wait for one thing at a time (key, command, click, selection, condition or button)");
  }
  lua_getfield(L, index, "hint");
  if (!lua_isnil(L, -1)) {
    if (!is_text(L, -1)) raise(L, "wait_for: hint must be a string, got " + type_name(L, -1));
    wait.hint = read_text(L, -1, "wait_for", "hint");
  } else {
    wait.hint = default_hint(L, wait);
  }
  lua_pop(L, 1);
  wait.where = caller_where(L);
  return wait;
}

// ---- points, curves, patches -----------------------------------------------------------------------

// The `points` field of a curve or patch userdata (from the Bézier bindings), or the table itself.
void push_points_table(lua_State* L, int index) {
  if (lua_type(L, index) == LUA_TUSERDATA) lua_getfield(L, index, "points");
  else lua_pushvalue(L, index);
}

std::vector<glm::dvec3> read_points(lua_State* L, int index, const std::string& what) {
  push_points_table(L, index);
  const int list = lua_gettop(L);
  if (!lua_istable(L, list)) raise(L, "show: " + what + " needs a list of points, got " + type_name(L, list));
  std::vector<glm::dvec3> points;
  const lua_Integer n = luaL_len(L, list);
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, list, i);
    glm::dvec3 p{};
    if (!read_point(L, -1, p)) {
      raise(L, "show: point " + std::to_string(i) + " of " + what + " is not a point ({x=, y=, z=} or {x, y, z})");
    }
    points.push_back(p);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return points;
}

std::string userdata_name(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TUSERDATA) return "";
  std::string name;
  if (luaL_getmetafield(L, index, "__name") != LUA_TNIL) {
    if (lua_type(L, -1) == LUA_TSTRING) name = lua_tostring(L, -1);
    lua_pop(L, 1);
  }
  return name;
}

void show_curve(lua_State* L, LessonHost& host, int index) {
  const std::vector<glm::dvec3> points = read_points(L, index, "a curve");
  if (points.empty()) raise(L, "show: a curve needs at least one point");
  BezierCurve curve;
  for (size_t i = 0; i < points.size(); ++i) {
    if (points[i].z != 0.0) {
      raise(L, "show: curves are drawn in 2D, but point " + std::to_string(i + 1) +
                   " has z = " + format_rounded(points[i].z));
    }
    curve.control_points.emplace_back(points[i].x, points[i].y);
  }
  host.show_curve(curve);
}

BezierPatch read_patch(lua_State* L, int index, const std::string& what) {
  const std::vector<glm::dvec3> points = read_points(L, index, what);
  if (points.size() != 16) {
    raise(L, "show: " + what + " needs 16 control points (4 rows of 4), got " + std::to_string(points.size()));
  }
  BezierPatch patch;
  for (size_t i = 0; i < 16; ++i) patch.points[i] = points[i];
  return patch;
}

// Calls fn(element) for the element at `index`, or for each element of a list there.
template <class Fn>
void for_each_element(lua_State* L, int index, const char* call, Fn fn) {
  if (lua_istable(L, index)) {
    const lua_Integer n = luaL_len(L, index);
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_geti(L, index, i);
      fn(check_element(L, lua_gettop(L), call));
      lua_pop(L, 1);
    }
    return;
  }
  fn(check_element(L, index, call));
}

// ---- the globals -----------------------------------------------------------------------------------

int api_lesson(lua_State* L) {
  require_loading(L, "lesson{}");
  if (!lua_istable(L, 1)) raise(L, "lesson: expected a table like {title=\"...\", summary=\"...\"}");
  check_fields(L, 1, "lesson", {"title", "summary"});
  LessonScript& script = script_of(L);
  for (const char* field : {"title", "summary"}) {
    lua_getfield(L, 1, field);
    if (!lua_isnil(L, -1)) {
      if (!is_text(L, -1)) raise(L, std::string("lesson: ") + field + " must be a string");
      (std::strcmp(field, "title") == 0 ? script.title : script.summary) = read_text(L, -1, "lesson", field);
    }
    lua_pop(L, 1);
  }
  return 0;
}

int api_step(lua_State* L) {
  require_loading(L, "step()");
  if (!is_text(L, 1) || lua_type(L, 1) == LUA_TNUMBER) {
    raise(L, "step: the first argument is the step's title, got " + type_name(L, 1));
  }
  if (!lua_isfunction(L, 2)) {
    raise(L, "step: the second argument is the step's body, function() ... end, got " + type_name(L, 2));
  }
  LessonScript& script = script_of(L);
  LessonStepDef def;
  def.title = read_text(L, 1, "step", "the title");
  def.where = caller_where(L);
  lua_pushvalue(L, 2);
  def.function_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  script.steps.push_back(std::move(def));
  return 0;
}

int api_say(lua_State* L) {
  require_step(L, "say()");
  if (!is_text(L, 1)) raise(L, "say: expected text, got " + type_name(L, 1));
  LessonScript& script = script_of(L);
  script.said.push_back(read_text(L, 1, "say", "the text"));
  script.blocks.push_back({LessonBlock::Kind::Text, script.said.size() - 1});
  return 0;
}

// show(mesh, {up = "y"}): the axis a mesh read from a file is shown with pointing up (its file's, which the lesson
// knows); none: Z, as for every mesh MeshEdit makes.
std::optional<UpAxis> show_up_axis(lua_State* L, int index) {
  if (lua_isnoneornil(L, index)) return std::nullopt;
  if (!lua_istable(L, index))
    raise(L, "show: the second argument is a table like {up = \"y\"}, got " + type_name(L, index));
  check_fields(L, index, "show", {"up"});
  lua_getfield(L, index, "up");
  const char* up = lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
  const std::string word = up;
  lua_pop(L, 1);
  if (word == "x") return UpAxis::X;
  if (word == "y") return UpAxis::Y;
  if (word == "z") return UpAxis::Z;
  raise(L, "show: up must be \"x\", \"y\" or \"z\" (the axis pointing up on screen), got '" + word + "'");
}

int api_show(lua_State* L) {
  require_step(L, "show()");
  LessonHost& host = *script_of(L).host;
  if (std::shared_ptr<HalfedgeMesh> mesh = to_mesh(L, 1)) {
    host.show_mesh(std::move(mesh), show_up_axis(L, 2));
    return 0;
  }
  const std::string name = userdata_name(L, 1);
  if (name == "curve") {
    show_curve(L, host, 1);
    return 0;
  }
  if (name == "patch") {
    host.show_patches({read_patch(L, 1, "a patch")});
    return 0;
  }
  if (lua_istable(L, 1) && luaL_len(L, 1) > 0) {
    lua_geti(L, 1, 1);
    glm::dvec3 p{};
    const bool curve = read_point(L, -1, p);
    lua_pop(L, 1);
    if (curve) {
      show_curve(L, host, 1);
      return 0;
    }
    std::vector<BezierPatch> patches;
    const lua_Integer n = luaL_len(L, 1);
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_geti(L, 1, i);
      patches.push_back(read_patch(L, lua_gettop(L), "patch " + std::to_string(i)));
      lua_pop(L, 1);
    }
    host.show_patches(patches);
    return 0;
  }
  raise(L, "show: expected a mesh, a curve (a list of points) or patches (a list of 16-point lists), got " +
               (name.empty() ? type_name(L, 1) : name));
}

int api_highlight(lua_State* L) {
  require_step(L, "highlight()");
  const glm::vec3 colour = read_colour(L, 2);
  LessonHost& host = *script_of(L).host;
  for_each_element(L, 1, "highlight", [&](ElementRef element) { host.highlight(element, colour); });
  return 0;
}

int api_label(lua_State* L) {
  require_step(L, "label()");
  const ElementRef element = check_element(L, 1, "label");
  if (lua_isnoneornil(L, 2)) raise(L, "label: the second argument is the text to show");
  std::string text;
  if (lua_istable(L, 2) && is_text(L, 2)) {
    text = read_text(L, 2, "label", "the text");
  } else {
    text = luaL_tolstring(L, 2, nullptr);
    lua_pop(L, 1);
  }
  script_of(L).host->label(element, text);
  return 0;
}

int api_clear(lua_State* L) {
  require_step(L, "clear()");
  script_of(L).host->clear_annotations();
  return 0;
}

int api_camera(lua_State* L) {
  require_step(L, "camera()");
  CameraRequest request;
  if (lua_type(L, 1) == LUA_TSTRING) {
    const std::string word = lua_tostring(L, 1);
    if (word == "fit") request.fit = true;
    else if (word == "reset") request.reset = true;
    else raise(L, "camera: '" + word + "' is not a camera request (use \"fit\", \"reset\" or a table)");
  } else if (lua_istable(L, 1)) {
    check_fields(L, 1, "camera", {"fit", "reset", "yaw", "pitch", "distance", "target"});
    lua_getfield(L, 1, "fit");
    request.fit = lua_toboolean(L, -1);
    lua_getfield(L, 1, "reset");
    request.reset = lua_toboolean(L, -1);
    lua_pop(L, 2);
    const auto number = [&](const char* field, std::optional<double>& out) {
      lua_getfield(L, 1, field);
      if (!lua_isnil(L, -1)) {
        if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1))) {
          raise(L, std::string("camera: ") + field + " must be a number");
        }
        out = lua_tonumber(L, -1);
      }
      lua_pop(L, 1);
    };
    number("yaw", request.yaw_degrees);
    number("pitch", request.pitch_degrees);
    number("distance", request.distance);
    if (request.distance && *request.distance <= 0.0) raise(L, "camera: distance must be positive");
    lua_getfield(L, 1, "target");
    if (!lua_isnil(L, -1)) {
      glm::dvec3 target{};
      if (!read_point(L, -1, target)) raise(L, "camera: target must be a point ({x=, y=, z=} or {x, y, z})");
      request.target = target;
    }
    lua_pop(L, 1);
  } else {
    raise(L, "camera: expected \"fit\", \"reset\" or a table like {yaw=30, pitch=20, distance=4}");
  }
  script_of(L).host->camera(request);
  return 0;
}

int api_view(lua_State* L) {
  require_step(L, "view()");
  if (!lua_istable(L, 1)) raise(L, "view: expected a table like {halfedges=true, labels=false}");
  check_fields(L, 1, "view", {"halfedges", "wireframe", "vertices", "labels", "curve", "tangent"});
  ViewRequest request;
  const std::pair<const char*, std::optional<bool>*> fields[] = {
      {"halfedges", &request.halfedges}, {"wireframe", &request.wireframe}, {"vertices", &request.vertices},
      {"labels", &request.labels},       {"curve", &request.curve},         {"tangent", &request.tangent}};
  for (const auto& [name, out] : fields) {
    lua_getfield(L, 1, name);
    if (!lua_isnil(L, -1)) {
      if (!lua_isboolean(L, -1)) raise(L, std::string("view: ") + name + " must be true or false");
      *out = bool(lua_toboolean(L, -1));
    }
    lua_pop(L, 1);
  }
  script_of(L).host->view(request);
  return 0;
}

int api_current_mesh(lua_State* L) {
  require_reading(L, "current_mesh()");
  std::shared_ptr<HalfedgeMesh> mesh = script_of(L).host->current_mesh();
  if (mesh) push_mesh(L, std::move(mesh));
  else lua_pushnil(L);
  return 1;
}

// Not tied to a phase: a lesson may load its assets at the top level as well as inside a step.
int api_lesson_file(lua_State* L) {
  const std::filesystem::path relative(luaL_checkstring(L, 1));
  const LessonScript& script = script_of(L);
  const std::filesystem::path full = relative.is_absolute() ? relative : script.directory / relative;
  lua_pushstring(L, full.lexically_normal().string().c_str());
  return 1;
}

int api_selection(lua_State* L) {
  require_reading(L, "selection()");
  LessonHost& host = *script_of(L).host;
  const ElementRef selected = host.current_selection();
  if (selected.valid()) push_element_value(L, host, selected);
  else lua_pushnil(L);
  return 1;
}

// ---- helpers the prelude calls ---------------------------------------------------------------------

int api_check_wait(lua_State* L) {
  require_step_thread(L, "wait_for()");
  const LessonWait wait = parse_wait(L, 1);
  lua_pushstring(L, wait.kind == LessonWait::Kind::Condition ? "condition" : "event");
  return 1;
}

int api_wait(lua_State* L) {
  require_step_thread(L, "wait_for()");
  LessonScript& script = script_of(L);
  script.wait = parse_wait(L, 1);
  script.api_yield = true;
  return lua_yield(L, 0);  // the runner resumes with what the wait returns
}

int api_check_animate(lua_State* L) {
  require_step_thread(L, "animate()");
  if (lua_type(L, 1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, 1)) || lua_tonumber(L, 1) < 0) {
    raise(L, "animate: the first argument is the length in seconds (a number >= 0), got " +
                 (lua_type(L, 1) == LUA_TNUMBER ? std::string(lua_tostring(L, 1)) : type_name(L, 1)));
  }
  if (!lua_isfunction(L, 2)) raise(L, "animate: the second argument is function(t) ... end, got " + type_name(L, 2));
  return 0;
}

int api_frame(lua_State* L) {
  require_step_thread(L, "animate()");
  LessonScript& script = script_of(L);
  LessonWait wait;
  wait.kind = LessonWait::Kind::Animation;
  wait.seconds = lua_tonumber(L, 1);
  wait.elapsed = lua_tonumber(L, 2);
  wait.where = caller_where(L);
  script.wait = wait;
  script.api_yield = true;
  return lua_yield(L, 0);  // the runner resumes with the frame's dt
}

}  // namespace

// ---- public functions ------------------------------------------------------------------------------

void push_element_value(lua_State* L, LessonHost& host, ElementRef element) {
  std::shared_ptr<HalfedgeMesh> mesh = host.current_mesh();
  if (!mesh || !element.valid() || element.index >= mesh->capacity(element.kind)) {
    lua_pushstring(L, format_id(element).c_str());
    return;
  }
  push_mesh(L, std::move(mesh));
  lua_getfield(L, -1, kind_name(element.kind));  // mesh:vertex(i), mesh:edge(i), ...
  lua_insert(L, -2);
  lua_pushinteger(L, element.index);
  lua_call(L, 2, 1);
}

void open_lesson_api(LuaRuntime& runtime, LessonScript& script) {
  set_globals(runtime, script,
              {{"lesson", lesson_guarded<api_lesson>},
               {"step", lesson_guarded<api_step>},
               {"say", lesson_guarded<api_say>},
               {"show", lesson_guarded<api_show>},
               {"highlight", lesson_guarded<api_highlight>},
               {"label", lesson_guarded<api_label>},
               {"clear", lesson_guarded<api_clear>},
               {"camera", lesson_guarded<api_camera>},
               {"view", lesson_guarded<api_view>},
               {"current_mesh", lesson_guarded<api_current_mesh>},
               {"selection", lesson_guarded<api_selection>},
               {"lesson_file", lesson_guarded<api_lesson_file>}});
  open_prelude_functions(runtime, script, "__lesson_api",
                         {{"check_wait", lesson_guarded<api_check_wait>},
                          {"wait", lesson_guarded<api_wait>},
                          {"check_animate", lesson_guarded<api_check_animate>},
                          {"frame", lesson_guarded<api_frame>}},
                         kPrelude);
  open_lesson_questions(runtime, script);
  open_lesson_displays(runtime, script);
  open_lesson_your_turn(runtime, script);
}

void clear_step_display(lua_State* L, LessonScript& script) {
  for (const LessonLive& live : script.lives) luaL_unref(L, LUA_REGISTRYINDEX, live.function_ref);
  for (const LessonPlot& plot : script.plots) luaL_unref(L, LUA_REGISTRYINDEX, plot.marker_ref);
  script.said.clear();
  script.blocks.clear();
  script.lives.clear();
  script.plots.clear();
  script.answered.clear();
  script.last_judgement = {};
  script.judgements = 0;
  script.your_turns.clear();
}

}  // namespace meshedit
