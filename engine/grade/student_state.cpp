// StudentState: the fresh sandboxed state of one test, its restricted API, and calls into it (see
// student_state.h).
#include "grade/student_state.h"

#include <algorithm>
#include <optional>

#include <lua.hpp>

#include "exercise/exercise_locality.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/student_api.h"
#include "grade/value_bridge.h"
#include "script/bezier_bindings.h"
#include "script/lua_handles.h"
#include "script/lua_source.h"
#include "script/mesh_bindings.h"
#include "script/reference_functions.h"

namespace meshedit {
namespace {

struct Setup {
  const StudentOptions* options;
  int* returned_ref;
};

// Runs in protected mode on a fresh state: the student API (student_api.h), the returned-tables list.
int setup(lua_State* L) {
  const auto* s = static_cast<Setup*>(lua_touserdata(L, 1));
  lua_getglobal(L, "meshedit");
  if (!lua_istable(L, -1)) return luaL_error(L, "the meshedit module is missing");
  // The whole module first (curves and patches too), so that what a test allows is there to allow.
  open_bezier_bindings(L);
  lua_pop(L, 1);
  set_student_api(L, s->options->allow_api);
  lua_newtable(L);
  *s->returned_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  return 0;
}

// The meshes of suite[first .. first + nargs - 1] that are meshes or elements of one, each once, in argument order.
std::vector<std::shared_ptr<HalfedgeMesh>> meshes_among(lua_State* suite, int first, int nargs) {
  std::vector<std::shared_ptr<HalfedgeMesh>> meshes;
  for (int i = first; i < first + nargs; ++i) {
    std::shared_ptr<HalfedgeMesh> mesh = to_mesh(suite, i);
    if (const Handle* h = mesh ? nullptr : test_handle(suite, i)) mesh = h->mesh();
    if (mesh && std::find(meshes.begin(), meshes.end(), mesh) == meshes.end()) meshes.push_back(std::move(mesh));
  }
  return meshes;
}

struct Call {
  StudentState* self;
  const std::string* name;
  lua_State* suite;
  int first;
  int nargs;
  bool only_check;  // has(): push whether the function exists
};

}  // namespace

StudentState::StudentState(const StudentOptions& options) : runtime_(options.limits), options_(options) {
  runtime_.set_print([this](const std::string& line) {
    output_ += line;
    output_ += '\n';
  });
  runtime_.set_print_limit(options.output_bytes);
  lua_State* L = runtime_.state();
  MeshLimits mesh_limits_for_students;
  mesh_limits_for_students.elements_per_kind = uint32_t(1) << 22;
  mesh_limits_for_students.storage_bytes = std::max<size_t>(options.limits.memory_bytes, size_t(64) << 20);
  set_mesh_limits(L, mesh_limits_for_students);
  Setup s{&options_, &returned_tables_ref_};
  lua_pushcfunction(L, guarded<setup>);
  lua_pushlightuserdata(L, &s);
  runtime_.call(1, 0);
  install_references();
}

void StudentState::install_references() {
  lua_State* L = runtime_.state();
  for (const auto& name : options_.reference) {
    lua_pushcfunction(L, [](lua_State* S) {
      const auto* n = static_cast<const std::string*>(lua_touserdata(S, 1));
      if (!install_reference_function(S, *n)) return luaL_error(S, "unknown reference function '%s'", n->c_str());
      return 0;
    });
    lua_pushlightuserdata(L, const_cast<std::string*>(&name));
    runtime_.call(1, 0);
  }
}

void StudentState::load(const Submission& submission, const std::vector<std::string>& files) {
  lua_State* L = runtime_.state();
  for (const auto& name : files) {
    const SubmissionFile* file = submission.find(name);
    if (!file) throw LoadFailure("the submission has no " + name, ScriptError::Limit::None);
    try {
      runtime_.load(file->text, name);
      runtime_.call(0, 1);
    } catch (const ScriptError& e) {  // a file that is not UTF-8 text says so after its error
      const bool limit = e.limit() != ScriptError::Limit::None || e.out_of_memory();
      throw LoadFailure(limit ? std::string(e.what()) : with_encoding_note(e.what(), file->text, name), e.limit());
    }
    if (lua_istable(L, -1)) {
      lua_rawgeti(L, LUA_REGISTRYINDEX, returned_tables_ref_);
      lua_insert(L, -2);
      lua_rawseti(L, -2, static_cast<lua_Integer>(lua_rawlen(L, -2) + 1));
    }
    lua_settop(L, 0);
  }
  install_references();
}

void StudentState::push_function(const std::string& name) {
  lua_State* L = runtime_.state();
  lua_pushglobaltable(L);
  lua_pushlstring(L, name.data(), name.size());
  lua_rawget(L, -2);
  lua_remove(L, -2);
  if (lua_isfunction(L, -1)) return;
  lua_pop(L, 1);
  lua_rawgeti(L, LUA_REGISTRYINDEX, returned_tables_ref_);
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    lua_pushlstring(L, name.data(), name.size());
    lua_rawget(L, -2);
    if (lua_isfunction(L, -1)) {
      lua_replace(L, -3);
      lua_pop(L, 1);
      return;
    }
    lua_pop(L, 2);
  }
  lua_pop(L, 1);
  lua_pushnil(L);
}

