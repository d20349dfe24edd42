// LuaRuntime: state creation, the whitelisted globals, the capped allocator and the one count hook that
// enforces every limit (see lua_runtime.h for the invariants).
#include "script/lua_runtime.h"

#include <cstring>
#include <new>
#include <sstream>

#include <lua.hpp>

#include "core/file_bytes.h"
#include "core/value_format.h"
#include "script/exception_text.h"
#include "script/lua_source.h"

namespace meshedit {
namespace {

LuaRuntime* runtime_of(lua_State* L) { return *static_cast<LuaRuntime**>(lua_getextraspace(L)); }

// How an error value that is not a string reads (error_value_text): kNotStringBefore, its type, kNotStringAfter.
constexpr char kNotStringBefore[] = "(error object is a ";
constexpr char kNotStringAfter[] = " value)";

// Message handler: error_value_text, made by Lua (a C++ exception must not cross into Lua). It never calls
// __tostring, so an error object cannot run script code outside the limits' reach.
int message_handler(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING) return 1;
  lua_pushfstring(L, "%s%s%s", kNotStringBefore, luaL_typename(L, 1), kNotStringAfter);
  return 1;
}

// Replaces each argument by its tostring; run in protected mode because __tostring is script code.
int to_strings(lua_State* L) {
  const int n = lua_gettop(L);
  for (int i = 1; i <= n; ++i) {
    luaL_tolstring(L, i, nullptr);
    lua_replace(L, i);
  }
  return n;
}

// Keeps only the listed fields of the table on top of the stack.
void keep_only(lua_State* L, std::initializer_list<const char*> keep) {
  std::vector<std::string> drop;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) != LUA_TSTRING) continue;
    std::string key = lua_tostring(L, -1);
    bool kept = false;
    for (const char* k : keep) kept = kept || key == k;
    if (!kept) drop.push_back(key);
  }
  for (const auto& key : drop) {
    lua_pushnil(L);
    lua_setfield(L, -2, key.c_str());
  }
}

}  // namespace

std::string error_value_text(lua_State* L, int index) {
  if (lua_type(L, index) == LUA_TSTRING) return lua_tostring(L, index);
  return kNotStringBefore + std::string(luaL_typename(L, index)) + kNotStringAfter;
}

std::string memory_limit_message(size_t bytes) { return "memory limit exceeded (" + format_bytes(bytes) + ")"; }

std::optional<std::string> read_lua_file(const std::filesystem::path& path) {
  FileBytes file = read_file_bytes(path);
  if (!file.ok()) return std::nullopt;
  return lua_source_text(std::move(file.bytes));
}

LuaRuntime::LuaRuntime(LuaLimits limits) : limits_(limits) {
  L_ = lua_newstate(&LuaRuntime::allocate, this);
  if (!L_) throw std::bad_alloc();  // memory ran out, as for any other allocation the caller makes
  *static_cast<LuaRuntime**>(lua_getextraspace(L_)) = this;
  try {
    open_whitelist();
  } catch (...) {
    lua_close(L_);  // the destructor does not run for an object whose constructor threw
    L_ = nullptr;
    throw;
  }
}

LuaRuntime::~LuaRuntime() {
  if (L_) lua_close(L_);
}

void* LuaRuntime::allocate(void* ud, void* ptr, size_t old_size, size_t new_size) {
  auto* self = static_cast<LuaRuntime*>(ud);
  const size_t old = ptr ? old_size : 0;  // old_size is a type tag when ptr is null
  if (new_size == 0) {
    self->pool_.release(ptr, old);
    self->memory_used_ -= old;
    return nullptr;
  }
  // After the cap was hit, a little headroom lets Lua build the error message that stops the script.
  const size_t cap = self->memory_hit_ ? self->limits_.memory_bytes + (size_t(1) << 20) : self->limits_.memory_bytes;
  if (new_size > old && self->memory_used_ - old + new_size > cap) {
    self->note_memory_hit();
    return nullptr;
  }
  void* result = self->pool_.resize(ptr, old, new_size);
  if (result) self->memory_used_ = self->memory_used_ - old + new_size;
  else self->out_of_memory_ = true;  // below the cap: the system's memory ran out, not the script's budget
  return result;
}

