// LuaRuntime: the sandbox whitelist, print capture, and the limits a script cannot escape (instruction
// budget, memory cap, wall clock), each with its exact message.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "script/lua_runtime.h"

#include <lua.hpp>

namespace meshedit {
namespace {

std::string error_of(LuaRuntime& lua, const std::string& code, const std::string& name = "t.lua") {
  try {
    lua.run_string(code, name);
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LuaRuntime, ReturnsResultsAndPrintsThroughTheCallback) {
  LuaRuntime lua;
  std::vector<std::string> printed;
  lua.set_print([&](const std::string& line) { printed.push_back(line); });
  const auto results = lua.run_string("print('a', 1, nil, true) return 1 + 2, 'x'", "t.lua");
  EXPECT_EQ(results, (std::vector<std::string>{"3", "x"}));
  EXPECT_EQ(printed, (std::vector<std::string>{"a\t1\tnil\ttrue"}));
}

TEST(LuaRuntime, ErrorsCarryFileAndLine) {
  LuaRuntime lua;
  EXPECT_EQ(error_of(lua, "local x = 1\nerror('boom')", "lesson.lua"), "lesson.lua:2: boom");
  EXPECT_EQ(error_of(lua, "local x = = 1", "bad.lua"), "bad.lua:1: unexpected symbol near '='");
  EXPECT_EQ(error_of(lua, "error({})"), "(error object is a table value)");
  // Results are converted with tostring under the same protection and limits as the script.
  EXPECT_EQ(error_of(lua, "return setmetatable({}, {__tostring = function() error('no') end})"), "t.lua:1: no");
  EXPECT_EQ(lua.run_string("return setmetatable({}, {__tostring = function() return 'me' end}), nil", "t.lua"),
            (std::vector<std::string>{"me", "nil"}));
}

TEST(LuaRuntime, RunawayLoopStopsAtItsLine) {
  LuaRuntime lua(LuaLimits{10'000'000, size_t(64) << 20, 60.0});
  EXPECT_EQ(error_of(lua, "local n = 0\n\nwhile true do n = n + 1 end", "loop.lua"),
            "loop.lua:3: instruction budget exceeded (10000000 instructions)");
}

TEST(LuaRuntime, PcallCannotSwallowTheInstructionBudget) {
  LuaRuntime lua(LuaLimits{1'000'000, size_t(64) << 20, 60.0});
  const std::string message =
      error_of(lua, "while true do\n  pcall(function() while true do end end)\nend", "evade.lua");
  EXPECT_NE(message.find("instruction budget exceeded (1000000 instructions)"), std::string::npos) << message;
  EXPECT_EQ(message.rfind("evade.lua:", 0), 0u) << message;
  // The next run starts with a fresh budget.
  EXPECT_EQ(lua.run_string("return 40 + 2", "t.lua"), std::vector<std::string>{"42"});
}

TEST(LuaRuntime, PcallInsideCoroutinesCannotSwallowTheBudget) {
  LuaRuntime lua(LuaLimits{1'000'000, size_t(64) << 20, 60.0});
  const std::string message = error_of(
      lua, "while true do\n  pcall(coroutine.wrap(function() while true do pcall(function() end) end end))\nend");
  EXPECT_NE(message.find("instruction budget exceeded"), std::string::npos) << message;
}

TEST(LuaRuntime, ACoroutineFromAStoppedRunResumesWithTheNextRunsBudget) {
  LuaRuntime lua(LuaLimits{1'000'000, size_t(64) << 20, 60.0});
  const std::string message = error_of(lua,
                                       "co = coroutine.create(function(n)\n"
                                       "  while true do\n"
                                       "    local s = 0 for i = 1, n do s = s + i end n = coroutine.yield(s)\n"
                                       "  end\n"
                                       "end)\n"
                                       "coroutine.resume(co, 10)\n"
                                       "while true do end\n");
  EXPECT_EQ(message, "t.lua:7: instruction budget exceeded (1000000 instructions)");
  // The budget is per run: 10000 iterations fit in the next one.
  EXPECT_EQ(lua.run_string("return coroutine.resume(co, 10000)", "t.lua"),
            (std::vector<std::string>{"true", "50005000"}));
}

TEST(LuaRuntime, RunFileSetsArgAndSkipsAShebang) {
  const auto path = std::filesystem::temp_directory_path() / "meshedit_lua_runtime_test_args.lua";
  std::ofstream(path) << "#!/usr/bin/env meshedit run\n"
                         "print(arg[0] == '" +
                             path.string() +
                             "', #arg, arg[2], select('#', ...), (...))\n"
                             "error('x')\n";
  LuaRuntime lua;
  std::vector<std::string> printed;
  lua.set_print([&](const std::string& line) { printed.push_back(line); });
  try {
    lua.run_file(path, {"a", "b"});
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()).substr(std::string(e.what()).size() - 5), ":3: x");
  }
  EXPECT_EQ(printed, std::vector<std::string>{"true\t2\tb\t2\ta"});
  std::filesystem::remove(path);
  EXPECT_THROW(lua.run_file(path), ScriptError);
}

TEST(LuaRuntime, MemoryBombStops) {
  LuaRuntime lua(LuaLimits{1'000'000'000, size_t(32) << 20, 60.0});
  EXPECT_EQ(error_of(lua, "local s = 'x'\nlocal t = s:rep(1 << 30)", "bomb.lua"),
            "bomb.lua:2: memory limit exceeded (32 MB)");
  EXPECT_LT(lua.memory_used(), size_t(33) << 20);
}

TEST(LuaRuntime, PcallCannotSwallowTheMemoryCap) {
  LuaRuntime lua(LuaLimits{1'000'000'000, size_t(32) << 20, 60.0});
  const std::string message = error_of(lua,
                                       "local t = {}\n"
                                       "while true do\n"
                                       "  pcall(function() t[#t + 1] = string.rep('x', 1 << 22) end)\n"
                                       "end",
                                       "grow.lua");
  EXPECT_NE(message.find("memory limit exceeded (32 MB)"), std::string::npos) << message;
  EXPECT_EQ(message.rfind("grow.lua:", 0), 0u) << message;
}

// Memory running out is a flag set where a std::bad_alloc is caught (tests/out_of_memory), never read from the text: a
// script that says the words itself, or one that hits the memory cap (its own doing), did not run out of memory.
TEST(LuaRuntime, AScriptsOwnMemoryRanOutErrorIsNotOutOfMemory) {
  LuaRuntime lua(LuaLimits{1'000'000'000, size_t(32) << 20, 60.0});
  try {
    lua.run_string("error('memory ran out')", "own.lua");
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), "own.lua:1: memory ran out");
    EXPECT_FALSE(e.out_of_memory());
    EXPECT_EQ(e.limit(), ScriptError::Limit::None);
  }
  EXPECT_FALSE(lua.ran_out_of_memory());
  try {
    lua.run_string("local s = 'x'\nlocal t = s:rep(1 << 30)", "bomb.lua");
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(e.limit(), ScriptError::Limit::Memory);
    EXPECT_FALSE(e.out_of_memory());
  }
  EXPECT_FALSE(lua.ran_out_of_memory());
}

TEST(LuaRuntime, WallClockStopsALoopTheBudgetAllows) {
  LuaRuntime lua(LuaLimits{~uint64_t(0) >> 1, size_t(64) << 20, 0.05});
  const std::string message = error_of(lua, "while true do pcall(function() end) end", "slow.lua");
  EXPECT_EQ(message, "slow.lua:1: time limit exceeded (0.05 s)");
}

TEST(LuaRuntime, OnlyWhitelistedLibrariesExist) {
  LuaRuntime lua;
  const auto r = lua.run_string(
      "return type(io), type(package), type(require), type(debug), type(dofile), type(loadfile),\n"
      "  type(os.execute), type(os.getenv), type(os.exit), type(os.clock), type(os.time), type(os.date),\n"
      "  type(string.dump), type(string.rep), type(table.concat), type(math.sqrt), type(utf8.char),\n"
      "  type(coroutine.wrap), tostring(getmetatable(''))",
      "t.lua");
  EXPECT_EQ(r, (std::vector<std::string>{"nil", "nil", "nil", "nil", "nil", "nil", "nil", "nil", "nil", "function",
                                         "function", "function", "nil", "function", "function", "function", "function",
                                         "function", "false"}));
}

TEST(LuaRuntime, LoadIsTextOnly) {
  LuaRuntime lua;
  EXPECT_EQ(lua.run_string("return load('return 6 * 7')()", "t.lua"), std::vector<std::string>{"42"});
  EXPECT_EQ(lua.run_string("local f, e = load('\\27Lua junk') return tostring(f), e", "t.lua"),
            (std::vector<std::string>{"nil", "attempt to load a binary chunk (mode is 't')"}));
  EXPECT_EQ(lua.run_string("return load('return x', 'c', 't', {x = 5})()", "t.lua"), std::vector<std::string>{"5"});
  EXPECT_EQ(error_of(lua, "collectgarbage('stop')"),
            "t.lua:1: bad argument #1 to 'collectgarbage' (option 'stop' is not allowed)");
}

TEST(LuaRuntime, PrintIsCappedPerWindow) {
  LuaRuntime lua;
  std::vector<std::string> printed;
  lua.set_print([&](const std::string& line) { printed.push_back(line); });
  lua.set_print_limit(10);
  lua.run_string("print('abcd') print('efghijkl') print('never')", "t.lua");
  // 'abcd' + newline = 5 bytes; the second line gets the 4 that are left (its newline is the 10th byte).
  EXPECT_EQ(printed, (std::vector<std::string>{"abcd", "efgh", "[output truncated: more than 10 bytes printed]"}));
  EXPECT_TRUE(lua.print_truncated());
  printed.clear();
  // A megabyte print is cut without being built in full, and the next window starts a fresh count.
  lua.run_string("print(string.rep('x', 1 << 20)) print('y')", "t.lua");
  EXPECT_EQ(printed, (std::vector<std::string>{"xxxxxxxxx", "[output truncated: more than 10 bytes printed]"}));
  printed.clear();
  lua.run_string("print('ok')", "t.lua");
  EXPECT_EQ(printed, std::vector<std::string>{"ok"});
  EXPECT_FALSE(lua.print_truncated());
}

TEST(LuaRuntime, SetmetatableRefusesFinalizers) {
  LuaRuntime lua;
  EXPECT_EQ(error_of(lua, "setmetatable({}, {__gc = function() while true do end end})"),
            "t.lua:1: __gc metamethods are not allowed in scripts");
  // A placeholder would mark the object for finalization as well.
  EXPECT_EQ(error_of(lua, "setmetatable({}, {__gc = true})"), "t.lua:1: __gc metamethods are not allowed in scripts");
  EXPECT_EQ(lua.run_string("local t = setmetatable({}, {__index = function() return 7 end}) return t.x", "t.lua"),
            std::vector<std::string>{"7"});
  EXPECT_EQ(error_of(lua, "local t = setmetatable({}, {__metatable = 1}) setmetatable(t, {})"),
            "t.lua:1: cannot change a protected metatable");
}

TEST(LuaRuntime, LoadAndCallShareOneBudgetWindow) {
  LuaRuntime lua(LuaLimits{1'000'000, size_t(64) << 20, 60.0});
  lua_State* L = lua.state();
  lua.load("function spin(n) local s = 0 for i = 1, n do s = s + i end return s end", "lib.lua");
  lua.start_budget();
  EXPECT_EQ(lua.call(0, 0), 0);
  lua_getglobal(L, "spin");
  lua_pushinteger(L, 1000);
  ASSERT_EQ(lua.call(1, LUA_MULTRET), 1);
  EXPECT_EQ(lua_tointeger(L, -1), 500500);
  lua_settop(L, 0);
  // Two calls of 400k iterations each: the second one runs out of the window's budget.
  lua_getglobal(L, "spin");
  lua_pushinteger(L, 100'000);
  EXPECT_EQ(lua.call(1, 1), 1);
  lua_settop(L, 0);
  lua_pushinteger(L, 99);  // stays below the function: the stack is restored to it after an error
  lua_getglobal(L, "spin");
  lua_pushinteger(L, 1'000'000);
  try {
    lua.call(1, 1);
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), "lib.lua:1: instruction budget exceeded (1000000 instructions)");
    EXPECT_EQ(e.limit(), ScriptError::Limit::Instructions);
  }
  EXPECT_EQ(lua_gettop(L), 1);
  // The window stays stopped: even a tiny call fails until a new window opens.
  lua_getglobal(L, "spin");
  lua_pushinteger(L, 1);
  EXPECT_THROW(lua.call(1, 1), ScriptError);
  lua.start_budget();
  lua_getglobal(L, "spin");
  lua_pushinteger(L, 3);
  EXPECT_EQ(lua.call(1, 1), 1);
  EXPECT_EQ(lua_tointeger(L, -1), 6);
  lua_settop(L, 0);
}

TEST(LuaRuntime, LoadReportsSyntaxErrorsAndErrorsSayWhichLimit) {
  LuaRuntime lua(LuaLimits{1'000'000'000, size_t(32) << 20, 60.0});
  lua_State* L = lua.state();
  try {
    lua.load("x = = 1", "student.lua");
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), "student.lua:1: unexpected symbol near '='");
    EXPECT_EQ(e.limit(), ScriptError::Limit::None);
  }
  EXPECT_EQ(lua_gettop(L), 0);
  lua.load("local t = {} while true do pcall(function() t[#t + 1] = ('x'):rep(1 << 22) end) end", "grow.lua");
  try {
    lua.start_budget();
    lua.call(0, 0);
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(e.limit(), ScriptError::Limit::Memory) << e.what();
  }
  LuaRuntime slow(LuaLimits{~uint64_t(0) >> 1, size_t(64) << 20, 0.05});
  slow.load("while true do end", "slow.lua");
  try {
    slow.call(0, 0);
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), "slow.lua:1: time limit exceeded (0.05 s)");
    EXPECT_EQ(e.limit(), ScriptError::Limit::Time);
  }
}

TEST(LuaRuntime, LoadReaderPiecesAreCapped) {
  LuaRuntime lua(LuaLimits{1'000'000'000, size_t(16) << 20, 60.0});
  const std::string message = error_of(lua, "local s = ('-'):rep(1 << 20)\nload(function() return s end)", "r.lua");
  EXPECT_EQ(message, "r.lua:2: chunk too large to load");
}

}  // namespace
}  // namespace meshedit
