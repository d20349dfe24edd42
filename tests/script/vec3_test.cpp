// vec3 in scripts: arithmetic with numbers on either side, methods, tostring, equality with plain tables,
// the error messages, and reading points from the three accepted table shapes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <lua.hpp>

#include "script/lua_runtime.h"
#include "script/script_runtime.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;

// A runtime with the vec3 constructor bound to the global `vec3` (independently of the meshedit module).
struct Vec3Fixture {
  ScriptRuntime lua;
  Vec3Fixture() {
    lua_newtable(lua.state());
    open_vec3(lua.state());
    lua_getfield(lua.state(), -1, "vec3");
    lua_setglobal(lua.state(), "vec3");
    lua_pop(lua.state(), 1);
  }
  Strings run(const std::string& code) { return lua.run_string(code, "v.lua"); }
  std::string error(const std::string& code) {
    try {
      lua.run_string(code, "v.lua");
    } catch (const ScriptError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST(Vec3, ArithmeticAndMethods) {
  Vec3Fixture f;
  EXPECT_EQ(f.run("local a, b = vec3(1, 2, 3), vec3(4, 5, 6) "
                  "return tostring(a + b), tostring(b - a), tostring(a * 2), tostring(0.5 * a), tostring(b / 2), "
                  "tostring(-a), a:dot(b), tostring(a:cross(b)), vec3(3, 4, 0):length(), "
                  "tostring(vec3(0, 0, 5):normalized()), tostring(vec3():normalized()), tostring(vec3(7))"),
            (Strings{"(5, 7, 9)", "(3, 3, 3)", "(2, 4, 6)", "(0.5, 1, 1.5)", "(2, 2.5, 3)", "(-1, -2, -3)", "32.0",
                     "(-3, 6, -3)", "5.0", "(0, 0, 1)", "(0, 0, 0)", "(7, 0, 0)"}));
}

TEST(Vec3, PlainTablesMixInAndCompareEqual) {
  Vec3Fixture f;
  EXPECT_EQ(f.run("local a = vec3(1, 2, 3) "
                  "return tostring(a + {1, 1, 1}), tostring({x = 1, y = 0, z = 0} + a), a == vec3(1, 2, 3), "
                  "a == {1, 2, 3}, a == vec3(1, 2, 4), a.x + a.y + a.z"),
            (Strings{"(2, 3, 4)", "(2, 2, 3)", "true", "true", "false", "6.0"}));
}

TEST(Vec3, ResultsAreFreshTablesAndTheMetatableIsProtected) {
  Vec3Fixture f;
  EXPECT_EQ(f.run("local a = vec3(1, 2, 3) local b = a + vec3() b.x = 9 "
                  "return a.x, getmetatable(a), pcall(setmetatable, a, {})"),
            (Strings{"1.0", "vec3", "false", "cannot change a protected metatable"}));
}

TEST(Vec3, ErrorsNameTheOperationAndType) {
  Vec3Fixture f;
  EXPECT_EQ(f.error("return vec3(1, 2, 3) + nil"), "v.lua:1: vec3 '+': expected a vec3, got nil");
  EXPECT_EQ(f.error("return vec3(1, 2, 3) - {1, 2}"), "v.lua:1: vec3 '-': expected a vec3, got table");
  EXPECT_EQ(f.error("return vec3(1, 2, 3) * vec3(1, 2, 3)"),
            "v.lua:1: vec3 '*': multiply by a number (use a:dot(b) or a:cross(b) for two vectors)");
  EXPECT_EQ(f.error("return vec3(1, 2, 3) / vec3()"), "v.lua:1: vec3 '/': divide by a number");
  EXPECT_EQ(f.error("return vec3('a')"), "v.lua:1: bad argument #1 to 'vec3' (number expected, got string)");
  EXPECT_EQ(f.error("return vec3(1, 2, 3):dot(5)"), "v.lua:1: vec3 'dot': expected a vec3, got number");
}

TEST(Vec3, CheckVec3AcceptsThreeShapesAndNamesWhatItWanted) {
  Vec3Fixture f;
  lua_State* L = f.lua.state();
  const char* shapes[] = {"return vec3(1, 2, 3)", "return {1, 2, 3}", "return {x = 1, y = 2, z = 3}"};
  for (const char* code : shapes) {
    ASSERT_EQ(luaL_dostring(L, code), LUA_OK) << code;
    glm::dvec3 p;
    EXPECT_TRUE(to_vec3(L, -1, p)) << code;
    EXPECT_EQ(p, glm::dvec3(1, 2, 3)) << code;
    lua_pop(L, 1);
  }
  ASSERT_EQ(luaL_dostring(L, "return {x = '1', y = 2, z = 3}"), LUA_OK);
  glm::dvec3 p(7.0);
  EXPECT_FALSE(to_vec3(L, -1, p));  // numeric strings are not numbers here
  EXPECT_EQ(p, glm::dvec3(7.0));
  lua_pop(L, 1);
}

}  // namespace
}  // namespace meshedit
