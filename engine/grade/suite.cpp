// Suite: loading a suite file (the suite{} and test{} declarations) and running one test in this process
// (see suite.h).
//
// Map of this file (each part starts at its `// ---- name` banner):
//   fields                      Fields (what suite{} and test{} declare), limits_for, Declarations, Context
//   reading declarations        SuiteApi: string_list, number_field, read_fields and its parts
//   the suite file's functions  suite{}, test{}, include(), exercise{}, fixture()
//   the student table           student.f(...), student:has, student:output, push_student_table
//   loading                     Suite::load, from_text, finish_loading, files_for
//   running a test              end_for_limit, Suite::run_test_here
#include "grade/suite.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <type_traits>
#include <utility>

#include <lua.hpp>

#include "core/file_bytes.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "exercise/student_api.h"
#include "grade/expectations.h"
#include "grade/student_state.h"
#include "script/bezier_bindings.h"
#include "script/exception_text.h"
#include "script/lua_handles.h"
#include "script/mesh_bindings.h"
#include "script/reference_functions.h"
#include "script/script_runtime.h"

namespace meshedit {
namespace {

// ---- fields ----------------------------------------------------------------------------------------

constexpr double kMaxTimeLimit = 600.0;
constexpr double kDefaultTimeLimit = 10.0;
constexpr size_t kDefaultMemoryMb = 256;
constexpr size_t kSuiteMemoryBytes = size_t(1) << 30;
// Lua instructions per second of a test's time limit: the budget is a deterministic backstop only, set well
// above what any machine runs in that time, so the wall clock is what a slow solution meets.
constexpr double kInstructionsPerSecond = 2e9;

const std::set<std::string> kVisibilities = {"visible", "hidden", "after_due_date", "after_published"};

struct Fields {
  std::optional<std::string> name, number, visibility, language;
  std::optional<double> points, time_limit, memory_mb, output_kb;
  std::optional<bool> partial, extra_credit;
  std::optional<std::vector<std::string>> files, reference, allow_api, tags;
  int run_ref = LUA_NOREF;
};

LuaLimits limits_for(double seconds, size_t memory_bytes) {
  LuaLimits l;
  l.wall_seconds = seconds;
  l.memory_bytes = memory_bytes;
  l.instructions = static_cast<uint64_t>(std::max(1.0, seconds) * kInstructionsPerSecond);
  return l;
}

}  // namespace

// What the files declared: one scope of suite{} defaults per file (the suite file is scope 0, each include
// adds one), and the tests, each with the scope it was declared in.
struct Suite::Declarations {
  std::vector<Fields> scopes{Fields{}};
  size_t current = 0;
  std::vector<std::pair<Fields, size_t>> tests;
};

struct Suite::Context {
  StudentState* student = nullptr;
  bool student_failed = false;
  std::string student_error;
  ScriptError::Limit student_limit = ScriptError::Limit::None;
};

// A scripted exercise's fixture as a test's run function: the student's function on a copy of the fixture's mesh,
// checked by expect.exercise against the mesh before the call.
constexpr const char* kFixtureTest = R"lua(local fixture, values_of = ...
return function(name, call, index, what, on_values)
  return function(student, expect)
    if on_values then
      local input, args = values_of(name, index)
      local result = student[call](table.unpack(args, 1, args.n))
      return expect.exercise(name, input, result, nil, what)
    end
    local before, kind, id = fixture(name, index)
    local mine = before:copy()
    local result
    if kind then
      result = student[call](mine, mine[kind](mine, id))
    else
      result = student[call](mine)
    end
    return expect.exercise(name, { mesh = before, element = id }, result, mine, what)
  end
end
)lua";

// The C functions of the suite's Lua API (friends of Suite).
struct SuiteApi {
  // ---- reading declarations ------------------------------------------------------------------------

  static Suite& suite_of(lua_State* L) { return *static_cast<Suite*>(lua_touserdata(L, lua_upvalueindex(1))); }

