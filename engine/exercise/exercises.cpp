// The built-in exercises, loading student files, and running "mine" and the reference (exercises.h). The
// comparison and its diagnoses are in exercise_compare.cpp.
//
// How a student function is called under the runtime's limits: LuaRuntime only runs text, so two small Lua
// helpers are made when the runtime is new (before any student code exists, so they hold the real `load`,
// `table.pack` and `table.unpack`): `loader` wraps a file's text and `caller` wraps a call, each into a closure
// that stores its results in a table only C++ holds. The closure is put in a global under a reserved name,
// called by a one-line chunk through run_string (so the instruction budget, memory cap and deadline apply),
// and removed again. Everything C++ reads back is read raw (no metamethod of the student's runs outside the
// limits).
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers                         kBuiltinInfo, the Lua helpers (kHelpers), describe_value, check_input
//   returned values                 read_returned_value: what a student function returned, checked for its shape
//   exercises and inputs            the built-in handles, exercise_info, the ExerciseInput makers and describe
//   student code                    StudentCode: load, the exercise API, run (under the limits, recorded)
//   running mine and the reference  load_student_file, run_mine, run_reference
#include "exercise/exercises.h"

#include <algorithm>
#include <new>
#include <stdexcept>

#include <lua.hpp>

#include "core/loop_subdivision.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/normals.h"
#include "core/translation.h"
#include "core/value_format.h"
#include "exercise/exercise_locality.h"
#include "exercise/internal/upsample_runaway.h"
#include "exercise/scripted_exercise.h"
#include "exercise/student_api.h"
#include "script/bezier_bindings.h"
#include "script/edit_recorder.h"
#include "script/lua_handles.h"
#include "script/lua_source.h"
#include "script/mesh_bindings.h"
#include "script/reference_functions.h"
#include "script/script_runtime.h"
#include "script/touch_recorder.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

// Indexed by ExerciseKind.
constexpr ExerciseInfo kBuiltinInfo[] = {
    {"curve", "curve.lua", "evaluate_step", "evaluate_step(points, t) -> list of n - 1 vec3",
     "Part 1: a de Casteljau step"},
    {"patch", "patch.lua", "evaluate", "evaluate(patch, u, v) -> vec3", "Part 2: evaluating a Bezier patch"},
    {"normals", "normals.lua", "vertex_normal", "vertex_normal(v) -> unit vec3",
     "Part 3: area-weighted vertex normals"},
    {"flip", "flip.lua", "flip_edge", "flip_edge(mesh, e) -> e or nil", "Part 4: edge flip"},
    {"split", "split.lua", "split_edge", "split_edge(mesh, e) -> new vertex or nil", "Part 5: edge split"},
    {"upsample", "upsample.lua", "upsample", "upsample(mesh)", "Part 6: Loop subdivision"},
};

constexpr Exercise kBuiltins[] = {Exercise::CurveStep, Exercise::PatchEvaluate, Exercise::VertexNormal,
                                  Exercise::FlipEdge,  Exercise::SplitEdge,     Exercise::Upsample};

constexpr const char* kRunnerGlobal = "__meshedit_exercise_call";
constexpr size_t kMaxOutputLines = 1000;
constexpr size_t kMaxOutputLineBytes = 4096;

constexpr const char* kHelpers = R"lua(
local load, pack, unpack, error = load, table.pack, table.unpack, error
return {
  loader = function(text, name, out)
    return function()
      local chunk, message = load(text, name, "t")
      if not chunk then error(message, 0) end
      out.module = chunk()
    end
  end,
  caller = function(f, args, out)
    return function()
      out.result = pack(f(unpack(args, 1, args.n)))
    end
  end,
}
)lua";

