// LuaRuntime: one sandboxed Lua 5.4 state with limits a script cannot escape.
//
// Invariants:
// - Lua is Debian's C++ build: a Lua error unwinds C++ frames (destructors run). Bindings catch
//   std::exception and turn it into a Lua error (`guarded` in mesh_bindings.cpp); no C++ exception crosses
//   into Lua.
// - The instruction budget, the memory cap, the wall-clock deadline and the host's stop request are checked in one
//   count hook (the stop request is the only state another thread may touch, and only the flag it points to).
//   Once any of them is exceeded the runtime is "killed": the hook is re-armed to fire on every instruction
//   and errors each time, so a `pcall` in the script cannot swallow the stop; it lasts until the next window.
// - Globals are built by whitelist: base (without dofile, loadfile, warn; load is text-only; collectgarbage
//   only "count", "collect" and "step"; setmetatable refuses __gc, because Lua runs finalizers with hooks off),
//   string (without dump), table, math, utf8, coroutine, and os with only clock, time, date, difftime. No io,
//   package/require or debug. The string metatable is protected.
// - A LuaRuntime opens the standard libraries only; script_runtime.h's ScriptRuntime adds the `meshedit` module.
// - The wall clock is checked in the hook only: a long call into C (a pathological string pattern, one big
//   C++ operation) is not interrupted; a watchdog thread or a child process is the backstop for that.
// - Every error a run reports is a string starting with `file:line:` when Lua knows the line.
// - Limits are counted per budget window: run_string and run_file each open their own; a host calling
//   functions itself (load + call) opens one with start_budget(), and every call in it shares the budget,
//   so a grader can give a whole test one budget however many times it calls into the script.
// - print output is capped per window (set_print_limit), and a print that fails is a Lua error (set_print).
// - Out of memory: the script layer's rule of docs/ARCHITECTURE.md (Memory running out). Memory running out (a
//   binding's or the host's std::bad_alloc, Lua's allocator finding none) is flagged where it is caught
//   (ran_out_of_memory, ScriptError::out_of_memory), and so is a binding's cap (note_cap,
//   ScriptError::Limit::Changes); callers never guess either from an error's text.
// - No finalizer written in Lua ever runs (setmetatable refuses __gc), so neither a collection in the middle
//   of a run nor closing the state can run script code outside the hook.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "script/small_block_pool.h"

struct lua_State;
struct lua_Debug;

namespace meshedit {

// A script failed: the Lua error message ("loop.lua:3: instruction budget exceeded (10000000 instructions)").
class ScriptError : public std::runtime_error {
 public:
  // Which limit stopped the script, if one did (a grader reports a timeout differently from an error). Changes: a
  // binding's cap on what a script may make (recorded changes, element ids), noted with LuaRuntime::note_cap.
  // Stopped: the host asked the script to stop (LuaRuntime::set_stop_request: the window's Stop button).
  enum class Limit { None, Instructions, Memory, Time, Changes, Stopped };
  using std::runtime_error::runtime_error;
  ScriptError(const std::string& message, Limit limit, bool out_of_memory = false)
      : std::runtime_error(message), limit_(limit), out_of_memory_(out_of_memory) {}
  Limit limit() const { return limit_; }
  // Whether memory ran out under the script (LuaRuntime::ran_out_of_memory): not the script's doing, and gone with
  // memory to spare; told apart from a script's own error("memory ran out") by this flag, never by the text.
  bool out_of_memory() const { return out_of_memory_; }

 private:
  Limit limit_ = Limit::None;
  bool out_of_memory_ = false;
};

struct LuaLimits {
  uint64_t instructions = 1'000'000'000;    // per run; counted in steps of kHookInterval
  size_t memory_bytes = size_t(512) << 20;  // everything Lua allocates (not C++ mesh storage)
  double wall_seconds = 60.0;               // per run
};

// The Lua error value at `index` as text: a string as it is, anything else named by its type ("(error object is a
// table value)"). Never calls __tostring, which is script code and would run outside the limits' reach.
std::string error_value_text(lua_State* L, int index);
// "memory limit exceeded (32 MB)": what a run stopped by the memory cap of `bytes` says, wherever it was stopped.
std::string memory_limit_message(size_t bytes);
// A Lua file's text as lua.c reads it (lua_source.h: a UTF-8 byte order mark dropped, a first line starting with '#',
// a shebang, made a comment), or nullopt when it cannot be read (core/file_bytes.h: not a regular file, or too large).
std::optional<std::string> read_lua_file(const std::filesystem::path& path);

class LuaRuntime {
 public:
  static constexpr int kHookInterval = 1000;

  explicit LuaRuntime(LuaLimits limits = {});  // throws std::bad_alloc when the state cannot be made
  virtual ~LuaRuntime();
  LuaRuntime(const LuaRuntime&) = delete;
  LuaRuntime& operator=(const LuaRuntime&) = delete;

