// The one list of what student code may call, and hiding the rest (see student_api.h).
#include "exercise/student_api.h"

#include <algorithm>
#include <cstring>
#include <span>
#include <string>

#include <lua.hpp>

#include "exercise/scripted_exercise.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

struct ApiEntry {
  const char* name;  // how suites and messages spell it
  bool method;       // a mesh method (else a field of the meshedit module)
  const char* field;
  const char* why;  // the end of hidden_api_message
};

constexpr const char* kNoFiles = "student code cannot read or write files";

const ApiEntry kHideable[] = {
    {"mesh:flip", true, "flip", "it is what flip_edge does, so write the pointer updates yourself"},
    {"mesh:split", true, "split", "it is what split_edge does, so write the pointer updates yourself"},
    {"mesh:collapse", true, "collapse", "it is a reference operation that no exercise uses"},
    {"mesh:loop_subdivide", true, "loop_subdivide", "it is what upsample does, so write the five steps yourself"},
    {"mesh:catmull_clark", true, "catmull_clark",
     "it is what catmull_clark_level does, so move the vertices yourself after mesh:linear_subdivide()"},
    {"meshedit.curve", false, "curve",
     "it evaluates curves for you; evaluate_step and evaluate are yours to write with vec3 arithmetic"},
    {"meshedit.patch", false, "patch", "it evaluates patches for you; evaluate is yours to write with vec3 arithmetic"},
};

const ApiEntry kFileEntries[] = {{"meshedit.load", false, "load", kNoFiles},
                                 {"meshedit.load_curve", false, "load_curve", kNoFiles},
                                 {"meshedit.load_patches", false, "load_patches", kNoFiles},
                                 {"mesh:save", true, "save", kNoFiles}};

// The registry key of the stash: {module = meshedit, methods = the mesh methods, [name] = the real function}.
const char kStashKey = 0;

int refuse(lua_State* L) {
  // luaL_error puts the caller's "file.lua:LINE: " in front (level 1: the student's function calling this one).
  return luaL_error(L, "%s", lua_tostring(L, lua_upvalueindex(1)));
}

void push_refusal(lua_State* L, const char* name) {
  lua_pushstring(L, hidden_api_message(name).c_str());
  lua_pushcclosure(L, refuse, 1);
}

// The exercise whose function is `name` ("evaluate_step" -> curve), or nullptr.
const ExerciseInfo* exercise_of_function(const char* name) {
  for (const Exercise exercise : builtin_exercises()) {
    if (std::strcmp(exercise.info().function, name) == 0) return &exercise.info();
  }
  return nullptr;
}

// Called in place of another exercise file's function (upvalues: its name, the calling file's name).
int explain_other_file(lua_State* L) {
  const ExerciseInfo* owner = exercise_of_function(lua_tostring(L, lua_upvalueindex(1)));
  const std::string message = other_file_message(owner->function, owner->file, lua_tostring(L, lua_upvalueindex(2)));
  return luaL_error(L, "%s", message.c_str());
}

// The globals' __index: read from a Lua file that is not the function's own, another exercise's function reads as
// explain_other_file; anything else (C code's reads included) as nil.
int globals_index(lua_State* L) {
  const char* name = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : nullptr;
  const ExerciseInfo* owner = name != nullptr ? exercise_of_function(name) : nullptr;
  lua_Debug caller{};
  if (owner == nullptr || lua_getstack(L, 1, &caller) == 0 || lua_getinfo(L, "S", &caller) == 0 ||
      std::strcmp(caller.what, "C") == 0 || std::strcmp(caller.short_src, owner->file) == 0) {
    lua_pushnil(L);
    return 1;
  }
  lua_pushvalue(L, 2);
  lua_pushstring(L, caller.short_src);
  lua_pushcclosure(L, explain_other_file, 2);
  return 1;
}