// Describes the Lua value at `index` for messages, reading tables raw. In English whatever the window's language: it
// is the outcome's `returned`, which a definition's diagnose reads and code compares with "nil"; a message puts it in
// through tr (its fixed words, "a string", are in the catalog).
std::string describe_value(lua_State* L, int index) {
  switch (lua_type(L, index)) {
    case LUA_TNONE:
    case LUA_TNIL: return "nil";
    case LUA_TBOOLEAN: return lua_toboolean(L, index) ? "true" : "false";
    case LUA_TNUMBER: return "the number " + format_number(lua_tonumber(L, index));
    case LUA_TSTRING: return "a string";
    case LUA_TTABLE: {
      glm::dvec3 p;
      if (to_vec3(L, index, p)) return format_position(p);
      const lua_Unsigned n = lua_rawlen(L, index);
      return n > 0 ? "a list of " + std::to_string(n) + " values" : "a table";
    }
    case LUA_TUSERDATA: {
      if (const Handle* h = test_handle(L, index)) return h->name();
      if (to_curve(L, index)) return "a curve";
      if (to_patch(L, index)) return "a patch";
      if (to_mesh(L, index)) return "a mesh";
      return "a userdata";
    }
    case LUA_TFUNCTION: return "a function";
    default: return std::string("a ") + luaL_typename(L, index);
  }
}

void check_input(Exercise exercise, const ExerciseInput& input) {
  if (!is_mesh_exercise(exercise)) return;
  if (!input.mesh) throw MeshError(std::string(exercise_info(exercise).function) + " needs a mesh");
  const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition();
  if (exercise == Exercise::Upsample || (scripted && !scripted->takes())) return;
  const ElementKind wanted = scripted                             ? *scripted->takes()
                             : exercise == Exercise::VertexNormal ? ElementKind::Vertex
                                                                  : ElementKind::Edge;
  if (input.element.kind != wanted || !input.mesh->alive(input.element)) {
    throw MeshError(std::string(exercise_info(exercise).function) + " needs a live " + kind_name(wanted) +
                        " of the mesh, got " + format_id(input.element),
                    input.element);
  }
}

// Pushes the arguments of the exercise's function as a list with field n.
void push_arguments(lua_State* L, Exercise exercise, const ExerciseInput& input,
                    const std::shared_ptr<HalfedgeMesh>& mesh) {
  lua_newtable(L);
  int n = 0;
  const auto add = [&] { lua_rawseti(L, -2, ++n); };
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition()) {
    if (scripted->takes_values()) {
      n = scripted->push_value_arguments(L, input);
      for (int i = n; i >= 1; --i) lua_rawseti(L, -1 - i, i);
      lua_pushinteger(L, n);
      lua_setfield(L, -2, "n");
      return;
    }
    push_mesh(L, mesh);
    add();
    if (scripted->takes()) {
      push_handle(L, mesh, input.element);
      add();
    }
  }
  switch (exercise.kind()) {
    case ExerciseKind::CurveStep:
      lua_createtable(L, static_cast<int>(input.points.size()), 0);
      for (size_t i = 0; i < input.points.size(); ++i) {
        push_vec3(L, input.points[i]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
      }
      add();
      lua_pushnumber(L, input.t);
      add();
      break;
    case ExerciseKind::PatchEvaluate:
      push_student_patch(L, input.patch);
      add();
      lua_pushnumber(L, input.u);
      add();
      lua_pushnumber(L, input.v);
      add();
      break;
    case ExerciseKind::VertexNormal:
      push_handle(L, mesh, input.element);
      add();
      break;
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge:
      push_mesh(L, mesh);
      add();
      push_handle(L, mesh, input.element);
      add();
      break;
    case ExerciseKind::Upsample:
      push_mesh(L, mesh);
      add();
      break;
    default: break;  // scripted: above
  }
  lua_pushinteger(L, n);
  lua_setfield(L, -2, "n");
}

}  // namespace

// ---- returned values -------------------------------------------------------------------------------

