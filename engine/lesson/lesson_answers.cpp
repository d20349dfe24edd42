// Reading the headless answers file (see lesson_answers.h): one table of fields per answer, read raw.
#include "lesson/internal/lesson_answers.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "core/file_bytes.h"
#include "core/subdivision_phases.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

using Kind = ScriptedAnswer::Kind;

struct AnswerField {
  const char* name;
  Kind kind;
};
const AnswerField kAnswerFields[] = {{"key", Kind::Key},
                                     {"click", Kind::Click},
                                     {"selection", Kind::Selection},
                                     {"button", Kind::Button},
                                     {"flip", Kind::Flip},
                                     {"split", Kind::Split},
                                     {"collapse", Kind::Collapse},
                                     {"subdivide", Kind::Subdivide},
                                     {"subdivide_phase", Kind::SubdividePhase},
                                     {"loop_phase", Kind::SubdividePhase},
                                     {"triangulate", Kind::Triangulate},
                                     {"open_repaired", Kind::OpenRepaired},
                                     {"choose", Kind::Choose},
                                     {"answer", Kind::Value},
                                     {"curve_t", Kind::CurveT},
                                     {"patch_uv", Kind::PatchUv},
                                     {"curve_click", Kind::CurveClick},
                                     {"your_turn", Kind::YourTurn}};

constexpr const char* kAnswerNames =
    "key, click, selection, button, flip, split, collapse, subdivide, subdivide_phase, loop_phase, triangulate, "
    "open_repaired, choose, answer, curve_t, patch_uv, curve_click or your_turn";

// The answers file's text, read under the size cap; not a regular file or unreadable: "<path>: <why>".
std::string read_text(const std::filesystem::path& path) {
  FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw ScriptError(path.string() + ": " + file.error);
  return std::move(file.bytes);
}

std::string number_text(double value) { return format_rounded(value, 17); }

// The value at the top of the stack as an answer{} text: a number, a text as typed, or a list of 2 or 3 numbers.
std::string value_text(lua_State* L, const std::string& where) {
  if (lua_type(L, -1) == LUA_TNUMBER) return number_text(lua_tonumber(L, -1));
  if (lua_type(L, -1) == LUA_TSTRING) return lua_tostring(L, -1);
  const std::string usage = where + ": answer must be a number, a text as typed (\"3/8\") or {x, y[, z]}";
  if (!lua_istable(L, -1)) throw ScriptError(usage);
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
  if (n < 2 || n > 3) throw ScriptError(usage);
  std::string text;
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    if (lua_type(L, -1) != LUA_TNUMBER) throw ScriptError(usage);
    text += (text.empty() ? "" : ", ") + number_text(lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  return text;
}

// The value at the top of the stack as two finite numbers, {a, b}: "0.25 0.5"; anything else raises `usage`.
std::string pair_text(lua_State* L, const std::string& usage) {
  if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2) throw ScriptError(usage);
  std::string text;
  for (lua_Integer i = 1; i <= 2; ++i) {
    lua_rawgeti(L, -1, i);
    if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1))) throw ScriptError(usage);
    text += (text.empty() ? "" : " ") + number_text(lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  return text;
}

