// The Bézier Lua API: every result equals core/bezier.h bit for bit (compared through vec3's shortest
// round-trip printing), .bzc/.bez loading, immutability of curves and patches, and every error message.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/bezier.h"
#include "core/value_format.h"
#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "script/bezier_bindings.h"
#include "script/lua_runtime.h"
#include "script/script_runtime.h"
#include "script/vec3_bindings.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;

// A runtime whose meshedit module has the Bézier API (and vec3, whoever opens it first).
struct Fixture {
  ScriptRuntime lua;
  Fixture() {
    lua_State* L = lua.state();
    lua_getglobal(L, "meshedit");
    open_vec3(L);
    open_bezier_bindings(L);
    lua_pop(L, 1);
    // Lua helpers: a list of points as "(x, y, z) (x, y, z)", levels joined by " | ".
    lua.run_string(
        "function str(points) local s = {} for i, p in ipairs(points) do s[i] = tostring(p) end "
        "return table.concat(s, ' ') end "
        "function strlevels(levels) local s = {} for i, l in ipairs(levels) do s[i] = str(l) end "
        "return table.concat(s, ' | ') end",
        "helpers.lua");
  }
  Strings run(const std::string& code) { return lua.run_string(code, "t.lua"); }
  std::string error(const std::string& code) {
    try {
      lua.run_string(code, "t.lua");
    } catch (const ScriptError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

std::string str(std::span<const glm::dvec3> points) {
  std::string s;
  for (const auto& p : points) s += (s.empty() ? "" : " ") + format_position(p);
  return s;
}

std::string strlevels(const std::vector<std::vector<glm::dvec3>>& levels) {
  std::string s;
  for (const auto& l : levels) s += (s.empty() ? "" : " | ") + str(l);
  return s;
}

const std::vector<glm::dvec3> kCubic = {{0.1, 0.2, 0}, {0.35, 0.9, 0}, {0.65, 0.1, 0}, {0.9, 0.8, 0}};
const char* kCubicLua =
    "meshedit.curve({{0.1, 0.2, 0}, meshedit.vec3(0.35, 0.9), {x = 0.65, y = 0.1, z = 0}, "
    "{0.9, 0.8, 0}})";

TEST(BezierBindings, CurveResultsAreTheCoresBitForBit) {
  Fixture f;
  f.run(std::string("c = ") + kCubicLua);
  for (double t : {0.0, 0.25, 0.3, 0.5, 0.7, 1.0, 1.5}) {
    SCOPED_TRACE(t);
    const std::string ts = format_number(t);
    const CurveSplit<glm::dvec3> halves = split_curve(std::span<const glm::dvec3>(kCubic), t);
    EXPECT_EQ(f.run("local l, r = c:split(" + ts + ") return tostring(c:evaluate(" + ts + ")), strlevels(c:levels(" +
                    ts + ")), str(c:step(c.points, " + ts + ")), str(l.points), str(r.points), #l, #r"),
              (Strings{format_position(evaluate_curve(std::span<const glm::dvec3>(kCubic), t)),
                       strlevels(de_casteljau_levels(std::span<const glm::dvec3>(kCubic), t)),
                       str(de_casteljau_step(std::span<const glm::dvec3>(kCubic), t)), str(halves.left),
                       str(halves.right), "4", "4"}));
  }
  // A step of an arbitrary list, 3D, and of a single point (no points).
  const std::vector<glm::dvec3> three = {{1, 2, 3}, {-1, 0.5, 7}, {4, 4, 4}};
  EXPECT_EQ(f.run("return str(c:step({{1, 2, 3}, {-1, 0.5, 7}, {4, 4, 4}}, 0.3)), #c:step({{1, 2, 3}}, 0.3)"),
            (Strings{str(de_casteljau_step(std::span<const glm::dvec3>(three), 0.3)), "0"}));
}

TEST(BezierBindings, CurveLevelsHaveEveryStep) {
  Fixture f;
  f.run(std::string("c = ") + kCubicLua);
  EXPECT_EQ(f.run("local l = c:levels(0.5) return #l, #l[1], #l[2], #l[3], #l[4], str(l[1]) == str(c.points), "
                  "tostring(l[4][1]) == tostring(c:evaluate(0.5))"),
            (Strings{"4", "4", "3", "2", "1", "true", "true"}));
  EXPECT_EQ(f.run("return tostring(c), #c, str(c.points), tostring(meshedit.curve({{1, 1, 1}}))"),
            (Strings{"curve (4 points)", "4", str(kCubic), "curve (1 point)"}));
}

TEST(BezierBindings, CurvesAndPatchesAreImmutableValues) {
  Fixture f;
  f.run(std::string("c = ") + kCubicLua);
  f.run("p = meshedit.patch((function() local t = {} for i = 1, 16 do t[i] = {i, 0, 0} end return t end)())");
  EXPECT_EQ(f.run("local pts = c.points pts[1].x = 99 pts[2] = nil "
                  "local q = p.points q[1].x = 42 local e = c:evaluate(0) e.x = 7 "
                  "return c.points[1].x, #c.points, p.points[1].x, c:evaluate(0).x, c.points ~= c.points"),
            (Strings{"0.1", "4", "1.0", "0.1", "true"}));
  // Results carry the vec3 metatable.
  EXPECT_EQ(f.run("return tostring(c:evaluate(0) + c:evaluate(1)), getmetatable(c), getmetatable(p)"),
            (Strings{format_position(kCubic[0] + kCubic[3]), "false", "false"}));
}

TEST(BezierBindings, PatchResultsAreTheCoresBitForBit) {
  Fixture f;
  const auto teapot = read_bez(testing::source_dir() / "assets" / "teapot.bez");
  ASSERT_EQ(teapot.size(), 32u);
  f.lua.run_string(
      "patches = meshedit.load_patches('" + (testing::source_dir() / "assets" / "teapot.bez").string() + "')", "t.lua");
  EXPECT_EQ(f.run("return #patches, tostring(patches[1])"), (Strings{"32", "patch"}));
  for (int index : {1, 6, 14, 22}) {
    const BezierPatch& patch = teapot[index - 1];
    EXPECT_EQ(f.run("return str(patches[" + std::to_string(index) + "].points)"), Strings{str(patch.points)});
    for (auto [u, v] : {std::pair{0.0, 0.0}, {0.3, 0.8}, {0.5, 0.25}, {1.0, 0.6}}) {
      SCOPED_TRACE(std::to_string(index) + " " + std::to_string(u) + " " + std::to_string(v));
      const std::string args = format_number(u) + ", " + format_number(v);
      const PatchEvaluation e = evaluate_patch_steps(patch, u, v);
      EXPECT_EQ(f.run("local p = patches[" + std::to_string(index) + "] local e = p:evaluation(" + args +
                      ") return tostring(p:evaluate(" + args + ")), str(p:rows(" + format_number(u) +
                      ")), str(e.rows), strlevels(e.column_levels), tostring(e.point)"),
                (Strings{format_position(evaluate_patch(patch, u, v)), str(e.row_points), str(e.row_points),
                         strlevels(e.column_levels), format_position(e.point)}));
    }
  }
}

TEST(BezierBindings, PatchFromAListIsRowMajor) {
  Fixture f;
  // Row r, column c at (c, r, r * c): the corners come back as the core documents.
  f.run("local t = {} for r = 0, 3 do for c = 0, 3 do t[#t + 1] = {c, r, r * c} end end p = meshedit.patch(t)");
  EXPECT_EQ(f.run("return tostring(p:evaluate(0, 0)), tostring(p:evaluate(1, 0)), tostring(p:evaluate(0, 1)), "
                  "tostring(p:evaluate(1, 1)), tostring(p.points[6])"),
            (Strings{"(0, 0, 0)", "(3, 0, 0)", "(0, 3, 0)", "(3, 3, 9)", "(1, 1, 1)"}));
}

TEST(BezierBindings, LoadCurveGivesZZero) {
  Fixture f;
  const auto path = testing::source_dir() / "assets" / "curve_quartic.bzc";
  const BezierCurve curve = read_bzc(path);
  std::vector<glm::dvec3> expected;
  for (const auto& p : curve.control_points) expected.emplace_back(p.x, p.y, 0.0);
  EXPECT_EQ(f.run("local c = meshedit.load_curve('" + path.string() + "') return str(c.points), #c"),
            (Strings{str(expected), std::to_string(expected.size())}));
}

TEST(BezierBindings, CourseFilesLoad) {
  MESHEDIT_REQUIRE_COURSE_DATA(dir);
  Fixture f;
  EXPECT_EQ(f.run("return #meshedit.load_curve('" + (dir / "bzc" / "curve1.bzc").string() +
                  "'), #meshedit.load_patches('" + (dir / "bez" / "teapot.bez").string() + "')"),
            (Strings{"4", "32"}));
}

TEST(BezierBindings, ErrorsNameTheArgumentAndThePoint) {
  Fixture f;
  f.run(std::string("c = ") + kCubicLua);
  EXPECT_EQ(f.error("meshedit.curve(5)"), "t.lua:1: bad argument #1 to 'curve' (table expected, got number)");
  EXPECT_EQ(f.error("meshedit.curve({})"),
            "t.lua:1: bad argument #1 to 'curve' (a curve needs at least one control point)");
  EXPECT_EQ(f.error("meshedit.curve({{1, 2, 3}, 'x'})"),
            "t.lua:1: bad argument #1 to 'curve' (point 2 must be a vec3 or a table {x, y, z} of numbers, got string)");
  EXPECT_EQ(f.error("meshedit.curve({{1, 2, 3}, {1, 2}})"),
            "t.lua:1: bad argument #1 to 'curve' (point 2 must be a vec3 or a table {x, y, z} of numbers, got table)");
  EXPECT_EQ(f.error("local t = {} for i = 1, 1025 do t[i] = {i, 0, 0} end meshedit.curve(t)"),
            "t.lua:1: bad argument #1 to 'curve' (at most 1024 points are allowed, got 1025)");
  EXPECT_EQ(f.error("c:evaluate('x')"), "t.lua:1: bad argument #1 to 'evaluate' (number expected, got string)");
  EXPECT_EQ(f.error("c.evaluate(5, 0.5)"), "t.lua:1: bad argument #1 to 'evaluate' (curve expected, got number)");
  EXPECT_EQ(f.error("c:step(5, 0.5)"), "t.lua:1: bad argument #1 to 'step' (table expected, got number)");
  EXPECT_EQ(f.error("return c.degree"), "t.lua:1: curve has no field 'degree'");
  EXPECT_EQ(f.error("meshedit.patch({{1, 2, 3}})"),
            "t.lua:1: bad argument #1 to 'patch' (a patch needs 16 control points (4 rows of 4), got 1)");
  EXPECT_EQ(f.error("local t = {} for i = 1, 16 do t[i] = {i, 0, 0} end t[16] = true meshedit.patch(t)"),
            "t.lua:1: bad argument #1 to 'patch' (point 16 must be a vec3 or a table {x, y, z} of numbers, got "
            "boolean)");
  EXPECT_EQ(f.error("local t = {} for i = 1, 16 do t[i] = {i, 0, 0} end meshedit.patch(t):evaluate(0.5)"),
            "t.lua:1: bad argument #2 to 'evaluate' (number expected, got no value)");
  EXPECT_EQ(f.error("meshedit.load_curve('/nonexistent/x.bzc')").rfind("t.lua:1: /nonexistent/x.bzc", 0), 0u)
      << f.error("meshedit.load_curve('/nonexistent/x.bzc')");
  // Through pcall the module function is named with its module.
  EXPECT_EQ(f.run("return pcall(meshedit.curve, {})"),
            (Strings{"false", "bad argument #1 to 'meshedit.curve' (a curve needs at least one control point)"}));
}

TEST(BezierBindings, OpeningTwiceIsHarmlessAndPushHelpersRoundTrip) {
  Fixture f;
  lua_State* L = f.lua.state();
  lua_getglobal(L, "meshedit");
  open_bezier_bindings(L);
  lua_pop(L, 1);
  f.run(std::string("c = ") + kCubicLua);
  EXPECT_EQ(f.run("return tostring(c:evaluate(0.5))"),
            Strings{format_position(evaluate_curve(std::span<const glm::dvec3>(kCubic), 0.5))});
  push_curve(L, kCubic);
  const std::vector<glm::dvec3>* points = to_curve(L, -1);
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(*points, kCubic);
  EXPECT_EQ(to_patch(L, -1), nullptr);
  BezierPatch patch;
  patch.points[5] = {1, 2, 3};
  push_patch(L, patch);
  ASSERT_NE(to_patch(L, -1), nullptr);
  EXPECT_EQ(to_patch(L, -1)->points[5], glm::dvec3(1, 2, 3));
  EXPECT_EQ(to_curve(L, -1), nullptr);
  lua_pop(L, 2);
}

}  // namespace
}  // namespace meshedit