void read_returned_value(lua_State* L, int index, Exercise exercise, const std::shared_ptr<HalfedgeMesh>& mesh,
                         ExerciseOutcome& out) {
  const ExerciseInfo& info = exercise_info(exercise);
  const int top = lua_absindex(L, index);
  out.returned = describe_value(L, top);
  out.ran = true;
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition();
      scripted && scripted->takes_values()) {
    out.value = read_exercise_value(L, top);
    out.returned = describe(out.value);
    return;
  }
  switch (exercise.kind()) {
    case ExerciseKind::CurveStep: {
      if (lua_type(L, top) != LUA_TTABLE) {
        out.ran = false;
        out.error = tr_format("{function} returned {returned}; it must return a list of points",
                              {{"function", info.function}, {"returned", tr(out.returned)}});
        return;
      }
      const lua_Unsigned n = lua_rawlen(L, top);
      for (lua_Unsigned i = 1; i <= n; ++i) {
        lua_rawgeti(L, top, static_cast<lua_Integer>(i));
        glm::dvec3 p;
        const bool ok = to_vec3(L, -1, p);
        const std::string what = describe_value(L, -1);
        lua_pop(L, 1);
        if (!ok) {
          out.ran = false;
          out.error = tr_format("point {number} of the list {function} returned is {what}, not a point",
                                {{"number", std::to_string(i)}, {"function", info.function}, {"what", tr(what)}});
          return;
        }
        out.points.push_back(p);
      }
      out.returned =
          tr_format(n == 1 ? "a list of {count} point" : "a list of {count} points", {{"count", std::to_string(n)}});
      return;
    }
    case ExerciseKind::PatchEvaluate:
    case ExerciseKind::VertexNormal: {
      glm::dvec3 p;
      if (!to_vec3(L, top, p)) {
        out.ran = false;
        out.error = tr_format("{function} returned {returned}; it must return a vec3",
                              {{"function", info.function}, {"returned", tr(out.returned)}});
        return;
      }
      out.points.push_back(p);
      return;
    }
    case ExerciseKind::Upsample: return;
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge:
    default: {  // and the scripted exercises: an element of the mesh, or nil
      if (const Handle* h = test_handle(L, top)) {
        if (h->mesh() == mesh) out.element = h->ref();
        else out.returned += " of another mesh";
      }
      return;
    }
  }
}

// ---- exercises and inputs ---------------------------------------------------------------------------------

std::span<const Exercise> builtin_exercises() { return kBuiltins; }

const ExerciseInfo& Exercise::info() const {
  if (kind_ == ExerciseKind::Scripted) return definition()->info();
  return kBuiltinInfo[static_cast<size_t>(kind_)];
}

const ExerciseInfo& exercise_info(Exercise exercise) { return exercise.info(); }

bool is_mesh_exercise(Exercise e) {
  switch (e.kind()) {
    case ExerciseKind::CurveStep:
    case ExerciseKind::PatchEvaluate: return false;
    case ExerciseKind::VertexNormal:
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge:
    case ExerciseKind::Upsample: return true;
    case ExerciseKind::Scripted: return !e.definition()->takes_values();
  }
  return false;
}

ExerciseInput ExerciseInput::curve_step(std::vector<glm::dvec3> points, double t) {
  ExerciseInput input;
  input.points = std::move(points);
  input.t = t;
  return input;
}

ExerciseInput ExerciseInput::patch_point(const BezierPatch& patch, double u, double v) {
  ExerciseInput input;
  input.patch = patch;
  input.u = u;
  input.v = v;
  return input;
}

ExerciseInput ExerciseInput::vertex(std::shared_ptr<const HalfedgeMesh> mesh, VertexId v) {
  ExerciseInput input;
  input.mesh = std::move(mesh);
  input.element = v;
  return input;
}

ExerciseInput ExerciseInput::edge(std::shared_ptr<const HalfedgeMesh> mesh, EdgeId e) {
  ExerciseInput input;
  input.mesh = std::move(mesh);
  input.element = e;
  return input;
}

ExerciseInput ExerciseInput::whole_mesh(std::shared_ptr<const HalfedgeMesh> mesh) {
  ExerciseInput input;
  input.mesh = std::move(mesh);
  return input;
}

ExerciseInput ExerciseInput::element_of(std::shared_ptr<const HalfedgeMesh> mesh, ElementRef element) {
  ExerciseInput input;
  input.mesh = std::move(mesh);
  input.element = element;
  return input;
}