  static std::vector<std::string> string_list(lua_State* L, int index, const char* field) {
    if (!lua_istable(L, index)) luaL_error(L, "field '%s' must be a list of strings", field);
    std::vector<std::string> out;
    const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, index, i);
      if (lua_type(L, -1) != LUA_TSTRING) luaL_error(L, "field '%s' must be a list of strings", field);
      out.emplace_back(lua_tostring(L, -1));
      lua_pop(L, 1);
    }
    return out;
  }

  static double number_field(lua_State* L, int index, const char* field, double min, double max) {
    if (lua_type(L, index) != LUA_TNUMBER) luaL_error(L, "field '%s' must be a number", field);
    const double x = lua_tonumber(L, index);
    if (!(x >= min && x <= max)) luaL_error(L, "field '%s' must be between %f and %f", field, min, max);
    return x;
  }

  // "a, b, c".
  template <class Names>
  static std::string comma_list(const Names& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
  }

  static bool boolean_field(lua_State* L, int index, const char* field) {
    if (!lua_isboolean(L, index)) luaL_error(L, "field '%s' must be true or false", field);
    return lua_toboolean(L, index);
  }

  // Reads the declaration table at argument 1 into `f`; `test` says which fields are allowed. Fields are read in a
  // fixed order, so a table with several wrong fields is refused for the same one each time.
  static void read_fields(lua_State* L, Fields& f, bool test) {
    luaL_checktype(L, 1, LUA_TTABLE);
    refuse_unknown_fields(L, test);
    if (get_field(L, "name")) {
      if (lua_type(L, -1) != LUA_TSTRING) luaL_error(L, "field 'name' must be a string");
      f.name = lua_tostring(L, -1);
    }
    lua_pop(L, 1);
    if (test) read_test_fields(L, f);
    read_run_fields(L, f, test);
    read_name_lists(L, f);
  }

  static bool get_field(lua_State* L, const char* field) { return lua_getfield(L, 1, field) != LUA_TNIL; }

  static void refuse_unknown_fields(lua_State* L, bool test) {
    static const std::set<std::string> kSuiteFields = {"name",       "files",     "time_limit", "memory_mb",
                                                       "visibility", "reference", "allow_api",  "partial",
                                                       "output_kb",  "language"};
    static const std::set<std::string> kTestFields = {"name",      "points",       "number", "visibility", "time_limit",
                                                      "memory_mb", "partial",      "files",  "reference",  "allow_api",
                                                      "tags",      "extra_credit", "run"};
    const auto& allowed = test ? kTestFields : kSuiteFields;
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
      lua_pop(L, 1);
      if (lua_type(L, -1) != LUA_TSTRING || !allowed.contains(lua_tostring(L, -1))) {
        const std::string key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : luaL_typename(L, -1);
        luaL_error(L, "%s: unknown field '%s' (fields: %s)", test ? "test" : "suite", key.c_str(),
                   comma_list(allowed).c_str());
      }
    }
  }

  // What only a test declares: its number, points, tags, extra credit and run function (name required).
  static void read_test_fields(lua_State* L, Fields& f) {
    if (!f.name || f.name->empty()) luaL_error(L, "test: field 'name' is required");
    if (get_field(L, "number")) {
      if (lua_type(L, -1) != LUA_TSTRING && lua_type(L, -1) != LUA_TNUMBER) {
        luaL_error(L, "field 'number' must be a string");
      }
      f.number = lua_tostring(L, -1);
    }
    lua_pop(L, 1);
    if (get_field(L, "points")) f.points = number_field(L, -1, "points", 0.0, 1e6);
    lua_pop(L, 1);
    if (get_field(L, "tags")) f.tags = string_list(L, lua_gettop(L), "tags");
    lua_pop(L, 1);
    if (get_field(L, "extra_credit")) f.extra_credit = boolean_field(L, -1, "extra_credit");
    lua_pop(L, 1);
    if (lua_getfield(L, 1, "run") != LUA_TFUNCTION) {
      luaL_error(L, "test '%s': field 'run' must be a function(student, expect)", f.name->c_str());
    }
    f.run_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  }

  // How a test runs and is shown: visibility, time and memory limits, output cap (suites only), partial credit.
  static void read_run_fields(lua_State* L, Fields& f, bool test) {
    if (get_field(L, "visibility")) {
      if (lua_type(L, -1) != LUA_TSTRING || !kVisibilities.contains(lua_tostring(L, -1))) {
        luaL_error(L, "field 'visibility' must be visible, hidden, after_due_date or after_published");
      }
      f.visibility = lua_tostring(L, -1);
    }
    lua_pop(L, 1);
    if (get_field(L, "time_limit")) f.time_limit = number_field(L, -1, "time_limit", 0.01, kMaxTimeLimit);
    lua_pop(L, 1);
    if (get_field(L, "memory_mb")) f.memory_mb = number_field(L, -1, "memory_mb", 4, 8192);
    lua_pop(L, 1);
    if (!test) {
      if (get_field(L, "output_kb")) f.output_kb = number_field(L, -1, "output_kb", 1, 1024);
      lua_pop(L, 1);
      if (get_field(L, "language")) {
        const std::optional<Language> language =
            lua_type(L, -1) == LUA_TSTRING ? language_by_code(lua_tostring(L, -1)) : std::nullopt;
        if (!language || std::string(lua_tostring(L, -1)) != language_code(*language))
          luaL_error(L, "field 'language' must be en or zh (the language the feedback is written in)");
        f.language = lua_tostring(L, -1);
      }
      lua_pop(L, 1);
    }
    if (get_field(L, "partial")) f.partial = boolean_field(L, -1, "partial");
    lua_pop(L, 1);
  }

  // The student files a test loads, the reference functions it installs and the hidden API it allows.
  static void read_name_lists(lua_State* L, Fields& f) {
    if (get_field(L, "files")) f.files = string_list(L, lua_gettop(L), "files");
    lua_pop(L, 1);
    if (get_field(L, "reference")) {
      f.reference = string_list(L, lua_gettop(L), "reference");
      for (const auto& r : *f.reference) {
        if (!is_reference_function(r)) {
          luaL_error(L, "unknown reference function '%s' (there are: %s)", r.c_str(),
                     comma_list(reference_function_names()).c_str());
        }
      }
    }
    lua_pop(L, 1);
    if (get_field(L, "allow_api")) {
      f.allow_api = string_list(L, lua_gettop(L), "allow_api");
      const auto& names = hideable_api_names();
      for (const auto& a : *f.allow_api) {
        if (std::find(names.begin(), names.end(), a) == names.end()) {
          luaL_error(L, "allow_api: unknown entry '%s' (there are: %s)", a.c_str(), comma_list(names).c_str());
        }
      }
    }
    lua_pop(L, 1);
  }

  // ---- the suite file's functions ------------------------------------------------------------------

  static int declare_suite(lua_State* L) {
    Suite& s = suite_of(L);
    if (!s.declarations_) return luaL_error(L, "suite{} can only be called while the suite file loads");
    read_fields(L, s.declarations_->scopes[s.declarations_->current], false);
    return 0;
  }

  static int declare_test(lua_State* L) {
    Suite& s = suite_of(L);
    if (!s.declarations_) return luaL_error(L, "test{} can only be called while the suite file loads");
    Fields f;
    read_fields(L, f, true);
    s.declarations_->tests.emplace_back(std::move(f), s.declarations_->current);
    return 0;
  }

  // include("curve.lua"): runs another suite file (relative to this suite's folder) in the same state, so one
  // assignment suite can gather the parts' suites. Only while loading. The included file's suite{} defaults
  // apply to its own tests only (then the including file's, then the built-in ones).
  static int include(lua_State* L) {
    Suite& s = suite_of(L);
    if (!s.declarations_) return luaL_error(L, "include() can only be called while the suite file loads");
    const std::string name = luaL_checkstring(L, 1);
    const std::filesystem::path path = s.folder_ / name;
    std::string text;
    {
      FileBytes file = read_file_bytes(path);
      if (!file.ok()) return luaL_error(L, "include: cannot open %s", path.string().c_str());
      text = std::move(file.bytes);
    }
    const std::string chunk = "@" + (std::filesystem::path(s.chunk_folder_) / name).generic_string();
    if (luaL_loadbufferx(L, text.data(), text.size(), chunk.c_str(), "t") != LUA_OK) return lua_error(L);
    Suite::Declarations& d = *s.declarations_;
    const size_t outer = d.current;
    d.scopes.emplace_back();
    d.current = d.scopes.size() - 1;
    lua_call(L, 0, 0);  // an error leaves the scope set: loading fails as a whole anyway
    d.current = outer;
    return 0;
  }

  // exercise{...}: a file of scripts/exercises (scripted_exercise.h) used as a suite. The definition is loaded from
  // the calling file into a state of its own and registered (expect.exercise finds it by name); the suite's defaults
  // become its student file and allowed API, and each fixture a test that runs the student's function on a copy of
  // the fixture's mesh and checks it with expect.exercise, as the window checks it.
  static int declare_exercise(lua_State* L) {
    Suite& s = suite_of(L);
    if (!s.declarations_) return luaL_error(L, "exercise{} can only be called while the suite file loads");
    lua_Debug caller;
    if (!lua_getstack(L, 1, &caller) || !lua_getinfo(L, "S", &caller)) return luaL_error(L, "exercise: no caller");
    std::string source = caller.source;
    if (!source.empty() && (source[0] == '@' || source[0] == '=')) source.erase(0, 1);
    const std::filesystem::path file = s.folder_ / std::filesystem::path(source).filename();
    std::shared_ptr<const ScriptedExercise> definition;
    try {
      std::shared_ptr<ScriptedExercise> loaded = ScriptedExercise::load(file);
      register_scripted_exercise(loaded);
      definition = std::move(loaded);
    } catch (const ScriptError& e) {
      return luaL_error(L, "%s", e.what());
    }
    const ExerciseInfo& info = definition->info();
    lua_getglobal(L, "suite");
    lua_createtable(L, 0, 3);
    lua_pushstring(L, info.name);
    lua_setfield(L, -2, "name");
    lua_createtable(L, 1, 0);
    lua_pushstring(L, info.file);
    lua_rawseti(L, -2, 1);
    lua_setfield(L, -2, "files");
    lua_createtable(L, static_cast<int>(definition->api().allow_api.size()), 0);
    for (size_t i = 0; i < definition->api().allow_api.size(); ++i) {
      lua_pushstring(L, definition->api().allow_api[i].c_str());
      lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_setfield(L, -2, "allow_api");
    lua_call(L, 1, 0);
    if (luaL_loadbufferx(L, kFixtureTest, std::char_traits<char>::length(kFixtureTest), "=exercise fixtures", "t") !=
        LUA_OK) {
      return lua_error(L);
    }
    lua_pushcfunction(L, fixture_of);
    lua_pushcfunction(L, values_of);
    lua_call(L, 2, 1);  // make_run(name, call, index, what, on_values)
    const int make_run = lua_gettop(L);
    const std::vector<ScriptedFixture>& fixtures = definition->fixtures();
    for (size_t i = 0; i < fixtures.size(); ++i) {
      lua_getglobal(L, "test");
      lua_createtable(L, 0, 4);
      lua_pushstring(L, std::to_string(i + 1).c_str());
      lua_setfield(L, -2, "number");
      lua_pushstring(L, fixtures[i].name.c_str());
      lua_setfield(L, -2, "name");
      lua_pushnumber(L, fixtures[i].points);
      lua_setfield(L, -2, "points");
      lua_pushvalue(L, make_run);
      lua_pushstring(L, info.name);
      lua_pushstring(L, info.function);
      lua_pushinteger(L, static_cast<lua_Integer>(i + 1));
      lua_pushstring(L, fixtures[i].name.c_str());
      lua_pushboolean(L, definition->takes_values());
      lua_call(L, 5, 1);
      lua_setfield(L, -2, "run");
      lua_call(L, 1, 0);
    }
    return 0;
  }

  // The fixture `index` of the exercise named at 1 (the index at 2), with its definition; a Lua error when none.
  static std::pair<std::shared_ptr<const ScriptedExercise>, const ScriptedFixture*> fixture_at(lua_State* L) {
    const std::optional<Exercise> exercise = find_exercise(luaL_checkstring(L, 1));
    if (!exercise) luaL_error(L, "%s", exercise_registry().unknown_name_error(lua_tostring(L, 1)).c_str());
    std::shared_ptr<const ScriptedExercise> definition = exercise->definition();
    const lua_Integer index = luaL_checkinteger(L, 2);
    if (!definition || index < 1 || static_cast<size_t>(index) > definition->fixtures().size()) {
      luaL_error(L, "no fixture %d of the exercise %s", int(index), lua_tostring(L, 1));
    }
    const ScriptedFixture* fixture = &definition->fixtures()[static_cast<size_t>(index - 1)];
    return {std::move(definition), fixture};
  }

  // values_of(name, index) -> the input for expect.exercise ({control =, args =} or {patch =, args =}) and the
  // arguments of the student's call as a list with n (the input, then the args): fresh tables each, so what the
  // student's call does to its arguments changes nothing of what the check reads.
  static int values_of(lua_State* L) {
    const auto [definition, fixture] = fixture_at(L);
    const ExerciseInput input = definition->input_of(*fixture);
    const bool patch = definition->input() == ScriptedExercise::Input::Patch;
    lua_createtable(L, 0, 2);
    if (patch) {
      push_student_patch(L, input.patch);
    } else {
      push_exercise_value(L, ExerciseValue::of_points(input.points));
    }
    lua_setfield(L, -2, patch ? "patch" : "control");
    push_exercise_value(L, ExerciseValue::of_list(input.args));
    lua_setfield(L, -2, "args");
    lua_newtable(L);
    int n = 0;
    std::string error;
    try {
      n = definition->push_value_arguments(L, input);
    } catch (const ScriptError& e) {
      error = e.what();
    }
    if (!error.empty()) return luaL_error(L, "%s", error.c_str());
    for (int i = n; i >= 1; --i) lua_rawseti(L, -1 - i, i);
    lua_pushinteger(L, n);
    lua_setfield(L, -2, "n");
    return 2;
  }

  // fixture(name, index) -> a copy of the fixture's mesh, the kind of element the exercise takes ("edge") or nil, the
  // element's id or nil.
  static int fixture_of(lua_State* L) {
    const auto [definition, found] = fixture_at(L);
    const ScriptedFixture& fixture = *found;
    push_mesh(L, std::make_shared<HalfedgeMesh>(*fixture.mesh));
    if (!definition->takes()) return 1;
    lua_pushstring(L, kind_name(*definition->takes()));
    lua_pushinteger(L, fixture.element.index);
    return 3;
  }

  // ---- the student table ---------------------------------------------------------------------------

  static Suite::Context& context(lua_State* L) {
    Suite& s = suite_of(L);
    if (!s.current_ || !s.current_->student) luaL_error(L, "student can only be used while a test runs");
    return *s.current_;
  }

  // Hands what the student's call touched of each mesh it was given to the test's recorder (expect.exercise).
  static void note_touches(Suite& s, const StudentState& student) {
    if (!s.recorder_slot_) return;
    for (const MeshTouches& t : student.last_call_touches()) s.recorder_slot_->note_touches(t.mesh, t.count);
  }

  // student.NAME(...): the submission's function, run in its sandbox.
  static int call_named(lua_State* L, const std::string& name, int first) {
    Suite::Context& c = context(L);
    const int nargs = lua_gettop(L) - first + 1;
    std::string error;
    ScriptError::Limit limit = ScriptError::Limit::None;
    int n = 0;
    bool failed = false;
    try {
      n = c.student->call(name, L, first, nargs);
      note_touches(suite_of(L), *c.student);
    } catch (const ScriptError& e) {
      error = e.what();
      limit = e.limit();
      failed = true;
    } catch (const std::exception& e) {
      error = exception_text(e);
      failed = true;
    }
    if (failed) {
      c.student_failed = true;
      c.student_error = error;
      c.student_limit = limit;
      lua_pushlstring(L, error.data(), error.size());
      return lua_error(L);
    }
    return n;
  }

  static int student_function(lua_State* L) {
    const std::string name = lua_tostring(L, lua_upvalueindex(2));
    return call_named(L, name, 1);
  }

  static int student_call(lua_State* L) {
    const std::string name = luaL_checkstring(L, 1);
    return call_named(L, name, 2);
  }

  static int student_has(lua_State* L) {
    Suite::Context& c = context(L);
    const std::string name = luaL_checkstring(L, 1);
    std::string error;
    bool result = false;
    try {
      result = c.student->has(name);
    } catch (const std::exception& e) {
      error = exception_text(e);
    }
    if (!error.empty()) return luaL_error(L, "%s", error.c_str());
    lua_pushboolean(L, result);
    return 1;
  }

  static int student_output(lua_State* L) {
    Suite::Context& c = context(L);
    lua_pushlstring(L, c.student->output().data(), c.student->output().size());
    return 1;
  }

  // __index of the student table: the reserved names, else a function calling the student's NAME.
  static int student_index(lua_State* L) {
    const std::string key = luaL_checkstring(L, 2);
    lua_pushvalue(L, lua_upvalueindex(1));
    if (key == "has") lua_pushcclosure(L, student_has, 1);
    else if (key == "call") lua_pushcclosure(L, student_call, 1);
    else if (key == "output") lua_pushcclosure(L, student_output, 1);
    else {
      lua_pushvalue(L, 2);
      lua_pushcclosure(L, student_function, 2);
    }
    return 1;
  }

  static void push_student_table(lua_State* L, Suite* s) {
    lua_newtable(L);
    lua_createtable(L, 0, 2);
    lua_pushlightuserdata(L, s);
    lua_pushcclosure(L, student_index, 1);
    lua_setfield(L, -2, "__index");
    lua_pushliteral(L, "student");
    lua_setfield(L, -2, "__metatable");
    lua_setmetatable(L, -2);
  }
};