void LuaRuntime::note_out_of_memory(lua_State* L) noexcept { runtime_of(L)->out_of_memory_ = true; }

void LuaRuntime::note_cap(lua_State* L) noexcept { runtime_of(L)->cap_hit_ = true; }

void LuaRuntime::note_memory_hit() {
  if (memory_hit_ || !L_) {
    memory_hit_ = true;
    return;
  }
  memory_hit_ = true;
  // Stop at the very next instruction (a pcall may catch the memory error itself).
  lua_sethook(L_, &LuaRuntime::count_hook, LUA_MASKCOUNT, 1);
  // Remember where the script was (the innermost Lua frame): a memory error skips the message handler.
  lua_Debug ar;
  for (int level = 0; lua_getstack(L_, level, &ar); ++level) {
    if (!lua_getinfo(L_, "Sl", &ar)) break;
    if (ar.currentline > 0) {
      memory_hit_where_ = std::string(ar.short_src) + ":" + std::to_string(ar.currentline) + ": ";
      break;
    }
  }
}

void LuaRuntime::count_hook(lua_State* L, lua_Debug*) {
  LuaRuntime* self = runtime_of(L);
  if (!self->killed_) {
    self->instructions_ += kHookInterval;
    if (self->instructions_ > self->limits_.instructions) {
      self->kill_message_ =
          "instruction budget exceeded (" + std::to_string(self->limits_.instructions) + " instructions)";
      self->kill_limit_ = ScriptError::Limit::Instructions;
    } else if (self->memory_hit_) {
      self->kill_message_ = memory_limit_message(self->limits_.memory_bytes);
      self->kill_limit_ = ScriptError::Limit::Memory;
    } else if (self->stop_request_ != nullptr && self->stop_request_->load(std::memory_order_relaxed)) {
      self->kill_message_ = "stopped: you pressed Stop";
      self->kill_limit_ = ScriptError::Limit::Stopped;
    } else if (std::chrono::steady_clock::now() > self->deadline_) {
      std::ostringstream s;
      s << "time limit exceeded (" << self->limits_.wall_seconds << " s)";
      self->kill_message_ = s.str();
      self->kill_limit_ = ScriptError::Limit::Time;
    } else {
      // A coroutine made in an earlier, stopped run may still carry the every-instruction hook.
      if (lua_gethookcount(L) != kHookInterval) lua_sethook(L, &LuaRuntime::count_hook, LUA_MASKCOUNT, kHookInterval);
      return;
    }
    self->killed_ = true;
    // From now on every instruction errors, so no pcall can catch the stop and carry on.
    lua_sethook(L, &LuaRuntime::count_hook, LUA_MASKCOUNT, 1);
  }
  luaL_where(L, 0);
  lua_pushstring(L, self->kill_message_.c_str());
  lua_concat(L, 2);
  lua_error(L);
}

int LuaRuntime::print_function(lua_State* L) {
  LuaRuntime* self = runtime_of(L);
  if (self->print_limit_ > 0 && self->print_truncated_) return 0;
  // Everything that allocates on the C++ side (the line, the note, the host's callback) runs inside the try; the
  // message is copied out with exception_text, which cannot fail, and the Lua error is raised after the catch, so no
  // C++ exception crosses the Lua frames (a __tostring's Lua error is no std::exception: it passes through).
  std::string failure;
  bool failed = false;
  try {
    self->print_arguments(L);
  } catch (const std::exception& e) {
    failure = lua_error_text(L, e);  // std::bad_alloc, or a message that cannot be copied: "memory ran out"
    failed = true;
  }
  if (failed) return luaL_error(L, "print failed: %s", failure.c_str());
  return 0;
}

