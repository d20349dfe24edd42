// choose, pick and answer (see lesson_questions.h): a Lua prelude loops "ask, judge, record" in the step's coroutine,
// so the lesson's own answer and feedback functions run there (their errors point at their lines, under the step's
// budget); the C functions below check the question's table, make the wait, read typed answers and keep the record.
#include "lesson/internal/lesson_questions.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <lua.hpp>

#include "lesson/internal/lesson_answer_text.h"
#include "lesson/internal/lesson_api_support.h"
#include "script/lua_runtime.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

constexpr double kDefaultTolerance = 1e-3;

constexpr const char* kQuestionsPrelude = R"lua(local api = __lesson_questions
__lesson_questions = nil
local check, ask, read_answer, record = api.check, api.ask, api.read_answer, api.record
local text, message = api.text, api.message
local type, tostring, math, string, pairs = type, tostring, math, string, pairs

local function text_of(value)
  if value == nil or value == false then return nil end
  if type(value) == "table" then return text(value) end
  return tostring(value)
end

-- A copy of the question's table with each text the student reads (a string or {en = ..., zh = ...}) as its
-- English: the logic below compares English only, and text() keeps the other languages for the panel.
local function in_english(kind, spec)
  if type(spec) ~= "table" then return spec end
  local copy = {}
  for key, value in pairs(spec) do copy[key] = value end
  copy[1], copy.hint = text(copy[1]), text(copy.hint)
  if kind == "choose" then
    if type(copy.options) == "table" then
      local options = {}
      for i = 1, #copy.options do options[i] = text(copy.options[i]) end
      copy.options = options
    end
    if type(copy.answer) == "table" then copy.answer = text(copy.answer) end
  end
  if type(copy.feedback) == "table" then
    local feedback = {}
    for key, value in pairs(copy.feedback) do feedback[key] = text(value) end
    copy.feedback = feedback
  end
  return copy
end

-- Asks until the answer is right; judge(what ask returned) -> right, feedback, counted, value, the answer as the
-- record shows it (the first value ask returned when nil).
local function until_right(kind, spec, judge)
  local tries, feedback = 0, nil
  local function judged(given, ...)
    local right, text, counted, value, shown = judge(given, ...)
    record(spec, shown or given, right, text)
    return right, text, counted, value
  end
  while true do
    local right, text, counted, value = judged(ask(kind, spec, tries, feedback))
    if right then return value end
    if counted then tries = tries + 1 end
    feedback = text
  end
end

function choose(spec)
  spec = in_english("choose", spec)
  check("choose", spec)
  return until_right("choose", spec, function(given)
    local said = spec.feedback and text_of(spec.feedback[given])
    if given == spec.answer then return true, said, true, given end
    return false, said or message("{given} is not the answer.", {given = given}), true
  end)
end

-- A click on the curve view: ask gives the t of the curve point nearest the click, that point, and whether the click
-- was on the curve.
local function pick_on_curve(spec)
  local answer, feedback = spec.answer, spec.feedback
  local tolerance = spec.tolerance or 0.04
  return until_right("pick", spec, function(t, point, on)
    local shown = string.format("C(%.2f)", t)
    if not on then
      return false, message("That click is beside the curve: click on the curve itself."), false, nil,
        "a click beside the curve"
    end
    local right, why
    if type(answer) == "function" then
      right, why = answer(t, point)
    else
      right = math.abs(t - answer) <= tolerance
    end
    if right then return true, text_of(why), true, t, shown end
    local said = type(feedback) == "function" and feedback(t, point) or nil
    return false, text_of(said) or text_of(why) or message("That is {point}, the point of the curve at t = {t}.",
      {point = shown, t = string.format("%.2f", t)}), true, nil, shown
  end)
end