// ---- loading ---------------------------------------------------------------------------------------

Suite::Suite() = default;
Suite::~Suite() = default;

std::unique_ptr<Suite> Suite::load(const std::filesystem::path& path) {
  const FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw GradeError("cannot open the suite " + path.string());
  std::filesystem::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  // Named by the path as given, as lua.c names scripts: "suites/curve.lua" must not read like the student's
  // curve.lua in messages.
  return from_text(file.bytes, path.generic_string(), std::filesystem::absolute(folder).lexically_normal());
}

std::unique_ptr<Suite> Suite::from_text(std::string_view text, const std::string& chunk_name,
                                        const std::filesystem::path& folder) {
  std::unique_ptr<Suite> s(new Suite());
  s->runtime_ = std::make_unique<ScriptRuntime>(limits_for(60.0, kSuiteMemoryBytes));
  s->declarations_ = std::make_unique<Declarations>();
  lua_State* L = s->runtime_->state();
  // The Bézier part of the module (curves and patches: the references of parts 1 and 2).
  if (lua_getglobal(L, "meshedit") == LUA_TTABLE) open_bezier_bindings(L);
  lua_pop(L, 1);
  lua_pushlightuserdata(L, s.get());
  lua_pushcclosure(L, SuiteApi::declare_suite, 1);
  lua_setglobal(L, "suite");
  lua_pushlightuserdata(L, s.get());
  lua_pushcclosure(L, SuiteApi::declare_test, 1);
  lua_setglobal(L, "test");
  lua_pushlightuserdata(L, s.get());
  lua_pushcclosure(L, SuiteApi::include, 1);
  lua_setglobal(L, "include");
  lua_pushlightuserdata(L, s.get());
  lua_pushcclosure(L, guarded<SuiteApi::declare_exercise>, 1);
  lua_setglobal(L, "exercise");
  s->folder_ = folder;
  s->chunk_folder_ = std::filesystem::path(chunk_name).parent_path().generic_string();
  lua_pushstring(L, folder.string().c_str());
  lua_setglobal(L, "SUITE_DIR");
  try {
    s->runtime_->run_string(text, chunk_name);
  } catch (const ScriptError& e) {
    throw GradeError(std::string("the suite did not load: ") + e.what());
  }
  s->finish_loading(chunk_name);
  return s;
}