void LuaRuntime::print_arguments(lua_State* L) {
  const int n = lua_gettop(L);
  // The room left under the cap, counting the newline the host adds; text past it is never built.
  const bool capped = print_limit_ > 0;
  const size_t room = capped ? (printed_ < print_limit_ ? print_limit_ - printed_ : 0) : SIZE_MAX;
  std::string line;
  bool cut = false;
  for (int i = 1; i <= n && !cut; ++i) {
    size_t len = 0;
    const char* s = luaL_tolstring(L, i, &len);
    if (i > 1) line += '\t';
    if (capped && line.size() + len + 1 > room) {
      line.append(s, room > line.size() + 1 ? room - line.size() - 1 : 0);
      cut = true;
    } else {
      line.append(s, len);
    }
    lua_pop(L, 1);
  }
  if (capped && !cut && line.size() + 1 > room) cut = true;
  std::string note;
  if (cut) note = "[output truncated: more than " + std::to_string(print_limit_) + " bytes printed]";
  // Counted once the texts are made: a print that ran out of memory making them printed nothing.
  print_truncated_ = print_truncated_ || cut;
  printed_ += line.size() + 1;
  if (print_ && (!cut || !line.empty())) print_(line);
  if (print_ && cut) print_(note);
}

// load(chunk [, chunkname [, mode [, env]]]) with mode forced to text: bytecode is never loaded.
int LuaRuntime::load_function(lua_State* L) {
  const int has_env = !lua_isnone(L, 4);
  size_t len = 0;
  const char* text = nullptr;
  std::string pieces;
  if (lua_type(L, 1) == LUA_TSTRING) {
    text = lua_tolstring(L, 1, &len);
  } else {
    luaL_checktype(L, 1, LUA_TFUNCTION);
    for (;;) {  // the reader-function form: concatenate the pieces it returns
      lua_pushvalue(L, 1);
      lua_call(L, 0, 1);
      if (lua_isnil(L, -1) || (lua_type(L, -1) == LUA_TSTRING && lua_rawlen(L, -1) == 0)) {
        lua_pop(L, 1);
        break;
      }
      if (lua_type(L, -1) != LUA_TSTRING) return luaL_error(L, "reader function must return a string");
      size_t n = 0;
      const char* piece = lua_tolstring(L, -1, &n);
      // The pieces are gathered in C++ memory, outside the allocator's cap: cap them too.
      if (pieces.size() + n > runtime_of(L)->limits_.memory_bytes) return luaL_error(L, "chunk too large to load");
      pieces.append(piece, n);
      lua_pop(L, 1);
    }
    text = pieces.c_str();
    len = pieces.size();
  }
  const char* name = luaL_optstring(L, 2, text == pieces.c_str() ? "=(load)" : text);
  const int status = luaL_loadbufferx(L, text, len, name, "t");
  if (status != LUA_OK) {
    luaL_pushfail(L);
    lua_insert(L, -2);
    return 2;
  }
  if (has_env) {
    lua_pushvalue(L, 4);
    if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
  }
  return 1;
}

// setmetatable that refuses a metatable with a __gc field: Lua runs finalizers with hooks switched off, so a
// finalizer that loops would escape every limit. (A field added later does not mark the object, and a
// placeholder __gc is refused too, so no finalizer written in Lua ever runs.)
int setmetatable_function(lua_State* L) {
  const int t = lua_type(L, 2);
  luaL_checktype(L, 1, LUA_TTABLE);
  luaL_argexpected(L, t == LUA_TNIL || t == LUA_TTABLE, 2, "nil or table");
  if (t == LUA_TTABLE) {
    lua_pushliteral(L, "__gc");
    const bool has_gc = lua_rawget(L, 2) != LUA_TNIL;
    lua_pop(L, 1);
    if (has_gc) return luaL_error(L, "__gc metamethods are not allowed in scripts");
  }
  if (luaL_getmetafield(L, 1, "__metatable") != LUA_TNIL) return luaL_error(L, "cannot change a protected metatable");
  lua_settop(L, 2);
  lua_setmetatable(L, 1);
  return 1;
}

