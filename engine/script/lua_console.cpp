// The read-eval-print loop: see lua_console.h for the contract.
#include "script/lua_console.h"

#include <algorithm>
#include <utility>

#include <lua.hpp>

#include "script/mesh_bindings.h"

namespace meshedit {
namespace {

std::string join(const std::vector<std::string>& values) {
  std::string line;
  for (size_t i = 0; i < values.size(); ++i) line += (i ? "\t" : "") + values[i];
  return line;
}

}  // namespace

LuaLimits console_limits() {
  LuaLimits limits;
  limits.instructions = 200'000'000;
  limits.memory_bytes = size_t(256) << 20;
  limits.wall_seconds = 5.0;
  return limits;
}

bool is_blank_line(const std::string& line) {
  return std::all_of(line.begin(), line.end(), [](unsigned char c) { return c == ' ' || c == '\t' || c == '\n'; });
}

LuaConsole::LuaConsole() : lua_(console_limits()) {
  lua_.set_print([this](const std::string& line) { add(ConsoleEntryKind::Output, line); });
}

void LuaConsole::add(ConsoleEntryKind kind, std::string text) {
  if (text.size() > kMaxEntryBytes) {
    const size_t dropped = text.size() - kMaxEntryBytes;
    text.resize(kMaxEntryBytes);
    text += "... (" + std::to_string(dropped) + " more bytes)";
  }
  entries_.push_back({kind, std::move(text)});
  while (entries_.size() > kMaxEntries) entries_.pop_front();
}

bool LuaConsole::submit(const std::string& line) { return !record(line) || evaluate(line); }

bool LuaConsole::record(const std::string& line) {
  if (is_blank_line(line)) return false;
  add(ConsoleEntryKind::Input, line);
  history_.erase(std::remove(history_.begin(), history_.end(), line), history_.end());
  history_.push_back(line);
  if (history_.size() > kMaxHistory) history_.erase(history_.begin());
  history_cursor_ = history_.size();
  return true;
}

std::vector<std::string> LuaConsole::run(const std::string& line) {
  // lua.c's rule: an expression is printed; anything else runs as a statement.
  const std::string as_expression = "return " + line;
  lua_State* L = lua_.state();
  const bool expression = luaL_loadbufferx(L, as_expression.data(), as_expression.size(), "=console", "t") == LUA_OK;
  lua_pop(L, 1);  // the compiled chunk or the syntax error message
  return lua_.run_string(expression ? as_expression : line, "console");
}

bool LuaConsole::evaluate(const std::string& line) {
  try {
    const std::vector<std::string> results = run(line);
    if (!results.empty()) add(ConsoleEntryKind::Output, join(results));
    return true;
  } catch (const ScriptError& e) {
    add(ConsoleEntryKind::Error, e.what());
    return false;
  }
}

void LuaConsole::set_mesh(std::shared_ptr<HalfedgeMesh> mesh) {
  push_mesh(lua_.state(), std::move(mesh));
  lua_setglobal(lua_.state(), "mesh");
}

void LuaConsole::set_selected(ElementRef element) {
  lua_State* L = lua_.state();
  lua_getglobal(L, "mesh");
  // A line may have set `mesh` to anything: only a mesh's fields are read, outside a protected call.
  if (!element.valid() || !to_mesh(L, -1)) {
    lua_pop(L, 1);
    lua_pushnil(L);
  } else {
    // mesh:vertex(i) / :halfedge(i) / :edge(i) / :face(i) / :boundary(i) make the handle: the bindings are the
    // one place that knows how handles are built.
    lua_getfield(L, -1, kind_name(element.kind));
    lua_insert(L, -2);
    lua_pushinteger(L, element.index);
    if (lua_pcall(L, 2, 1, 0) != LUA_OK) {
      lua_pop(L, 1);
      lua_pushnil(L);
    }
  }
  lua_setglobal(L, "selected");
}

std::string LuaConsole::history_up() {
  if (history_.empty()) return {};
  if (history_cursor_ > 0) --history_cursor_;
  return history_[history_cursor_];
}

std::string LuaConsole::history_down() {
  if (history_cursor_ < history_.size()) ++history_cursor_;
  return history_cursor_ < history_.size() ? history_[history_cursor_] : std::string();
}

}  // namespace meshedit