// Gives the globals a metatable whose __index is globals_index, unless student code gave them one of its own.
void guide_other_files_functions(lua_State* L) {
  lua_pushglobaltable(L);
  if (lua_getmetatable(L, -1) == 0) {
    lua_createtable(L, 0, 1);
    lua_pushcfunction(L, globals_index);
    lua_setfield(L, -2, "__index");
    lua_setmetatable(L, -2);
  } else {
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

// Pushes the stash, making it on the first call from the module and the mesh methods as they are then.
void push_stash(lua_State* L) {
  if (lua_rawgetp(L, LUA_REGISTRYINDEX, &kStashKey) == LUA_TTABLE) return;
  lua_pop(L, 1);
  lua_getglobal(L, "meshedit");
  if (!lua_istable(L, -1)) luaL_error(L, "the meshedit module is missing");
  luaL_getmetatable(L, "mesh");
  if (!lua_istable(L, -1)) luaL_error(L, "the mesh metatable is missing");
  lua_getfield(L, -1, "__index");
  // Methods kept anywhere but in a table could not be hidden; fail loudly if the bindings ever change that.
  if (!lua_istable(L, -1)) luaL_error(L, "the mesh methods are not a table: cannot restrict them");
  lua_remove(L, -2);
  lua_createtable(L, 0, 8);
  const int stash = lua_gettop(L);
  const int module = stash - 2, methods = stash - 1;
  lua_pushvalue(L, module);
  lua_setfield(L, stash, "module");
  lua_pushvalue(L, methods);
  lua_setfield(L, stash, "methods");
  for (const ApiEntry& e : kHideable) {
    lua_pushstring(L, e.field);
    lua_rawget(L, e.method ? methods : module);
    lua_setfield(L, stash, e.name);
  }
  lua_pushvalue(L, stash);
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kStashKey);
  lua_replace(L, module);
  lua_pop(L, 1);
}

}  // namespace

const std::vector<std::string>& hideable_api_names() {
  static const std::vector<std::string> kNames = [] {
    std::vector<std::string> v;
    for (const ApiEntry& e : kHideable) v.emplace_back(e.name);
    return v;
  }();
  return kNames;
}

bool is_hideable_api(const std::string& name) {
  const auto& names = hideable_api_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

const ExerciseApi& exercise_api(Exercise exercise) {
  static const ExerciseApi kNone;
  static const ExerciseApi kUpsample{{"mesh:flip", "mesh:split"}, {"flip_edge", "split_edge"}};
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition()) return scripted->api();
  return exercise == Exercise::Upsample ? kUpsample : kNone;
}

std::string other_file_message(const std::string& function, const std::string& owner_file, const std::string& file) {
  return function + " is " + owner_file + "'s function, and each exercise file runs on its own (in the window and " +
         "in grading, where " + file + " is loaded alone), so " + file + " cannot call it: copy the function into " +
         file + ", as a local function";
}

std::string hidden_api_message(const std::string& name) {
  using Entries = std::span<const ApiEntry>;
  for (Entries list : {Entries(kHideable), Entries(kFileEntries)}) {
    for (const ApiEntry& e : list) {
      if (name == e.name) return name + " is hidden from your code (in the window and in grading): " + e.why;
    }
  }
  return name + " is hidden from your code (in the window and in grading)";
}

void set_student_api(lua_State* L, std::span<const std::string> allowed) {
  const int top = lua_gettop(L);
  luaL_checkstack(L, 8, "restricting the student API");
  push_stash(L);
  const int stash = lua_gettop(L);
  lua_getfield(L, stash, "module");
  lua_getfield(L, stash, "methods");
  const int module = stash + 1, methods = stash + 2;
  // Raw writes: a metatable student code gave the module cannot intercept them.
  for (const ApiEntry& e : kFileEntries) {
    lua_pushstring(L, e.field);
    push_refusal(L, e.name);
    lua_rawset(L, e.method ? methods : module);
  }
  for (const ApiEntry& e : kHideable) {
    lua_pushstring(L, e.field);
    if (std::find(allowed.begin(), allowed.end(), e.name) != allowed.end()) lua_getfield(L, stash, e.name);
    else push_refusal(L, e.name);
    lua_rawset(L, e.method ? methods : module);
  }
  guide_other_files_functions(L);
  lua_settop(L, top);
}

void push_student_patch(lua_State* L, const BezierPatch& patch) {
  lua_createtable(L, 0, 1);
  lua_createtable(L, static_cast<int>(patch.points.size()), 0);
  for (size_t i = 0; i < patch.points.size(); ++i) {
    push_vec3(L, patch.points[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "points");
}

}  // namespace meshedit
