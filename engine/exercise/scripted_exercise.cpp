// Exercises defined in Lua (see scripted_exercise.h): loading and checking a definition, running its reference and
// diagnose in the definition's own state.
#include "exercise/scripted_exercise.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <lua.hpp>

#include "core/file_bytes.h"
#include "core/mesh_compare.h"
#include "core/translation.h"
#include "core/validate.h"
#include "script/lua_args.h"
#include "script/lua_handles.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"
#include "script/script_runtime.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

struct TakesName {
  const char* name;
  std::optional<ElementKind> kind;
  ScriptedExercise::Input input;
};
constexpr TakesName kTakes[] = {{"vertex", ElementKind::Vertex, ScriptedExercise::Input::Element},
                                {"edge", ElementKind::Edge, ScriptedExercise::Input::Element},
                                {"face", ElementKind::Face, ScriptedExercise::Input::Element},
                                {"halfedge", ElementKind::Halfedge, ScriptedExercise::Input::Element},
                                {"mesh", std::nullopt, ScriptedExercise::Input::Mesh},
                                {"points", std::nullopt, ScriptedExercise::Input::Points},
                                {"patch", std::nullopt, ScriptedExercise::Input::Patch}};

bool is_identifier(const std::string& text) {
  if (text.empty() || !(std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_')) return false;
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// What the exercise{} call being read fills in (a light userdata upvalue of the exercise global).
struct Reading {
  ScriptedExercise* target = nullptr;
  bool called = false;
};

}  // namespace

// The exercise{} global: checks the table field by field (errors at the call's line) and keeps what it read.
struct ScriptedExerciseReader {
  static std::string string_field(lua_State* L, const char* field, bool required, const std::string& fallback = "") {
    lua_getfield(L, 1, field);
    std::string value = fallback;
    if (lua_type(L, -1) == LUA_TSTRING) {
      value = lua_tostring(L, -1);
    } else if (!lua_isnil(L, -1) || required) {
      raise(L, std::string("exercise: ") + field + " must be a string, got " + type_name(L, -1));
    }
    lua_pop(L, 1);
    return value;
  }

  static int read(lua_State* L) {
    auto* reading = static_cast<Reading*>(lua_touserdata(L, lua_upvalueindex(1)));
    if (reading->called) raise(L, "exercise: a file defines one exercise; exercise{} was called a second time");
    if (!lua_istable(L, 1))
      raise(L, "exercise: expected a table like exercise{ name = \"collapse\", ... }, got " + type_name(L, 1));
    check_fields(L, 1, "exercise",
                 {"name", "title", "file", "call", "signature", "takes", "allow", "reference", "diagnose", "hint",
                  "tolerance", "fixtures"});
    ScriptedExercise& x = *reading->target;
    x.name_ = string_field(L, "name", true);
    if (!is_identifier(x.name_)) raise(L, "exercise: name must be a word like \"collapse\", got '" + x.name_ + "'");
    if (std::any_of(builtin_exercises().begin(), builtin_exercises().end(),
                    [&](Exercise e) { return x.name_ == e.info().name; })) {
      raise(L, "exercise: '" + x.name_ + "' is a built-in exercise; choose another name");
    }
    x.title_ = string_field(L, "title", false, x.name_);
    x.file_ = string_field(L, "file", true);
    if (x.file_.size() < 5 || x.file_.substr(x.file_.size() - 4) != ".lua" ||
        x.file_.find_first_of("/\\") != std::string::npos) {
      raise(L, "exercise: file must be the student's file name, like \"collapse.lua\", got '" + x.file_ + "'");
    }
    x.function_ = string_field(L, "call", true);
    if (!is_identifier(x.function_)) {
      raise(L, "exercise: call must be the name of the student's function, got '" + x.function_ + "'");
    }
    x.hint_ = string_field(L, "hint", false);
    const std::string takes = string_field(L, "takes", true);
    const auto* const found =
        std::find_if(std::begin(kTakes), std::end(kTakes), [&](const TakesName& t) { return takes == t.name; });
    if (found == std::end(kTakes)) {
      raise(L, "exercise: takes must be vertex, edge, face, halfedge, mesh, points or patch, got '" + takes + "'");
    }
    x.takes_ = found->kind;
    x.input_ = found->input;
    const char* first = x.input_ == ScriptedExercise::Input::Points  ? "(points, ...)"
                        : x.input_ == ScriptedExercise::Input::Patch ? "(patch, ...)"
                                                                     : "(mesh, ...)";
    x.signature_ = string_field(L, "signature", false, x.function_ + first);
    read_tolerance(L, x);
    read_allow(L, x);
    x.reference_ = function_field(L, "reference", true);
    x.diagnose_ = function_field(L, "diagnose", false);
    read_fixtures(L, x);
    reading->called = true;
    return 0;
  }

  static void read_tolerance(lua_State* L, ScriptedExercise& x) {
    lua_getfield(L, 1, "tolerance");
    if (!lua_isnil(L, -1)) {
      if (!x.takes_values()) raise(L, "exercise: tolerance is for exercises that take points or a patch");
      if (lua_type(L, -1) != LUA_TNUMBER || !(lua_tonumber(L, -1) >= 0) || !std::isfinite(lua_tonumber(L, -1))) {
        raise(L, "exercise: tolerance must be a number of 0 or more, got " + type_name(L, -1));
      }
      x.tolerance_ = lua_tonumber(L, -1);
    }
    lua_pop(L, 1);
  }

  static void read_allow(lua_State* L, ScriptedExercise& x) {
    lua_getfield(L, 1, "allow");
    if (!lua_isnil(L, -1)) {
      if (!lua_istable(L, -1)) raise(L, "exercise: allow must be a list like {\"mesh:flip\"}, got " + type_name(L, -1));
      for (lua_Integer i = 1; i <= luaL_len(L, -1); ++i) {
        lua_geti(L, -1, i);
        const std::string name = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (!is_hideable_api(name)) {
          std::string names;
          for (const std::string& n : hideable_api_names()) names += (names.empty() ? "" : ", ") + n;
          raise(L, "exercise: allow[" + std::to_string(i) + "] must be one of " + names + ", got " +
                       (name.empty() ? type_name(L, -1) : "'" + name + "'"));
        }
        x.api_.allow_api.push_back(name);
        lua_pop(L, 1);
      }
    }
    lua_pop(L, 1);
  }

  // A registry reference to the function in `field`, or -1 when it is absent and not required.
  static int function_field(lua_State* L, const char* field, bool required) {
    lua_getfield(L, 1, field);
    if (lua_isfunction(L, -1)) return luaL_ref(L, LUA_REGISTRYINDEX);
    if (lua_isnil(L, -1) && !required) {
      lua_pop(L, 1);
      return -1;
    }
    raise(L, std::string("exercise: ") + field + " must be a function, got " + type_name(L, -1));
  }

  static void read_fixtures(lua_State* L, ScriptedExercise& x) {
    lua_getfield(L, 1, "fixtures");
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      return;
    }
    const char* shape = x.input_ == ScriptedExercise::Input::Points  ? "{name =, control =, args =}"
                        : x.input_ == ScriptedExercise::Input::Patch ? "{name =, patch =, args =}"
                                                                     : "{name =, mesh =, element =}";
    if (!lua_istable(L, -1)) raise(L, std::string("exercise: fixtures must be a list of ") + shape);
    const int list = lua_gettop(L);
    for (lua_Integer i = 1; i <= luaL_len(L, list); ++i) {
      const std::string which = "exercise: fixtures[" + std::to_string(i) + "]";
      lua_geti(L, list, i);
      if (!lua_istable(L, -1)) raise(L, which + " must be a table " + shape + ", got " + type_name(L, -1));
      const int item = lua_gettop(L);
      if (x.takes_values()) {
        check_fields(L, item, which.c_str(),
                     {"name", x.input_ == ScriptedExercise::Input::Points ? "control" : "patch", "args", "points"});
      } else {
        check_fields(L, item, which.c_str(), {"name", "mesh", "element", "points"});
      }
      ScriptedFixture fixture;
      lua_getfield(L, item, "name");
      fixture.name = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "fixture " + std::to_string(i);
      read_points_field(L, item, which, fixture);
      if (x.takes_values()) {
        read_values_input(L, item, which, x, fixture);
      } else {
        read_mesh_input(L, item, which, x, fixture);
      }
      x.fixtures_.push_back(std::move(fixture));
      lua_settop(L, list);
    }
    lua_pop(L, 1);
  }

  // A fixture's score: points = a number above 0 (1 when left out).
  static void read_points_field(lua_State* L, int item, const std::string& which, ScriptedFixture& fixture) {
    lua_getfield(L, item, "points");
    if (!lua_isnil(L, -1)) {
      if (lua_type(L, -1) != LUA_TNUMBER || !(lua_tonumber(L, -1) > 0)) {
        raise(L, which + ".points must be a number above 0 (the test's score), got " + type_name(L, -1));
      }
      fixture.points = lua_tonumber(L, -1);
    }
    lua_pop(L, 1);
  }

  // control = {...} or patch = {...}, and args = {...}.
  static void read_values_input(lua_State* L, int item, const std::string& which, const ScriptedExercise& x,
                                ScriptedFixture& fixture) {
    const bool points = x.input_ == ScriptedExercise::Input::Points;
    lua_getfield(L, item, points ? "control" : "patch");
    const std::string problem =
        points ? read_control_points(L, -1, fixture.control) : read_patch_points(L, -1, fixture.patch);
    if (!problem.empty()) raise(L, which + (points ? ".control " : ".patch ") + problem);
    lua_pop(L, 1);
    lua_getfield(L, item, "args");
    if (std::string bad = read_argument_values(L, -1, fixture.args); !bad.empty()) {
      raise(L, which + ".args" + (bad[0] == '[' ? "" : " ") + bad);
    }
    lua_pop(L, 1);
  }

  static void read_mesh_input(lua_State* L, int item, const std::string& which, const ScriptedExercise& x,
                              ScriptedFixture& fixture) {
    lua_getfield(L, item, "mesh");
    const std::shared_ptr<HalfedgeMesh> mesh = to_mesh(L, -1);
    if (!mesh) raise(L, which + ".mesh must be a mesh, got " + type_name(L, -1));
    fixture.mesh = std::make_shared<const HalfedgeMesh>(*mesh);
    if (x.takes_) {
      lua_getfield(L, item, "element");
      std::optional<ElementRef> element = to_element(L, -1);
      if (!element && lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0 && lua_tointeger(L, -1) <= UINT32_MAX) {
        element = ElementRef(*x.takes_, static_cast<uint32_t>(lua_tointeger(L, -1)));
      }
      if (!element || element->kind != *x.takes_ || !mesh->alive(*element)) {
        raise(L, which + ".element must be " + (*x.takes_ == ElementKind::Edge ? "an " : "a ") + kind_name(*x.takes_) +
                     " of its mesh (a handle, an id like \"" + kind_prefix(*x.takes_) + "3\", or the number), got " +
                     (element ? format_id(*element) : type_name(L, -1)));
      }
      fixture.element = *element;
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
};

std::shared_ptr<ScriptedExercise> ScriptedExercise::load(const std::filesystem::path& file) {
  const FileBytes source = read_file_bytes(file);
  if (!source.ok()) throw ScriptError("cannot open " + file.string());
  const std::string& code = source.bytes;
  std::shared_ptr<ScriptedExercise> x(new ScriptedExercise());
  x->path_ = file;
  x->stamp_ = file_stamp(file);
  x->runtime_ = std::make_unique<ScriptRuntime>();
  lua_State* L = x->runtime_->state();
  Reading reading{x.get(), false};
  lua_pushlightuserdata(L, &reading);
  lua_pushcclosure(L, guarded<ScriptedExerciseReader::read>, 1);
  lua_setglobal(L, "exercise");
  const std::string name = file.filename().string();
  x->runtime_->load(code, name);
  x->runtime_->call(0, 0);
  lua_pushnil(L);
  lua_setglobal(L, "exercise");  // the reader's upvalue points at `reading`, which ends here
  if (!reading.called) throw ScriptError(name + ": no exercise{} in the file");
  x->info_ =
      ExerciseInfo{x->name_.c_str(), x->file_.c_str(), x->function_.c_str(), x->signature_.c_str(), x->title_.c_str()};
  return x;
}

ScriptedExercise::~ScriptedExercise() = default;

ExerciseInput ScriptedExercise::input_of(const ScriptedFixture& fixture) const {
  switch (input_) {
    case Input::Points: return ExerciseInput::of_points(fixture.control, fixture.args);
    case Input::Patch: return ExerciseInput::of_patch(fixture.patch, fixture.args);
    case Input::Mesh: return ExerciseInput::whole_mesh(fixture.mesh);
    case Input::Element: break;
  }
  return ExerciseInput::element_of(fixture.mesh, fixture.element);
}

double ScriptedExercise::tolerance(const ExerciseInput& input) const {
  if (tolerance_) return *tolerance_;
  return input_ == Input::Patch ? points_tolerance(input.patch.points) : points_tolerance(input.points);
}

int ScriptedExercise::push_value_arguments(lua_State* L, const ExerciseInput& input) const {
  if (!lua_checkstack(L, static_cast<int>(input.args.size()) + 4)) throw ScriptError("too many arguments to pass");
  if (input_ == Input::Patch) {
    push_student_patch(L, input.patch);
  } else {
    lua_createtable(L, static_cast<int>(input.points.size()), 0);
    for (size_t i = 0; i < input.points.size(); ++i) {
      push_vec3(L, input.points[i]);
      lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
  }
  for (const ExerciseValue& arg : input.args) push_exercise_value(L, arg);
  return static_cast<int>(1 + input.args.size());
}

ExerciseOutcome ScriptedExercise::run_values_reference(const ExerciseInput& input) const {
  ExerciseOutcome out;
  lua_State* L = runtime_->state();
  lua_settop(L, 0);
  lua_rawgeti(L, LUA_REGISTRYINDEX, reference_);
  try {
    const int arguments = push_value_arguments(L, input);
    runtime_->start_budget();
    runtime_->call(arguments, 1);
    out.value = read_exercise_value(L, 1);
    out.returned = describe(out.value);
    out.ran = true;
  } catch (const ScriptError& e) {
    out.fail_with(e);
    out.error = tr_format("the exercise's reference failed: {error}", {{"error", out.error}});
  }
  lua_settop(L, 0);
  return out;
}

ExerciseOutcome ScriptedExercise::run_reference(const ExerciseInput& input) const {
  if (takes_values()) return run_values_reference(input);
  ExerciseOutcome out;
  out.mesh = std::make_shared<HalfedgeMesh>(*input.mesh);
  lua_State* L = runtime_->state();
  lua_settop(L, 0);
  lua_rawgeti(L, LUA_REGISTRYINDEX, reference_);
  push_mesh(L, out.mesh);
  if (takes_) push_handle(L, out.mesh, input.element);
  try {
    runtime_->start_budget();
    runtime_->call(takes_ ? 2 : 1, 2);
    if (const Handle* h = test_handle(L, 1); h && h->mesh() == out.mesh) {
      out.element = h->ref();
      out.returned = format_id(out.element);
    } else {
      out.returned = lua_isnil(L, 1) ? "nil" : "a " + type_name(L, 1);
    }
    if (out.returned == "nil" && out.mesh->same_as(*input.mesh)) {
      out.refused = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : tr("the reference leaves the mesh as it is");
    }
    out.ran = true;
  } catch (const ScriptError& e) {
    out.fail_with(e);
    out.error = tr_format("the exercise's reference failed: {error}", {{"error", out.error}});
  }
  lua_settop(L, 0);
  out.validation = validate(*out.mesh);
  return out;
}

std::vector<std::string> ScriptedExercise::diagnose(const ExerciseInput& input, const ExerciseOutcome& mine,
                                                    const ExerciseOutcome& reference) const {
  if (diagnose_ < 0) return {};
  if (!takes_values() && (!mine.mesh || !reference.mesh)) return {};
  lua_State* L = runtime_->state();
  lua_settop(L, 0);
  lua_rawgeti(L, LUA_REGISTRYINDEX, diagnose_);
  std::vector<std::string> out;
  try {
    if (takes_values()) {
      push_values_run(L, input, mine, reference);
    } else {
      push_mesh_run(L, input, mine, reference);
    }
    runtime_->start_budget();
    runtime_->call(1, 1);
    if (lua_type(L, 1) == LUA_TSTRING) {
      out.push_back(lua_tostring(L, 1));
    } else if (lua_istable(L, 1)) {
      for (lua_Integer i = 1; i <= static_cast<lua_Integer>(lua_rawlen(L, 1)); ++i) {
        if (lua_rawgeti(L, 1, i) == LUA_TSTRING) out.push_back(lua_tostring(L, -1));
        lua_pop(L, 1);
      }
    }
  } catch (const ScriptError& e) {
    out.push_back(tr_format("the exercise's diagnose failed: {error}", {{"error", e.what()}}));
  }
  lua_settop(L, 0);
  return out;
}

void ScriptedExercise::push_values_run(lua_State* L, const ExerciseInput& input, const ExerciseOutcome& mine,
                                       const ExerciseOutcome& reference) const {
  lua_createtable(L, 0, 4);
  ExerciseInput alone = input;  // the input without its args
  alone.args.clear();
  push_value_arguments(L, alone);
  lua_setfield(L, -2, "input");
  lua_createtable(L, static_cast<int>(input.args.size()), 0);
  for (size_t i = 0; i < input.args.size(); ++i) {
    push_exercise_value(L, input.args[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "args");
  push_exercise_value(L, mine.value);
  lua_setfield(L, -2, "mine");
  push_exercise_value(L, reference.value);
  lua_setfield(L, -2, "reference");
}

void ScriptedExercise::push_mesh_run(lua_State* L, const ExerciseInput& input, const ExerciseOutcome& mine,
                                     const ExerciseOutcome& reference) const {
  lua_createtable(L, 0, 5);
  const auto before = std::make_shared<HalfedgeMesh>(*input.mesh);
  push_mesh(L, before);
  lua_setfield(L, -2, "before");
  push_mesh(L, std::make_shared<HalfedgeMesh>(*mine.mesh));
  lua_setfield(L, -2, "mine");
  push_mesh(L, std::make_shared<HalfedgeMesh>(*reference.mesh));
  lua_setfield(L, -2, "reference");
  if (takes_) {
    push_handle(L, before, input.element);
    lua_setfield(L, -2, "element");
  }
  lua_pushstring(L, mine.returned.c_str());
  lua_setfield(L, -2, "returned");
}

}  // namespace meshedit
