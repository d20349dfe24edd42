// LuaRuntime: one sandboxed Lua 5.4 state with limits a script cannot escape.
//
// Invariants:
// - Lua is Debian's C++ build: a Lua error unwinds C++ frames (destructors run). Bindings catch
//   std::exception and turn it into a Lua error (`guarded` in mesh_bindings.cpp); no C++ exception crosses
//   into Lua.
// - The instruction budget, the memory cap and the wall-clock deadline are checked in one count hook.
//   Once any of them is exceeded the runtime is "killed": the hook is re-armed to fire on every instruction
//   and errors each time, so a `pcall` in the script cannot swallow the stop; it lasts until the next run.
// - Globals are built by whitelist: base (without dofile, loadfile, warn; load is text-only; collectgarbage
//   only "count", "collect" and "step"), string (without dump), table, math, utf8, coroutine, and os with only
//   clock, time, date, difftime. No io, package/require or debug. The string metatable is protected.
// - The `meshedit` module (mesh_bindings.h) is opened in every runtime.
// - The wall clock is checked in the hook only: a long call into C (a pathological string pattern, one big
//   C++ operation) is not interrupted; a watchdog thread or a child process is the backstop for that.
// - Every error a run reports is a string starting with `file:line:` when Lua knows the line.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct lua_State;
struct lua_Debug;

namespace meshedit {

// A script failed: the Lua error message ("loop.lua:3: instruction budget exceeded (10000000 instructions)").
class ScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LuaLimits {
  uint64_t instructions = 1'000'000'000;  // per run; counted in steps of kHookInterval
  size_t memory_bytes = size_t(512) << 20;  // everything Lua allocates (not C++ mesh storage)
  double wall_seconds = 60.0;              // per run
};

class LuaRuntime {
 public:
  static constexpr int kHookInterval = 1000;

  explicit LuaRuntime(LuaLimits limits = {});
  ~LuaRuntime();
  LuaRuntime(const LuaRuntime&) = delete;
  LuaRuntime& operator=(const LuaRuntime&) = delete;

  lua_State* state() { return L_; }
  const LuaLimits& limits() const { return limits_; }
  // Where `print` writes: one call per print, the arguments joined by tabs, without the newline.
  void set_print(std::function<void(const std::string&)> print) { print_ = std::move(print); }

  // Runs Lua source text (text only, never bytecode); `chunk_name` is what errors show before `:line:`
  // (give "loop.lua", not "@loop.lua"). Returns the chunk's results converted with tostring.
  // Throws ScriptError with the Lua message on any error, including a limit being hit.
  std::vector<std::string> run_string(std::string_view code, const std::string& chunk_name);
  // Runs a file with `arg` set as lua.c does: arg[0] = the path, arg[1..] = args; `...` is args too.
  // Throws ScriptError (a missing or unreadable file included).
  void run_file(const std::filesystem::path& path, const std::vector<std::string>& args = {});

  // Bytes Lua holds now.
  size_t memory_used() const { return memory_used_; }

 private:
  static void* allocate(void* ud, void* ptr, size_t old_size, size_t new_size);
  static void count_hook(lua_State* L, lua_Debug* ar);
  static int print_function(lua_State* L);
  static int load_function(lua_State* L);
  static int collectgarbage_function(lua_State* L);
  void open_whitelist();
  void start_run();
  // Runs the function on top of the stack with `nargs` arguments below it; leaves results on the stack.
  int call(int nargs);
  [[noreturn]] void throw_error();
  void note_memory_hit();

  LuaLimits limits_;
  lua_State* L_ = nullptr;
  std::function<void(const std::string&)> print_;
  size_t memory_used_ = 0;
  bool memory_hit_ = false;
  std::string memory_hit_where_;  // "file:line: " of the allocation that hit the cap
  uint64_t instructions_ = 0;
  bool killed_ = false;
  std::string kill_message_;       // without location
  std::chrono::steady_clock::time_point deadline_;
};

}  // namespace meshedit