int LuaRuntime::collectgarbage_function(lua_State* L) {
  const char* option = luaL_optstring(L, 1, "collect");
  if (std::strcmp(option, "count") == 0) {
    lua_pushnumber(L, lua_gc(L, LUA_GCCOUNT) + lua_gc(L, LUA_GCCOUNTB) / 1024.0);
    return 1;
  }
  if (std::strcmp(option, "collect") == 0) {
    lua_gc(L, LUA_GCCOLLECT);
    lua_pushinteger(L, 0);
    return 1;
  }
  if (std::strcmp(option, "step") == 0) {
    lua_pushboolean(L, lua_gc(L, LUA_GCSTEP, 0));
    return 1;
  }
  return luaL_argerror(L, 1, lua_pushfstring(L, "option '%s' is not allowed", option));
}

void LuaRuntime::open_whitelist() {
  struct Library {
    const char* name;
    lua_CFunction open;
  };
  const Library libraries[] = {{"_G", luaopen_base},
                               {LUA_STRLIBNAME, luaopen_string},
                               {LUA_TABLIBNAME, luaopen_table},
                               {LUA_MATHLIBNAME, luaopen_math},
                               {LUA_UTF8LIBNAME, luaopen_utf8},
                               {LUA_COLIBNAME, luaopen_coroutine},
                               {LUA_OSLIBNAME, luaopen_os}};
  for (const auto& library : libraries) {
    luaL_requiref(L_, library.name, library.open, 1);
    lua_pop(L_, 1);
  }
  lua_pushglobaltable(L_);
  for (const char* name : {"dofile", "loadfile", "warn"}) {
    lua_pushnil(L_);
    lua_setfield(L_, -2, name);
  }
  lua_pushcfunction(L_, &LuaRuntime::print_function);
  lua_setfield(L_, -2, "print");
  lua_pushcfunction(L_, &LuaRuntime::load_function);
  lua_setfield(L_, -2, "load");
  lua_pushcfunction(L_, &LuaRuntime::collectgarbage_function);
  lua_setfield(L_, -2, "collectgarbage");
  lua_pushcfunction(L_, setmetatable_function);
  lua_setfield(L_, -2, "setmetatable");
  lua_getfield(L_, -1, LUA_OSLIBNAME);
  keep_only(L_, {"clock", "time", "date", "difftime"});
  lua_pop(L_, 1);
  lua_getfield(L_, -1, LUA_STRLIBNAME);
  lua_pushnil(L_);
  lua_setfield(L_, -2, "dump");
  lua_pop(L_, 2);
  // Protect the string metatable: getmetatable("") returns false instead of the shared string table.
  lua_pushliteral(L_, "");
  lua_getmetatable(L_, -1);
  lua_pushboolean(L_, 0);
  lua_setfield(L_, -2, "__metatable");
  lua_pop(L_, 2);
  // Lessons get a fixed random sequence unless they seed it themselves.
  lua_getglobal(L_, LUA_MATHLIBNAME);
  lua_getfield(L_, -1, "randomseed");
  lua_pushinteger(L_, 184);
  lua_call(L_, 1, 0);
  lua_pop(L_, 1);
}

void LuaRuntime::start_run() {
  start_budget();
  lua_sethook(L_, &LuaRuntime::count_hook, LUA_MASKCOUNT, kHookInterval);
}

void LuaRuntime::start_budget() {
  instructions_ = 0;
  killed_ = false;
  kill_limit_ = ScriptError::Limit::None;
  kill_message_.clear();
  memory_hit_ = false;
  out_of_memory_ = false;
  cap_hit_ = false;
  memory_hit_where_.clear();
  printed_ = 0;
  print_truncated_ = false;
  window_open_ = true;
  deadline_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                     std::chrono::duration<double>(limits_.wall_seconds));
}

int LuaRuntime::protected_call(int nargs, int nresults) {
  const int base = lua_gettop(L_) - nargs;  // the function's slot
  lua_pushcfunction(L_, message_handler);
  lua_insert(L_, base);
  const int status = lua_pcall(L_, nargs, nresults, base);
  lua_remove(L_, base);
  return status;
}

ScriptError::Limit LuaRuntime::limit_hit() const {
  if (killed_) return kill_limit_;
  if (memory_hit_) return ScriptError::Limit::Memory;
  return cap_hit_ ? ScriptError::Limit::Changes : ScriptError::Limit::None;
}