void Suite::finish_loading(const std::string& chunk_name) {
  const Declarations& d = *declarations_;
  const Fields& top = d.scopes[0];
  name_ = top.name.value_or(std::filesystem::path(chunk_name).stem().string());  // "flip" for suites/flip.lua
  if (top.output_kb) output_bytes_ = static_cast<size_t>(*top.output_kb * 1024);
  if (top.language) language_ = language_by_code(*top.language).value_or(Language::English);
  if (d.tests.empty()) throw GradeError("the suite " + chunk_name + " declares no test");
  for (size_t i = 0; i < d.tests.size(); ++i) {
    const Fields& f = d.tests[i].first;
    const Fields& own = d.scopes[d.tests[i].second];
    // The test's field, else its file's suite{}, else the suite file's, else the built-in default.
    const auto pick = [&](const auto member, auto fallback) {
      using Value = std::decay_t<decltype(*(f.*member))>;
      for (const Fields* source : {&f, &own, &top}) {
        if ((source->*member).has_value()) return Value(*(source->*member));
      }
      return Value(fallback);
    };
    TestSpec t;
    t.name = *f.name;
    t.number = f.number.value_or(std::to_string(i + 1));
    t.points = f.points.value_or(1.0);
    t.visibility = pick(&Fields::visibility, std::string("visible"));
    t.time_limit = pick(&Fields::time_limit, kDefaultTimeLimit);
    t.memory_mb = static_cast<size_t>(pick(&Fields::memory_mb, double(kDefaultMemoryMb)));
    t.partial = pick(&Fields::partial, false);
    t.files = pick(&Fields::files, std::vector<std::string>{});
    t.reference = pick(&Fields::reference, std::vector<std::string>{});
    t.allow_api = pick(&Fields::allow_api, std::vector<std::string>{});
    t.tags = f.tags.value_or(std::vector<std::string>{});
    t.extra_credit = f.extra_credit.value_or(false);
    t.run_ref = f.run_ref;
    tests_.push_back(std::move(t));
  }
  declarations_.reset();
}