  lua_State* state() { return L_; }
  const LuaLimits& limits() const { return limits_; }
  // New limits; they apply from the next budget window (the memory cap applies at once).
  void set_limits(const LuaLimits& limits) { limits_ = limits; }
  // A flag another thread may set to stop the script: once it is true, the script stops within kHookInterval
  // instructions with ScriptError::Limit::Stopped ("stopped: you pressed Stop", at its line), as a limit stops it.
  // nullptr (the default) for none; the flag must outlive the calls made while it is set.
  void set_stop_request(const std::atomic<bool>* stop) { stop_request_ = stop; }
  // Where `print` writes: one call per print, the arguments joined by tabs, without the newline. A print that fails
  // (the callback throws, or memory runs out building the line) is the Lua error "print failed: <what>", with
  // "memory ran out" for a std::bad_alloc or a message that cannot be copied: reporting it cannot fail in turn.
  void set_print(std::function<void(const std::string&)> print) { print_ = std::move(print); }
  // At most `bytes` of printed text (tabs and newlines counted) reach the callback per budget window; 0 means no cap
  // (the default). Past the cap the callback gets one "[output truncated ...]" line and nothing more, and the text
  // is never built past the cap in C++.
  void set_print_limit(size_t bytes) { print_limit_ = bytes; }
  // Whether output was dropped in the current (or last) window.
  bool print_truncated() const { return print_truncated_; }

  // Runs Lua source text (text only, never bytecode); `chunk_name` is what errors show before `:line:`
  // (give "loop.lua", not "@loop.lua"). Returns the chunk's results converted with tostring.
  // Throws ScriptError with the Lua message on any error, including a limit being hit.
  std::vector<std::string> run_string(std::string_view code, const std::string& chunk_name);
  // Runs a file with `arg` set as lua.c does: arg[0] = the path, arg[1..] = args; `...` is args too.
  // Throws ScriptError (a missing or unreadable file included).
  void run_file(const std::filesystem::path& path, const std::vector<std::string>& args = {});

  // The host-driven way to run code: compile, then call within a budget window.
  // Compiles source text (never bytecode) and pushes the chunk as a function. Throws ScriptError with the
  // syntax error; the stack is then as before.
  void load(std::string_view code, const std::string& chunk_name);
  // Opens a new budget window: the instruction count, the memory flags, the kill and the print count restart,
  // and the wall-clock deadline is limits().wall_seconds from now.
  void start_budget();
  // Calls the function below the top `nargs` values within the current window (one is opened if none is),
  // under a message handler that never runs __tostring. Leaves `nresults` results (LUA_MULTRET for all) in
  // place of the function and arguments and returns how many. Throws ScriptError on any error or limit; the
  // stack is then as it was below the function. After a limit was hit, later calls in the same window fail
  // at their first Lua instruction with the same limit (a budget is per window, not per call).
  int call(int nargs, int nresults);

  // Bytes Lua holds now. Lua's memory comes from allocate(): blocks up to 256 bytes from a per-runtime
  // SmallBlockPool, larger ones from malloc. The memory cap counts the bytes Lua asked for, whichever served them.
  size_t memory_used() const { return memory_used_; }

  // Whether memory ran out in the current (or last) budget window: a C function turned a std::bad_alloc into a Lua
  // error (note_out_of_memory), or Lua's allocator found no memory below the cap. Not the memory cap (Limit::Memory,
  // the script's own doing), nor a script raising the words "memory ran out". The errors of such a window are
  // ScriptError::out_of_memory, even one the script raised after catching the first with pcall.
  bool ran_out_of_memory() const { return out_of_memory_; }
  // What a C function calls when it turns a std::bad_alloc (or a message that could not be copied for lack of memory)
  // into a Lua error: marks the window of the runtime that owns `L` (any of its threads). Never throws.
  static void note_out_of_memory(lua_State* L) noexcept;
  // What a binding calls before it raises the error of a cap on what a script may make (more changes than a recorder
  // keeps, more ids than MeshLimits allow): the errors of the runtime's current window are Limit::Changes, unless
  // one of the runtime's own limits stopped it. Never throws.
  static void note_cap(lua_State* L) noexcept;

 private:
  static void* allocate(void* ud, void* ptr, size_t old_size, size_t new_size);
  static void count_hook(lua_State* L, lua_Debug* ar);
  static int print_function(lua_State* L);
  // print's work: the arguments joined, cut at the cap, given to the callback. Throws what building the line or the
  // callback throws (print_function turns it into a Lua error).
  void print_arguments(lua_State* L);
  static int load_function(lua_State* L);
  static int collectgarbage_function(lua_State* L);
  void open_whitelist();
  void start_run();
  // Runs the function below the top `nargs` values; leaves results on the stack; returns the Lua status.
  int protected_call(int nargs, int nresults);
  // Throws the error on top of the stack as ScriptError, after cutting the stack to `base` values;
  // run_string/run_file end their window with it, call() keeps the window (a test's budget outlives errors).
  [[noreturn]] void throw_error(int base = 0, bool end_window = true);
  ScriptError::Limit limit_hit() const;
  void note_memory_hit();

  LuaLimits limits_;
  SmallBlockPool pool_;  // Lua's small blocks; outlives the lua_close in ~LuaRuntime, which returns them
  lua_State* L_ = nullptr;
  std::function<void(const std::string&)> print_;
  size_t print_limit_ = 0;
  size_t printed_ = 0;
  bool print_truncated_ = false;
  bool window_open_ = false;
  size_t memory_used_ = 0;
  bool memory_hit_ = false;
  bool out_of_memory_ = false;    // ran_out_of_memory()
  bool cap_hit_ = false;          // note_cap
  std::string memory_hit_where_;  // "file:line: " of the allocation that hit the cap
  uint64_t instructions_ = 0;
  bool killed_ = false;
  ScriptError::Limit kill_limit_ = ScriptError::Limit::None;
  std::string kill_message_;  // without location
  std::chrono::steady_clock::time_point deadline_;
  const std::atomic<bool>* stop_request_ = nullptr;
};

}  // namespace meshedit