ExerciseInput ExerciseInput::of_points(std::vector<glm::dvec3> points, std::vector<ExerciseValue> args) {
  ExerciseInput input;
  input.points = std::move(points);
  input.args = std::move(args);
  return input;
}

ExerciseInput ExerciseInput::of_patch(const BezierPatch& patch, std::vector<ExerciseValue> args) {
  ExerciseInput input;
  input.patch = patch;
  input.args = std::move(args);
  return input;
}

std::string ExerciseInput::describe(Exercise exercise) const {
  const auto mesh_text = [&] {
    if (!mesh) return std::string(tr("no mesh"));
    return tr_format(
        "a mesh with {vertices} vertices and {faces} faces",
        {{"vertices", std::to_string(mesh->num_vertices())}, {"faces", std::to_string(mesh->num_faces())}});
  };
  const auto of_mesh = [&] {
    return tr_format("{element} of {mesh}", {{"element", format_id(element)}, {"mesh", mesh_text()}});
  };
  switch (exercise.kind()) {
    case ExerciseKind::CurveStep:
      return tr_format(points.size() == 1 ? "{count} point, t = {t}" : "{count} points, t = {t}",
                       {{"count", std::to_string(points.size())}, {"t", format_number(t)}});
    case ExerciseKind::PatchEvaluate: return "(u, v) = (" + format_number(u) + ", " + format_number(v) + ")";
    case ExerciseKind::VertexNormal:
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge: return of_mesh();
    case ExerciseKind::Upsample: return mesh_text();
    case ExerciseKind::Scripted: break;
  }
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition(); scripted->takes_values()) {
    std::string text = scripted->input() == ScriptedExercise::Input::Patch
                           ? std::string(tr("a patch of 16 control points"))
                           : tr_format(points.size() == 1 ? "{count} control point" : "{count} control points",
                                       {{"count", std::to_string(points.size())}});
    for (size_t i = 0; i < args.size(); ++i) {
      text = tr_format(i == 0 ? "{inputs}, then {value}" : "{inputs}, {value}",
                       {{"inputs", text}, {"value", value_text(args[i])}});
    }
    return text;
  }
  return element.valid() ? of_mesh() : mesh_text();  // scripted
}

// ---- student code -----------------------------------------------------------------------------------------

void ExerciseOutcome::fail_with(const ScriptError& e, std::string_view prefix) {
  error = std::string(prefix) + e.what();
  out_of_memory = e.out_of_memory();
  limit = e.limit();
}

StudentCode::StudentCode(LuaLimits limits) : runtime_(std::make_unique<ScriptRuntime>(limits)) {
  lua_State* L = runtime_->state();
  // The Bézier API lives in the meshedit module; adding it again is harmless once the module does it itself.
  if (lua_getglobal(L, "meshedit") == LUA_TTABLE) open_bezier_bindings(L);
  lua_pop(L, 1);
  if (luaL_loadbufferx(L, kHelpers, std::char_traits<char>::length(kHelpers), "=exercise helpers", "t") != LUA_OK ||
      lua_pcall(L, 0, 1, 0) != LUA_OK) {
    const std::string message = lua_tostring(L, -1) ? lua_tostring(L, -1) : "?";
    lua_settop(L, 0);
    throw ScriptError("cannot set up the exercise helpers: " + message);
  }
  helpers_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_newtable(L);
  modules_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  // Until an exercise runs, student code sees the API with everything hideable hidden (its files' top level).
  try {
    open_exercise_api(nullptr);
  } catch (const ScriptError& e) {
    if (e.out_of_memory()) throw std::bad_alloc();  // as any other allocation of the constructor
    throw;
  }
  runtime_->set_print([this](const std::string& line) {
    if (output_ && output_->size() < kMaxOutputLines) output_->push_back(line.substr(0, kMaxOutputLineBytes));
  });
}

StudentCode::~StudentCode() = default;