// One answer table {key = "F"} at the top of the stack.
ScriptedAnswer read_answer(lua_State* L, const std::string& where) {
  if (!lua_istable(L, -1)) throw ScriptError(where + ": expected a table like {key = \"F\"}");
  ScriptedAnswer answer;
  int fields = 0;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    const std::string key = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : "";
    if (key == "feedback") {
      if (lua_type(L, -1) != LUA_TSTRING) throw ScriptError(where + ": feedback must be a string");
      answer.feedback = lua_tostring(L, -1);
      lua_pop(L, 1);
      continue;
    }
    const auto* found = std::find_if(std::begin(kAnswerFields), std::end(kAnswerFields),
                                     [&](const AnswerField& field) { return key == field.name; });
    if (found == std::end(kAnswerFields)) {
      throw ScriptError(where + ": unknown answer '" + key + "' (use " + kAnswerNames + ")");
    }
    answer.kind = found->kind;
    answer.field = key;
    const bool schemes = answer.kind == Kind::Subdivide || (answer.kind == Kind::SubdividePhase && key != "loop_phase");
    if (schemes && lua_type(L, -1) == LUA_TSTRING) {
      answer.value = lua_tostring(L, -1);
      if (!scheme_named(answer.value)) {
        throw ScriptError(where + ": " + key + " must be " + (answer.kind == Kind::Subdivide ? "true or " : "") +
                          scheme_names() + ", got '" + answer.value + "'");
      }
    } else if (answer.kind == Kind::SubdividePhase && key != "loop_phase") {
      throw ScriptError(where + ": " + key + " must be " + scheme_names());
    } else if (answer.kind == Kind::Subdivide || answer.kind == Kind::SubdividePhase ||
               answer.kind == Kind::Triangulate) {
      if (lua_type(L, -1) != LUA_TBOOLEAN || !lua_toboolean(L, -1)) {
        throw ScriptError(where + ": write " + key + " = true");
      }
      if (answer.kind != Kind::Triangulate) answer.value = "loop";
    } else if (answer.kind == Kind::Value) {
      answer.value = value_text(L, where);
    } else if (answer.kind == Kind::PatchUv) {
      answer.value = pair_text(L, where + ": patch_uv must be {u, v}, two numbers from 0 to 1");
    } else if (answer.kind == Kind::CurveClick) {
      answer.value = pair_text(L, where + ": curve_click must be {x, y}, the point clicked in the curve view");
    } else if (answer.kind == Kind::CurveT) {
      if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1))) {
        throw ScriptError(where + ": curve_t must be a number from 0 to 1");
      }
      answer.value = number_text(lua_tonumber(L, -1));
    } else {
      if (lua_type(L, -1) != LUA_TSTRING) throw ScriptError(where + ": " + key + " must be a string");
      answer.value = lua_tostring(L, -1);
    }
    ++fields;
    lua_pop(L, 1);
  }
  if (fields != 1) throw ScriptError(where + ": give exactly one answer per table");
  if (answer.kind == Kind::YourTurn && answer.value != "right" && answer.value != "wrong") {
    throw ScriptError(where + ": your_turn must be \"right\" or \"wrong\", got '" + answer.value + "'");
  }
  if (answer.kind == Kind::YourTurn && answer.feedback && answer.value == "right") {
    throw ScriptError(where + ": feedback goes with your_turn = \"wrong\"");
  }
  if (answer.feedback && answer.kind != Kind::Choose && answer.kind != Kind::Click && answer.kind != Kind::Value &&
      answer.kind != Kind::CurveClick && answer.kind != Kind::YourTurn) {
    throw ScriptError(where + ": feedback goes with a wrong choose, click, answer, curve_click or your_turn");
  }
  return answer;
}

}  // namespace

bool ScriptedAnswer::is_edit() const {
  return kind == Kind::Flip || kind == Kind::Split || kind == Kind::Collapse || kind == Kind::Subdivide ||
         kind == Kind::SubdividePhase || kind == Kind::Triangulate || kind == Kind::OpenRepaired ||
         kind == Kind::CurveT || kind == Kind::PatchUv;
}

ScriptedAnswers read_scripted_answers(const std::filesystem::path& path, const LuaLimits& limits) {
  const std::string name = path.filename().string();
  LuaRuntime lua(limits);
  lua.load(read_text(path), name);
  lua.start_budget();
  lua.call(0, 1);
  lua_State* L = lua.state();
  if (!lua_istable(L, -1)) {
    throw ScriptError(name + ": must return a table of answers per step, like { [2] = { {key = \"F\"} } }");
  }
  ScriptedAnswers answers;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    ScriptedAnswerList* list = nullptr;
    std::string step;
    if (lua_isinteger(L, -2)) {
      step = "step " + std::to_string(lua_tointeger(L, -2));
      list = &answers.by_number[lua_tointeger(L, -2)];
    } else if (lua_type(L, -2) == LUA_TSTRING) {
      step = "step '" + std::string(lua_tostring(L, -2)) + "'";
      list = &answers.by_title[lua_tostring(L, -2)];
    } else {
      throw ScriptError(name + ": keys are step numbers or step titles, got a " + luaL_typename(L, -2));
    }
    if (!lua_istable(L, -1)) throw ScriptError(name + ": " + step + ": expected a list of answers");
    const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, i);
      list->push_back(read_answer(L, name + ": " + step + ", answer " + std::to_string(i)));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  lua_settop(L, 0);
  return answers;
}

}  // namespace meshedit