void LuaRuntime::throw_error(int base, bool end_window) {
  std::string message = error_value_text(L_, -1);
  lua_settop(L_, base);
  // A memory error skips the message handler: give it the place and the reason it really has.
  if (memory_hit_ && !killed_ && message == "not enough memory") {
    message = memory_hit_where_ + memory_limit_message(limits_.memory_bytes);
  }
  const ScriptError::Limit limit = limit_hit();
  lua_sethook(L_, nullptr, 0, 0);
  if (end_window) window_open_ = false;
  throw ScriptError(message, limit, out_of_memory_);
}

void LuaRuntime::load(std::string_view code, const std::string& chunk_name) {
  const int base = lua_gettop(L_);
  const std::string name = "@" + chunk_name;
  if (luaL_loadbufferx(L_, code.data(), code.size(), name.c_str(), "t") != LUA_OK) throw_error(base, false);
}

int LuaRuntime::call(int nargs, int nresults) {
  const int base = lua_gettop(L_) - nargs - 1;
  if (base < 0 || !lua_isfunction(L_, base + 1)) {
    lua_settop(L_, base < 0 ? 0 : base);
    throw ScriptError("LuaRuntime::call: no function below the arguments");
  }
  if (!window_open_) start_budget();
  // A window whose limit was already hit stays stopped: the next instruction errors again.
  lua_sethook(L_, &LuaRuntime::count_hook, LUA_MASKCOUNT, killed_ || memory_hit_ ? 1 : kHookInterval);
  if (protected_call(nargs, nresults) != LUA_OK) throw_error(base, false);
  lua_sethook(L_, nullptr, 0, 0);
  return lua_gettop(L_) - base;
}

std::vector<std::string> LuaRuntime::run_string(std::string_view code, const std::string& chunk_name) {
  lua_settop(L_, 0);
  start_run();
  const std::string name = "@" + chunk_name;
  if (luaL_loadbufferx(L_, code.data(), code.size(), name.c_str(), "t") != LUA_OK) throw_error();
  if (protected_call(0, LUA_MULTRET) != LUA_OK) throw_error();
  const int n = lua_gettop(L_);
  lua_pushcfunction(L_, to_strings);
  lua_insert(L_, 1);
  if (protected_call(n, LUA_MULTRET) != LUA_OK) throw_error();
  std::vector<std::string> results;
  for (int i = 1; i <= n; ++i) {
    size_t len = 0;
    const char* s = lua_tolstring(L_, i, &len);
    results.emplace_back(s, len);
  }
  lua_settop(L_, 0);
  lua_sethook(L_, nullptr, 0, 0);
  window_open_ = false;
  return results;
}

void LuaRuntime::run_file(const std::filesystem::path& path, const std::vector<std::string>& args) {
  const FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw ScriptError("cannot open " + path.string());
  const std::string& code = file.bytes;

  lua_settop(L_, 0);
  lua_createtable(L_, static_cast<int>(args.size()), 1);
  lua_pushstring(L_, path.string().c_str());
  lua_rawseti(L_, -2, 0);
  for (size_t i = 0; i < args.size(); ++i) {
    lua_pushstring(L_, args[i].c_str());
    lua_rawseti(L_, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setglobal(L_, "arg");

  start_run();
  const std::string name = "@" + path.string();
  // A first line starting with '#' (a shebang) becomes a comment, keeping the line numbers, as lua.c skips it.
  const std::string body = !code.empty() && code[0] == '#' ? "--" + code : code;
  if (luaL_loadbufferx(L_, body.data(), body.size(), name.c_str(), "t") != LUA_OK) throw_error();
  for (const auto& a : args) lua_pushstring(L_, a.c_str());
  if (protected_call(static_cast<int>(args.size()), LUA_MULTRET) != LUA_OK) throw_error();
  lua_settop(L_, 0);
  lua_sethook(L_, nullptr, 0, 0);
  window_open_ = false;
}

}  // namespace meshedit