namespace {

// Run in protected mode (guarded: a C++ exception becomes a Lua error) with the ExerciseApi to show, or nullptr.
int apply_exercise_api(lua_State* L) {
  const auto* api = static_cast<const ExerciseApi*>(lua_touserdata(L, 1));
  set_student_api(L, api ? std::span<const std::string>(api->allow_api) : std::span<const std::string>());
  if (api) {
    for (const std::string& name : api->reference) install_reference_function(L, name);
  }
  return 0;
}

}  // namespace

void StudentCode::open_exercise_api(const Exercise* exercise) {
  lua_State* L = runtime_->state();
  lua_pushcfunction(L, guarded<apply_exercise_api>);
  lua_pushlightuserdata(L, const_cast<ExerciseApi*>(exercise ? &exercise_api(*exercise) : nullptr));
  if (const int status = lua_pcall(L, 1, 0, 0); status != LUA_OK) {
    const std::string message = lua_tostring(L, -1) ? lua_tostring(L, -1) : "?";
    lua_settop(L, 0);
    // Memory running out here is not the student's doing: flagged as run_mine's own out-of-memory errors are.
    if (status == LUA_ERRMEM || runtime_->ran_out_of_memory()) {
      throw ScriptError(message, ScriptError::Limit::None, true);
    }
    throw ScriptError("cannot set up the student API: " + message);
  }
}

// Calls the closure in the registry under `closure_ref` through run_string (so the limits apply).
void StudentCode::run_protected(int closure_ref) {
  lua_State* L = runtime_->state();
  const auto set_runner = [&](bool on) {
    lua_pushglobaltable(L);
    lua_pushstring(L, kRunnerGlobal);
    if (on) lua_rawgeti(L, LUA_REGISTRYINDEX, closure_ref);
    else lua_pushnil(L);
    lua_rawset(L, -3);
    lua_pop(L, 1);
  };
  set_runner(true);
  try {
    runtime_->run_string(std::string(kRunnerGlobal) + "()", "exercise");
  } catch (...) {
    set_runner(false);
    throw;
  }
  set_runner(false);
}

void StudentCode::load(const std::filesystem::path& file) {
  const std::optional<std::string> code = read_lua_file(file);
  if (!code) throw ScriptError("cannot open " + file.string());
  load_text(*code, file.filename().string());
}

void StudentCode::load_text(std::string_view code, const std::string& name) {
  lua_State* L = runtime_->state();
  lua_settop(L, 0);
  lua_newtable(L);  // out
  const int out = lua_gettop(L);
  lua_rawgeti(L, LUA_REGISTRYINDEX, helpers_ref_);
  lua_getfield(L, -1, "loader");
  lua_pushlstring(L, code.data(), code.size());
  lua_pushstring(L, ("@" + name).c_str());
  lua_pushvalue(L, out);
  if (lua_pcall(L, 3, 1, 0) != LUA_OK) {
    lua_settop(L, 0);
    throw ScriptError(name + ": cannot prepare the file");
  }
  const int closure = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pushvalue(L, out);
  const int out_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_settop(L, 0);
  try {
    run_protected(closure);
  } catch (const ScriptError& e) {  // a file that is not UTF-8 text says so after its error
    luaL_unref(L, LUA_REGISTRYINDEX, closure);
    luaL_unref(L, LUA_REGISTRYINDEX, out_ref);
    if (e.limit() != ScriptError::Limit::None || e.out_of_memory()) throw;
    throw ScriptError(with_encoding_note(e.what(), code, name), e.limit(), e.out_of_memory());
  } catch (...) {
    luaL_unref(L, LUA_REGISTRYINDEX, closure);
    luaL_unref(L, LUA_REGISTRYINDEX, out_ref);
    throw;
  }
  luaL_unref(L, LUA_REGISTRYINDEX, closure);
  lua_rawgeti(L, LUA_REGISTRYINDEX, out_ref);
  luaL_unref(L, LUA_REGISTRYINDEX, out_ref);
  lua_pushliteral(L, "module");
  if (lua_rawget(L, -2) == LUA_TTABLE) {
    lua_rawgeti(L, LUA_REGISTRYINDEX, modules_ref_);
    lua_pushvalue(L, -2);
    lua_rawseti(L, -2, static_cast<lua_Integer>(lua_rawlen(L, -2) + 1));
  }
  lua_settop(L, 0);
}