int StudentState::call_trampoline(lua_State* L) {
  auto* c = static_cast<Call*>(lua_touserdata(L, 1));
  lua_settop(L, 0);
  c->self->push_function(*c->name);
  if (c->only_check) {
    lua_pushboolean(L, lua_isfunction(L, -1));
    return 1;
  }
  if (!lua_isfunction(L, -1)) {
    lua_pushfstring(L, "the submission does not define a function %s", c->name->c_str());
    return lua_error(L);
  }
  std::string failure;
  try {
    ValueBridge bridge(c->suite, L, BridgeOptions{.bezier_as_tables = true});
    for (int i = 0; i < c->nargs; ++i) bridge.copy(c->first + i, "argument " + std::to_string(i + 1));
  } catch (const BridgeError& e) {
    failure = std::string("the grader could not pass ") + e.what();
  }
  if (!failure.empty()) {
    lua_pushstring(L, failure.c_str());
    return lua_error(L);
  }
  lua_call(L, c->nargs, LUA_MULTRET);
  return lua_gettop(L);
}

bool StudentState::has(const std::string& name) {
  lua_State* L = runtime_.state();
  const int base = lua_gettop(L);
  Call c{this, &name, nullptr, 0, 0, true};
  lua_pushcfunction(L, call_trampoline);
  lua_pushlightuserdata(L, &c);
  runtime_.call(1, 1);
  const bool result = lua_toboolean(L, -1);
  lua_settop(L, base);
  return result;
}

int StudentState::call(const std::string& name, lua_State* suite, int first, int nargs) {
  lua_State* L = runtime_.state();
  const int base = lua_gettop(L);
  Call c{this, &name, suite, first, nargs, false};
  // Only the functions held to a locality bound (flip_edge, split_edge) are counted: counting costs a flag per element
  // of every mesh given and a test per handle made, which no other call needs.
  last_call_touches_.clear();
  std::vector<std::unique_ptr<TouchRecorder>> touches;
  if (const std::optional<Exercise> exercise = find_exercise(name); exercise && has_locality_bound(*exercise)) {
    for (const std::shared_ptr<HalfedgeMesh>& mesh : meshes_among(suite, first, nargs)) {
      touches.push_back(std::make_unique<TouchRecorder>(L, mesh));
    }
  }
  lua_pushcfunction(L, call_trampoline);
  lua_pushlightuserdata(L, &c);
  const int n = runtime_.call(1, LUA_MULTRET);
  for (const std::unique_ptr<TouchRecorder>& recorder : touches) {
    recorder->stop();
    last_call_touches_.push_back({recorder->mesh(), recorder->count()});
  }
  struct Restore {
    lua_State* L;
    int base;
    ~Restore() { lua_settop(L, base); }
  } restore{L, base};
  luaL_checkstack(suite, n + 8, "too many results");
  ValueBridge bridge(L, suite);
  try {
    for (int i = 1; i <= n; ++i) bridge.copy(base + i, "result " + std::to_string(i));
  } catch (const BridgeError& e) {
    throw BridgeError(name + " returned a value the grader cannot read: " + e.what());
  }
  return n;
}

}  // namespace meshedit