void Suite::cap_time_limit(size_t index, double seconds) {
  if (index < tests_.size()) tests_[index].time_limit = std::min(tests_[index].time_limit, seconds);
}

std::vector<std::string> Suite::files_for(const TestSpec& spec, const Submission& submission) {
  if (!spec.files.empty()) return spec.files;
  std::vector<std::string> all;
  for (const auto& f : submission.files()) all.push_back(f.name);
  return all;
}

std::vector<std::string> Suite::named_files() const {
  std::vector<std::string> names;
  for (const auto& t : tests_) names.insert(names.end(), t.files.begin(), t.files.end());
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

namespace {

// ---- running a test --------------------------------------------------------------------------------

RunEnd end_for_limit(ScriptError::Limit limit, RunEnd otherwise) {
  switch (limit) {
    case ScriptError::Limit::Instructions:
    case ScriptError::Limit::Time:
    case ScriptError::Limit::Stopped: return RunEnd::Timeout;
    case ScriptError::Limit::Memory: return RunEnd::Memory;
    case ScriptError::Limit::Changes:
    case ScriptError::Limit::None: break;
  }
  return otherwise;
}

}  // namespace

TestRun Suite::run_test_here(size_t index, const Submission& submission) {
  TestRun run;
  if (index >= tests_.size()) {
    run.end = RunEnd::Error;
    run.error = "no test number " + std::to_string(index);
    return run;
  }
  const TestSpec& spec = tests_[index];
  TestRecorder recorder(run);
  recorder_slot_ = &recorder;
  Context context;
  struct Clear {
    Suite* s;
    ~Clear() {
      s->current_ = nullptr;
      s->recorder_slot_ = nullptr;
    }
  } clear{this};
  std::optional<StudentState> student;
  try {
    StudentOptions options;
    options.limits = limits_for(spec.time_limit, spec.memory_mb << 20);
    options.output_bytes = output_bytes_;
    options.reference = spec.reference;
    options.allow_api = spec.allow_api;
    student.emplace(options);
    context.student = &*student;
    current_ = &context;
    student->runtime().start_budget();
    try {
      student->load(submission, files_for(spec, submission));
    } catch (const LoadFailure& e) {
      run.end = end_for_limit(e.limit(), RunEnd::LoadError);
      run.error = std::string("the submission did not load: ") + e.what();
      run.output = student->output();
      run.output_truncated = student->output_truncated();
      return run;
    }
    lua_State* L = runtime_->state();
    runtime_->set_limits(limits_for(spec.time_limit, kSuiteMemoryBytes));
    runtime_->start_budget();
    lua_settop(L, 0);
    lua_rawgeti(L, LUA_REGISTRYINDEX, spec.run_ref);
    SuiteApi::push_student_table(L, this);
    push_expect_table(L, &recorder_slot_);
    try {
      runtime_->call(2, 0);
    } catch (const ScriptError& e) {
      if (context.student_failed && context.student_error == e.what()) {
        run.end = end_for_limit(context.student_limit, RunEnd::Error);
      } else {
        run.end = end_for_limit(e.limit(), RunEnd::Error);
      }
      run.error = e.what();
    }
    lua_settop(L, 0);
  } catch (const std::exception& e) {  // the student state could not be made: the grader's problem
    run.end = RunEnd::Error;
    run.error = std::string("the grader could not run this test: ") + exception_text(e);
  }
  recorder_slot_ = nullptr;
  if (student) {
    run.output = student->output();
    run.output_truncated = student->output_truncated();
  }
  return run;
}

}  // namespace meshedit
