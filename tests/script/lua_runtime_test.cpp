// LuaRuntime: the sandbox whitelist, print capture, and the limits a script cannot escape (instruction
// budget, memory cap, wall clock), each with its exact message.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "script/lua_runtime.h"

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
                          "print(arg[0] == '" + path.string() + "', #arg, arg[2], select('#', ...), (...))\n"
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
                                         "function", "function", "nil", "function", "function", "function",
                                         "function", "function", "false"}));
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

}  // namespace
}  // namespace meshedit