function pick(spec)
  spec = in_english("pick", spec)
  check("pick", spec)
  if spec.on == "curve" then return pick_on_curve(spec) end
  return until_right("pick", spec, function(element)
    local answer, feedback, id = spec.answer, spec.feedback, tostring(element)
    local right, why
    if type(answer) == "function" then
      right, why = answer(element)
    else
      right = id == tostring(answer)
    end
    if right then
      return true, text_of(type(feedback) == "table" and feedback[id] or why), true, element
    end
    local said
    if type(feedback) == "function" then
      said = feedback(element)
    elseif type(feedback) == "table" then
      said = feedback[id]
    end
    return false, text_of(said) or text_of(why) or message("Not {id}: look again.", {id = id}), true
  end)
end

function answer(spec)
  spec = in_english("answer", spec)
  check("answer", spec)
  return until_right("answer", spec, function(text)
    local value, right, help = read_answer(spec, text)
    if value == nil then return false, help, false end
    if right then return true, nil, true, value end
    local said = type(spec.feedback) == "function" and spec.feedback(value) or nil
    return false, text_of(said) or message("{given} is not the answer.", {given = text}), true
  end)
end
)lua";

// ---- reading the question's table -------------------------------------------------------------------------------

// The string field `name` of the table at `index` ("" when nil); raises for any other type.
std::string optional_string(lua_State* L, int index, const char* call, const char* name) {
  lua_getfield(L, index, name);
  std::string text;
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TSTRING) {
      raise(L, std::string(call) + ": " + name + " must be a string, got " + type_name(L, -1));
    }
    text = lua_tostring(L, -1);
  }
  lua_pop(L, 1);
  return text;
}

std::string question_text(lua_State* L, int index, const char* call) {
  lua_geti(L, index, 1);
  if (lua_type(L, -1) != LUA_TSTRING || lua_rawlen(L, -1) == 0) {
    raise(L, std::string(call) + ": the question comes first, as text: " + call + "{ \"Which ...?\", ... }, got " +
                 type_name(L, -1));
  }
  std::string text = lua_tostring(L, -1);
  lua_pop(L, 1);
  return text;
}

std::string joined(const std::vector<std::string>& words) {
  std::string list;
  for (const std::string& word : words) list += (list.empty() ? "" : ", ") + word;
  return list;
}

void read_choice(lua_State* L, int index, LessonWait& wait) {
  check_fields(L, index, "choose", {"options", "answer", "feedback", "hint"}, true);
  lua_getfield(L, index, "options");
  if (!lua_istable(L, -1)) {
    raise(L, "choose: options must be a list of texts like {\"h1\", \"h2\"}, got " + type_name(L, -1));
  }
  const lua_Integer n = luaL_len(L, -1);
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, -1, i);
    if (lua_type(L, -1) != LUA_TSTRING || lua_rawlen(L, -1) == 0) {
      raise(L, "choose: option " + std::to_string(i) + " must be a non-empty text, got " + type_name(L, -1));
    }
    std::string option = lua_tostring(L, -1);
    for (const std::string& before : wait.options) {
      if (before == option) raise(L, "choose: the option '" + option + "' is given twice");
    }
    wait.options.push_back(std::move(option));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (wait.options.size() < 2) raise(L, "choose: give at least two options");
  const auto is_option = [&](const std::string& text) {
    for (const std::string& option : wait.options) {
      if (option == text) return true;
    }
    return false;
  };
  lua_getfield(L, index, "answer");
  if (lua_type(L, -1) != LUA_TSTRING) raise(L, "choose: answer must be one of the options, got " + type_name(L, -1));
  if (!is_option(lua_tostring(L, -1))) {
    raise(L, "choose: the answer '" + std::string(lua_tostring(L, -1)) + "' is not one of the options (" +
                 joined(wait.options) + ")");
  }
  lua_pop(L, 1);
  lua_getfield(L, index, "feedback");
  if (!lua_isnil(L, -1)) {
    if (!lua_istable(L, -1)) raise(L, "choose: feedback must be a table from options to text, got " + type_name(L, -1));
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
      if (lua_type(L, -2) != LUA_TSTRING || !is_option(lua_tostring(L, -2))) {
        const std::string key = lua_type(L, -2) == LUA_TSTRING ? "'" + std::string(lua_tostring(L, -2)) + "'"
                                                               : "a " + type_name(L, -2) + " key";
        raise(L, "choose: feedback for " + key + ", which is not one of the options (" + joined(wait.options) + ")");
      }
      if (lua_type(L, -1) != LUA_TSTRING) {
        raise(L, "choose: the feedback for '" + std::string(lua_tostring(L, -2)) + "' must be text, got " +
                     type_name(L, -1));
      }
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
}

