// What the files defining the lesson globals share (internal to engine/lesson: lesson_api.cpp, lesson_questions.cpp,
// lesson_displays.cpp, lesson_your_turn.cpp): the script state behind each global, the phase checks, and the readers
// of the arguments every global takes the same way (elements, points, colours). Errors start with the lesson's
// `file:line:` (raise, script/lua_args.h).
//
// Invariants:
// - Every global is a C closure with the LessonScript as its one upvalue (set_globals), wrapped in lesson_guarded so
//   no C++ exception crosses a Lua frame. Each file lists its globals in one table, as Lua's luaL_Reg lists do.
// - The API's own Lua preludes are named kApiPreludeName, so an error names the lesson's line, never theirs.
// - The readers only read: they raise for a bad argument and change nothing.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>

#include <glm/vec3.hpp>
#include <lua.hpp>

#include "core/ids.h"
#include "lesson/internal/lesson_api.h"
#include "script/exception_text.h"
#include "script/lua_args.h"

namespace meshedit {

// The script of the running global (its upvalue 1).
LessonScript& script_of(lua_State* L);
// Runs an API function with C++ exceptions (from the host, or bad_alloc: "memory ran out") turned into Lua errors;
// the message is copied out first so the Lua error starts after the C++ exception is finished.
template <lua_CFunction F>
int lesson_guarded(lua_State* L) {
  std::string message;
  try {
    return F(L);
  } catch (const std::exception& e) {
    message = lua_error_text(L, e);
  }
  raise(L, message);
}

// Only while a step runs (phase Step): say, show, highlight, waits...
void require_step(lua_State* L, const char* name);
// While a step runs or a live block or plot marker is read (phase Step or Live): the calls that only read the view.
void require_reading(lua_State* L, const char* name);
// Only at the top level of the file (phase Loading): lesson{}, step().
void require_loading(lua_State* L, const char* name);
// A wait may only yield the step's own coroutine.
void require_step_thread(lua_State* L, const char* name);

// A text the student reads, at `index`: a string (or a number), or a table of languages {en = ..., zh = ...}. Returns
// the English (what the lesson's logic sees) and keeps the whole text in the script's texts; an unknown language
// is named there once. Raises "CALL: WHAT must be text ..." for anything else, or a table without `en`.
std::string read_text(lua_State* L, int index, const std::string& call, const std::string& what);
// Whether the value at `index` is a string, a number or a table read_text reads (a table with a string `en`).
bool is_text(lua_State* L, int index);

std::optional<ElementKind> kind_by_name(const std::string& name);
ElementRef check_element(lua_State* L, int index, const char* call);

// A colour argument: a palette name ("red" is the dark theme's vermillion swatch...), "#rrggbb" or {r, g, b} in [0, 1];
// none or nil gives the palette's lesson highlight. Raises for anything else.
glm::vec3 read_colour(lua_State* L, int index);
// The colour a name gives (the dark theme's swatch), or nullopt.
std::optional<glm::vec3> named_colour(const std::string& name);

// A C function of the lesson API: a global, or one a Lua prelude calls (lesson_guarded already applied).
struct LessonFunction {
  const char* name;
  lua_CFunction function;
};
// Sets a global for each of `functions`, bound to `script`.
void set_globals(LuaRuntime& runtime, LessonScript& script, std::initializer_list<LessonFunction> functions);
// Sets the global `table` to a table of `functions` bound to `script`, then runs `prelude` (named kApiPreludeName),
// which takes the table and clears the global (`local api = TABLE; TABLE = nil`). Throws ScriptError if the prelude
// fails.
void open_prelude_functions(LuaRuntime& runtime, LessonScript& script, const char* table,
                            std::initializer_list<LessonFunction> functions, const char* prelude);

}  // namespace meshedit
