// The shared pieces of the lesson globals (see lesson_api_support.h).
#include "lesson/internal/lesson_api_support.h"

#include "core/palette.h"
#include "script/lua_handles.h"
#include "script/lua_runtime.h"

namespace meshedit {

LessonScript& script_of(lua_State* L) { return *static_cast<LessonScript*>(lua_touserdata(L, lua_upvalueindex(1))); }

void require_step(lua_State* L, const char* name) {
  const LessonScript& script = script_of(L);
  if (script.phase == LessonScript::Phase::Step) return;
  if (script.phase == LessonScript::Phase::Live) {
    raise(L, std::string(name) + " cannot be used in a live() function or a plot's marker: they only read the view");
  }
  raise(L, std::string(name) + " can only be used inside a step: step(\"title\", function() ... end)");
}

void require_reading(lua_State* L, const char* name) {
  if (script_of(L).phase == LessonScript::Phase::Live) return;
  require_step(L, name);
}

void require_loading(lua_State* L, const char* name) {
  if (script_of(L).phase == LessonScript::Phase::Loading) return;
  raise(L, std::string(name) + " can only be used at the top level of a lesson file, not inside a step");
}

void require_step_thread(lua_State* L, const char* name) {
  require_step(L, name);
  if (L != script_of(L).step_thread) {
    raise(L, std::string(name) + " works in the step itself, not inside a coroutine of your own");
  }
  if (!lua_isyieldable(L)) {
    raise(L, std::string(name) + " cannot wait here (inside a metamethod or a C function)");
  }
}

std::optional<ElementKind> kind_by_name(const std::string& name) {
  for (ElementKind kind : kAllKinds) {
    if (name == kind_name(kind)) return kind;
  }
  return std::nullopt;
}

ElementRef check_element(lua_State* L, int index, const char* call) {
  if (std::optional<ElementRef> element = to_element(L, index)) return *element;
  if (lua_type(L, index) == LUA_TSTRING) {
    raise(L, std::string(call) + ": '" + lua_tostring(L, index) + "' is not an element id (like v3, h12, e7, f2, b0)");
  }
  raise(L, std::string(call) + ": expected an element (a handle or an id like \"e7\"), got " + type_name(L, index));
}

// ---- colours ----------------------------------------------------------------------------------------

namespace {

// A lesson's colour names give the palette's swatches (core/palette.h, the dark theme's values; the window shows each
// in its theme's shade), so a lesson stays colour-blind safe: "red" is vermillion, "green" bluish green, "cyan" sky
// blue, "magenta", "pink" and "purple" reddish purple, and "white" and "black" the ink (what reads on the theme's
// background: white-ish on dark, black-ish on light).
struct NamedColour {
  const char* name;
  glm::vec3 rgb;
};
const NamedColour kColours[] = {{"red", kDarkSwatches.vermillion},
                                {"green", kDarkSwatches.bluish_green},
                                {"blue", kDarkSwatches.blue},
                                {"yellow", kDarkSwatches.yellow},
                                {"orange", kDarkSwatches.orange},
                                {"magenta", kDarkSwatches.reddish_purple},
                                {"pink", kDarkSwatches.reddish_purple},
                                {"cyan", kDarkSwatches.sky_blue},
                                {"purple", kDarkSwatches.reddish_purple},
                                {"white", kDarkSwatches.ink},
                                {"grey", kDarkSwatches.grey},
                                {"gray", kDarkSwatches.grey},
                                {"black", kDarkSwatches.ink}};

// The colour of highlight(x) with no colour: the palette's lesson highlight (the last-edit colour).
glm::vec3 default_highlight() { return palette_for(Theme::Dark).lesson_highlight; }

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

bool is_text(lua_State* L, int index) {
  const int type = lua_type(L, index);
  if (type == LUA_TSTRING || type == LUA_TNUMBER) return true;
  if (type != LUA_TTABLE) return false;
  const bool english = lua_getfield(L, index, "en") == LUA_TSTRING;
  lua_pop(L, 1);
  return english;
}

std::string read_text(lua_State* L, int index, const std::string& call, const std::string& what) {
  index = lua_absindex(L, index);
  if (lua_type(L, index) == LUA_TSTRING || lua_type(L, index) == LUA_TNUMBER) {
    LocalText text;
    text.texts[0] = lua_tostring(L, index);
    script_of(L).texts.keep(text, caller_where(L));
    return text.texts[0];
  }
  if (!is_text(L, index)) {
    raise(L, call + ": " + what + " must be text: a string, or {en = \"...\", zh = \"...\"} (the English first), got " +
                 (lua_istable(L, index) ? "a table without en" : type_name(L, index)));
  }
  LocalText text;
  const std::string where = caller_where(L);
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    const std::optional<Language> language =
        lua_type(L, -2) == LUA_TSTRING ? language_by_code(lua_tostring(L, -2)) : std::nullopt;
    const bool exact = language && std::string(lua_tostring(L, -2)) == language_code(*language);
    if (!exact) {
      script_of(L).texts.unknown_language(lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : type_name(L, -2),
                                          where);
    } else if (lua_type(L, -1) != LUA_TSTRING) {
      raise(L, call + ": " + what + "'s " + language_code(*language) + " must be a string, got " + type_name(L, -1));
    } else {
      text.texts[size_t(*language)] = lua_tostring(L, -1);
    }
    lua_pop(L, 1);
  }
  script_of(L).texts.keep(text, where);
  return text.english();
}

std::optional<glm::vec3> named_colour(const std::string& name) {
  for (const NamedColour& c : kColours) {
    if (name == c.name) return c.rgb;
  }
  return std::nullopt;
}

glm::vec3 read_colour(lua_State* L, int index) {
  if (lua_isnoneornil(L, index)) return default_highlight();
  if (lua_type(L, index) == LUA_TSTRING) {
    const std::string text = lua_tostring(L, index);
    if (const std::optional<glm::vec3> named = named_colour(text)) return *named;
    if (text.size() == 7 && text[0] == '#') {
      glm::vec3 rgb{};
      bool ok = true;
      for (int i = 0; i < 3; ++i) {
        const int hi = hex_digit(text[1 + 2 * i]), lo = hex_digit(text[2 + 2 * i]);
        ok = ok && hi >= 0 && lo >= 0;
        rgb[i] = static_cast<float>(hi * 16 + lo) / 255.0f;
      }
      if (ok) return rgb;
    }
    std::string names;
    for (const NamedColour& c : kColours) names += (names.empty() ? "" : ", ") + std::string(c.name);
    raise(L, "unknown colour '" + text + "' (use " + names + ", \"#rrggbb\" or {r, g, b} from 0 to 1)");
  }
  if (lua_istable(L, index)) {
    glm::dvec3 p{};
    lua_getfield(L, index, "r");
    const bool named = lua_type(L, -1) == LUA_TNUMBER;
    lua_pop(L, 1);
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
      if (named) lua_getfield(L, index, i == 0 ? "r" : i == 1 ? "g" : "b");
      else lua_geti(L, index, i + 1);
      ok = ok && lua_type(L, -1) == LUA_TNUMBER;
      p[i] = lua_tonumber(L, -1);
      lua_pop(L, 1);
      ok = ok && p[i] >= 0.0 && p[i] <= 1.0;
    }
    if (ok) return glm::vec3(p);
    raise(L, "a colour table needs three numbers from 0 to 1: {r, g, b} or {r=, g=, b=}");
  }
  raise(L, "expected a colour (a name like \"red\", \"#rrggbb\" or {r, g, b}), got " + type_name(L, index));
}

namespace {

// Sets a field of the table on top of the stack for each of `functions`, bound to `script`.
void set_functions(lua_State* L, LessonScript& script, std::initializer_list<LessonFunction> functions) {
  for (const LessonFunction& f : functions) {
    lua_pushlightuserdata(L, &script);
    lua_pushcclosure(L, f.function, 1);
    lua_setfield(L, -2, f.name);
  }
}

}  // namespace

void set_globals(LuaRuntime& runtime, LessonScript& script, std::initializer_list<LessonFunction> functions) {
  lua_State* L = runtime.state();
  lua_pushglobaltable(L);
  set_functions(L, script, functions);
  lua_pop(L, 1);
}

void open_prelude_functions(LuaRuntime& runtime, LessonScript& script, const char* table,
                            std::initializer_list<LessonFunction> functions, const char* prelude) {
  lua_State* L = runtime.state();
  lua_pushglobaltable(L);
  lua_newtable(L);
  set_functions(L, script, functions);
  lua_setfield(L, -2, table);
  lua_pop(L, 1);
  runtime.run_string(prelude, kApiPreludeName);
}

}  // namespace meshedit