// pick{on = "curve", ...}: answer a t in [0, 1] or a function, tolerance in t, feedback a function.
void read_curve_pick(lua_State* L, int index) {
  check_fields(L, index, "pick", {"on", "answer", "tolerance", "feedback", "hint"}, true);
  lua_getfield(L, index, "answer");
  const bool t_answer = lua_type(L, -1) == LUA_TNUMBER;
  if (!(t_answer && lua_tonumber(L, -1) >= 0.0 && lua_tonumber(L, -1) <= 1.0) && !lua_isfunction(L, -1)) {
    raise(L,
          "pick on the curve: answer must be the t of the point, from 0 to 1, or function(t, point) return ok, "
          "why end; got " +
              (t_answer ? std::string(lua_tostring(L, -1)) : "a " + type_name(L, -1)));
  }
  lua_pop(L, 1);
  lua_getfield(L, index, "tolerance");
  if (!lua_isnil(L, -1) && (lua_type(L, -1) != LUA_TNUMBER || !(lua_tonumber(L, -1) >= 0.0))) {
    raise(L, "pick on the curve: tolerance must be a number >= 0 (in t), got " + type_name(L, -1));
  }
  lua_pop(L, 1);
  lua_getfield(L, index, "feedback");
  if (!lua_isnil(L, -1) && !lua_isfunction(L, -1)) {
    raise(L, "pick on the curve: feedback must be function(t, point) return text end, got " + type_name(L, -1));
  }
  lua_pop(L, 1);
}

// Whether the pick is on the curve view (on = "curve"); raises for any other `on`.
bool picks_on_curve(lua_State* L, int index) {
  lua_getfield(L, index, "on");
  const bool curve = lua_type(L, -1) == LUA_TSTRING && std::string(lua_tostring(L, -1)) == "curve";
  if (!curve && !lua_isnil(L, -1)) {
    raise(L, "pick: on must be \"curve\" (a click on the curve view), or left out for a click on the mesh; got " +
                 (lua_type(L, -1) == LUA_TSTRING ? "'" + std::string(lua_tostring(L, -1)) + "'"
                                                 : "a " + type_name(L, -1)));
  }
  lua_pop(L, 1);
  return curve;
}

void read_pick(lua_State* L, int index) {
  check_fields(L, index, "pick", {"answer", "feedback", "hint"}, true);
  lua_getfield(L, index, "answer");
  if (!lua_isfunction(L, -1) && !to_element(L, -1)) {
    const std::string got =
        lua_type(L, -1) == LUA_TSTRING ? "'" + std::string(lua_tostring(L, -1)) + "'" : "a " + type_name(L, -1);
    raise(L, "pick: answer must be an element, an id like \"h4\" or function(element) return ok, why end; got " + got);
  }
  lua_pop(L, 1);
  lua_getfield(L, index, "feedback");
  if (lua_istable(L, -1)) {
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
      if (lua_type(L, -2) != LUA_TSTRING || !parse_element(lua_tostring(L, -2))) {
        const std::string key = lua_type(L, -2) == LUA_TSTRING ? "'" + std::string(lua_tostring(L, -2)) + "'"
                                                               : "a " + type_name(L, -2) + " key";
        raise(L, "pick: feedback keys are element ids like \"h1\", got " + key);
      }
      if (lua_type(L, -1) != LUA_TSTRING) {
        raise(L,
              "pick: the feedback for " + std::string(lua_tostring(L, -2)) + " must be text, got " + type_name(L, -1));
      }
      lua_pop(L, 1);
    }
  } else if (!lua_isnil(L, -1) && !lua_isfunction(L, -1)) {
    raise(L, "pick: feedback must be function(element) ... end or a table from ids to text, got " + type_name(L, -1));
  }
  lua_pop(L, 1);
}