// Pushes the exercise's function (the last loaded file's table wins, then the global); false if none.
bool StudentCode::push_function(Exercise exercise) {
  lua_State* L = runtime_->state();
  const char* name = exercise_info(exercise).function;
  lua_rawgeti(L, LUA_REGISTRYINDEX, modules_ref_);
  for (auto i = static_cast<lua_Integer>(lua_rawlen(L, -1)); i >= 1; --i) {
    lua_rawgeti(L, -1, i);
    lua_pushstring(L, name);
    if (lua_rawget(L, -2) == LUA_TFUNCTION) {
      lua_replace(L, -3);
      lua_pop(L, 1);
      return true;
    }
    lua_pop(L, 2);
  }
  lua_pop(L, 1);
  lua_pushglobaltable(L);
  lua_pushstring(L, name);
  if (lua_rawget(L, -2) == LUA_TFUNCTION) {
    lua_remove(L, -2);
    return true;
  }
  lua_pop(L, 2);
  return false;
}

bool StudentCode::defines(Exercise exercise) {
  lua_State* L = runtime_->state();
  const int top = lua_gettop(L);
  const bool found = push_function(exercise);
  lua_settop(L, top);
  return found;
}

namespace {

// An upsample is recorded even when no replay asked for it: the recording's budget is what stops a runaway one early
// (upsample_runaway.h), and its edits say where it was.
void start_recording(std::optional<EditRecorder>& recorder, lua_State* L, Exercise exercise, const ExerciseInput& input,
                     const RunOptions& options, const ExerciseOutcome& out) {
  if (!(options.record_edits || exercise == Exercise::Upsample) || !out.mesh) return;
  EditRecorder::Options recording;
  recording.keep_before = false;
  if (options.max_edits > 0) recording.max_edits = options.max_edits;
  else if (exercise == Exercise::Upsample) recording.max_edits = upsample_edit_budget(*input.mesh);
  recorder.emplace(L, out.mesh, recording);
}

// What the call returned, from the results table at the top of the stack ({result = {value}}).
void read_results(lua_State* L, Exercise exercise, ExerciseOutcome& out) {
  lua_pushliteral(L, "result");
  if (lua_rawget(L, -2) == LUA_TTABLE) {
    lua_rawgeti(L, -1, 1);
    read_returned_value(L, -1, exercise, out.mesh, out);
  } else {
    out.error = "the call of " + std::string(exercise_info(exercise).function) + " gave no result table";
  }
}

}  // namespace