// The expected value of answer{}: a number, or a point of 2 or 3 components.
struct Expected {
  glm::dvec3 value{0.0};
  size_t components = 1;
  double tolerance = kDefaultTolerance;
};

Expected read_expected(lua_State* L, int index) {
  Expected expected;
  lua_getfield(L, index, "number");
  lua_getfield(L, index, "point");
  const bool number = !lua_isnil(L, -2), point = !lua_isnil(L, -1);
  if (number == point) {
    raise(L, number ? "answer: give number = ... or point = {x, y[, z]}, not both"
                    : "answer: say what the answer is: number = 0.375 or point = {x, y[, z]}");
  }
  if (number) {
    if (lua_type(L, -2) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -2))) {
      raise(L, "answer: number must be a finite number, got " + type_name(L, -2));
    }
    expected.value.x = lua_tonumber(L, -2);
  } else {
    if (!read_point(L, -1, expected.value) || !std::isfinite(expected.value.x) || !std::isfinite(expected.value.y) ||
        !std::isfinite(expected.value.z)) {
      raise(L, "answer: point must be {x, y} or {x, y, z} of finite numbers (or a vec3), got " + type_name(L, -1));
    }
    lua_getfield(L, -1, "z");
    const bool named_z = !lua_isnil(L, -1);
    lua_pop(L, 1);
    expected.components = named_z || luaL_len(L, -1) >= 3 ? 3 : 2;
  }
  lua_pop(L, 2);
  lua_getfield(L, index, "tolerance");
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1)) || lua_tonumber(L, -1) < 0.0) {
      raise(L, "answer: tolerance must be a number >= 0, got " + type_name(L, -1));
    }
    expected.tolerance = lua_tonumber(L, -1);
  }
  lua_pop(L, 1);
  return expected;
}

void read_answer_spec(lua_State* L, int index, LessonWait& wait) {
  check_fields(L, index, "answer", {"number", "point", "tolerance", "feedback", "hint"}, true);
  wait.components = read_expected(L, index).components;
  lua_getfield(L, index, "feedback");
  if (!lua_isnil(L, -1) && !lua_isfunction(L, -1)) {
    raise(L, "answer: feedback must be function(value) return text end, got " + type_name(L, -1));
  }
  lua_pop(L, 1);
}

// The wait a question makes, its table checked whole (`kind`: "choose", "pick" or "answer").
LessonWait parse_question(lua_State* L, const std::string& kind, int index) {
  const char* call = kind.c_str();
  if (!lua_istable(L, index)) {
    raise(L, kind + ": expected a table like " + kind + "{ \"the question\", ... }, got " + type_name(L, index));
  }
  LessonWait wait;
  wait.question = question_text(L, index, call);
  if (kind == "choose") {
    wait.kind = LessonWait::Kind::Choice;
    read_choice(L, index, wait);
  } else if (kind == "pick" && picks_on_curve(L, index)) {
    wait.kind = LessonWait::Kind::CurvePick;
    read_curve_pick(L, index);
  } else if (kind == "pick") {
    wait.kind = LessonWait::Kind::Pick;
    read_pick(L, index);
  } else {
    wait.kind = LessonWait::Kind::Answer;
    read_answer_spec(L, index, wait);
  }
  wait.hint = optional_string(L, index, call, "hint");
  wait.where = caller_where(L);
  return wait;
}

const char* question_kind(lua_State* L) {
  const char* kind = luaL_checkstring(L, 1);
  const std::string name = kind;
  if (name != "choose" && name != "pick" && name != "answer") luaL_error(L, "lesson api: unknown question %s", kind);
  return kind;
}

// ---- what the prelude calls ---------------------------------------------------------------------------------------

// check(kind, spec): the whole table, before the first wait.
int api_check(lua_State* L) {
  const std::string kind = question_kind(L);
  require_step_thread(L, (kind + "{}").c_str());
  parse_question(L, kind, 2);
  return 0;
}

// ask(kind, spec, tries, feedback): waits for an answer; the runner resumes with it.
int api_ask(lua_State* L) {
  const std::string kind = question_kind(L);
  require_step_thread(L, (kind + "{}").c_str());
  LessonScript& script = script_of(L);
  LessonWait wait = parse_question(L, kind, 2);
  wait.tries = static_cast<int>(luaL_checkinteger(L, 3));
  if (lua_type(L, 4) == LUA_TSTRING) wait.feedback = lua_tostring(L, 4);
  script.wait = std::move(wait);
  script.api_yield = true;
  return lua_yield(L, 0);
}

// read_answer(spec, text) -> value, right | nil, false, how to write one.
int api_read_answer(lua_State* L) {
  const Expected expected = read_expected(L, 1);
  const std::optional<std::vector<double>> typed = parse_answer_text(luaL_checkstring(L, 2), expected.components);
  if (!typed) {
    lua_pushnil(L);
    lua_pushboolean(L, false);
    const LocalText help = local_format(answer_text_help(expected.components).c_str(), {});
    script_of(L).texts.keep(help, caller_where(L));
    lua_pushstring(L, help.english().c_str());
    return 3;
  }
  glm::dvec3 value(0.0);
  for (size_t i = 0; i < expected.components; ++i) value[static_cast<int>(i)] = (*typed)[i];
  const glm::dvec3 d = value - expected.value;
  const double off = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (expected.components == 1) lua_pushnumber(L, value.x);
  else push_vec3(L, value);
  lua_pushboolean(L, off <= expected.tolerance);
  return 2;
}

// text(value) -> the English of a text (read_text), or the value itself when it is not one (check() names it).
int api_text(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING || (lua_istable(L, 1) && is_text(L, 1))) {
    lua_pushstring(L, read_text(L, 1, "lesson", "a text").c_str());
  } else {
    lua_settop(L, 1);
  }
  return 1;
}

// message(template, {name = part, ...}) -> the app's own message in English, its translations kept beside it.
int api_message(lua_State* L) {
  const char* english_template = luaL_checkstring(L, 1);
  MessageParts parts;
  if (lua_istable(L, 2)) {
    lua_pushnil(L);
    while (lua_next(L, 2) != 0) {
      // A key's text stays where it is while the table at 2 holds it, so its name may point into it.
      if (lua_type(L, -2) == LUA_TSTRING) {
        const std::string_view name = lua_tostring(L, -2);  // before luaL_tolstring pushes the value's text
        parts.emplace_back(name, luaL_tolstring(L, -1, nullptr));
        lua_pop(L, 1);
      }
      lua_pop(L, 1);
    }
  }
  const LocalText text = local_format(english_template, parts);
  script_of(L).texts.keep(text, caller_where(L));
  lua_pushstring(L, text.english().c_str());
  return 1;
}

// record(spec, given, right, feedback): the judgement, and an Answered block when it is right.
int api_record(lua_State* L) {
  LessonScript& script = script_of(L);
  LessonJudgement judgement;
  lua_geti(L, 1, 1);
  if (lua_type(L, -1) == LUA_TSTRING) judgement.question = lua_tostring(L, -1);
  lua_pop(L, 1);
  judgement.given = luaL_tolstring(L, 2, nullptr);
  lua_pop(L, 1);
  judgement.right = lua_toboolean(L, 3);
  if (lua_type(L, 4) == LUA_TSTRING) judgement.feedback = lua_tostring(L, 4);
  if (judgement.right) {
    script.answered.push_back(judgement);
    script.blocks.push_back({LessonBlock::Kind::Answered, script.answered.size() - 1});
  }
  script.last_judgement = std::move(judgement);
  ++script.judgements;
  return 0;
}

}  // namespace

void open_lesson_questions(LuaRuntime& runtime, LessonScript& script) {
  open_prelude_functions(runtime, script, "__lesson_questions",
                         {{"check", lesson_guarded<api_check>},
                          {"ask", lesson_guarded<api_ask>},
                          {"read_answer", lesson_guarded<api_read_answer>},
                          {"record", lesson_guarded<api_record>},
                          {"text", lesson_guarded<api_text>},
                          {"message", lesson_guarded<api_message>}},
                         kQuestionsPrelude);
}

}  // namespace meshedit