ExerciseOutcome StudentCode::run(Exercise exercise, const ExerciseInput& input, const RunOptions& options) {
  check_input(exercise, input);
  const ExerciseInfo& info = exercise_info(exercise);
  ExerciseOutcome out;
  if (is_mesh_exercise(exercise)) out.mesh = std::make_shared<HalfedgeMesh>(*input.mesh);

  try {
    open_exercise_api(&exercise);
  } catch (const ScriptError& e) {
    out.fail_with(e);
    return out;
  }
  lua_State* L = runtime_->state();
  lua_settop(L, 0);
  if (!push_function(exercise)) {
    out.error = tr_format("your code does not define {function} (as a global or in the table {file} returns)",
                          {{"function", info.function}, {"file", info.file}});
    return out;
  }
  const int function = lua_gettop(L);
  // Counting starts before the arguments are pushed, so the element handed over counts as touched, as the grader
  // counts the arguments of a student's call.
  std::optional<TouchRecorder> touches;
  if (has_locality_bound(exercise) && out.mesh) touches.emplace(L, out.mesh);
  push_arguments(L, exercise, input, out.mesh);
  const int arguments = lua_gettop(L);
  lua_newtable(L);
  const int results = lua_gettop(L);
  lua_rawgeti(L, LUA_REGISTRYINDEX, helpers_ref_);
  lua_getfield(L, -1, "caller");
  lua_pushvalue(L, function);
  lua_pushvalue(L, arguments);
  lua_pushvalue(L, results);
  if (lua_pcall(L, 3, 1, 0) != LUA_OK) {
    lua_settop(L, 0);
    out.error = "cannot prepare the call of " + std::string(info.function);
    return out;
  }
  const int closure = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pushvalue(L, results);
  const int results_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_settop(L, 0);

  std::optional<EditRecorder> recorder;
  start_recording(recorder, L, exercise, input, options, out);
  output_ = &out.output;
  try {
    run_protected(closure);
  } catch (const ScriptError& e) {
    out.fail_with(e);
  }
  output_ = nullptr;
  if (recorder) {
    recorder->stop();
    out.edits = recorder->take_edits();
  }
  if (touches) {
    touches->stop();
    out.touched = touches->count();
  }
  luaL_unref(L, LUA_REGISTRYINDEX, closure);
  lua_rawgeti(L, LUA_REGISTRYINDEX, results_ref);
  luaL_unref(L, LUA_REGISTRYINDEX, results_ref);
  if (out.error.empty()) read_results(L, exercise, out);
  lua_settop(L, 0);
  if (out.mesh) out.validation = validate(*out.mesh);
  return out;
}

// ---- running mine and the reference ----------------------------------------------------------------

std::unique_ptr<StudentCode> load_student_file(const std::filesystem::path& file, LuaLimits limits) {
  auto code = std::make_unique<StudentCode>(limits);
  code->load(file);
  return code;
}

ExerciseOutcome run_mine(StudentCode& code, Exercise exercise, const ExerciseInput& input, const RunOptions& options) {
  return code.run(exercise, input, options);
}

ExerciseOutcome run_reference(Exercise exercise, const ExerciseInput& input) {
  check_input(exercise, input);
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition()) {
    return scripted->run_reference(input);
  }
  ExerciseOutcome out;
  out.ran = true;
  switch (exercise.kind()) {
    case ExerciseKind::CurveStep:
      out.points = de_casteljau_step(std::span<const glm::dvec3>(input.points), input.t);
      out.returned = tr_format(out.points.size() == 1 ? "a list of {count} point" : "a list of {count} points",
                               {{"count", std::to_string(out.points.size())}});
      return out;
    case ExerciseKind::PatchEvaluate:
      out.points = {evaluate_patch(input.patch, input.u, input.v)};
      out.returned = format_position(out.points[0]);
      return out;
    default: break;
  }
  out.mesh = std::make_shared<HalfedgeMesh>(*input.mesh);
  HalfedgeMesh& mesh = *out.mesh;
  switch (exercise.kind()) {
    case ExerciseKind::VertexNormal:
      out.points = {vertex_normal(mesh, VertexId(input.element.index))};
      out.returned = format_position(out.points[0]);
      break;
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge: {
      const EdgeId e(input.element.index);
      const auto take = [&](const auto& result) {
        if (result.ok()) {
          out.element = result.value;
          out.returned = format_id(out.element);
        } else {
          out.refused = result.check.reason;
          out.returned = "nil";
        }
      };
      if (exercise == Exercise::FlipEdge) take(flip(mesh, e));
      else take(split(mesh, e));
      break;
    }
    case ExerciseKind::Upsample: {
      const Check check = loop_subdivide(mesh, LoopWeights::Course);
      if (!check) out.refused = check.reason;
      out.returned = "nil";
      break;
    }
    default: break;
  }
  out.validation = validate(mesh);
  return out;
}

ExerciseReport check_exercise(StudentCode& code, Exercise exercise, const ExerciseInput& input,
                              const RunOptions& options) {
  ExerciseOutcome reference = run_reference(exercise, input);
  ExerciseOutcome mine = run_mine(code, exercise, input, options);
  return compare(exercise, input, std::move(mine), std::move(reference));
}

}  // namespace meshedit
