// The expect functions: what each records, passing and failing, with the exact messages students read.
#include <gtest/gtest.h>

#include <string>

#include "grade_test_support.h"

namespace meshedit {
namespace {

// Runs `body` as a test's run function (with `student` and `expect`) and lists the checks it recorded.
std::string checks(const std::string& body) {
  auto suite = testing::suite_of("test{ name = 't', run = function(student, expect)\n" + body + "\nend }");
  const TestRun run = suite->run_test_here(0, testing::submission_of({}));
  std::string out;
  for (const auto& c : run.checks) out += std::string(c.passed ? "ok: " : "FAIL: ") + c.message + "\n";
  if (run.end != RunEnd::Completed) out += "END: " + run.error + "\n";
  if (run.fraction) out += "FRACTION: " + std::to_string(*run.fraction) + "\n";
  return out;
}

TEST(Expect, TruthAndNil) {
  EXPECT_EQ(checks("expect(1 == 1, 'callable') expect(nil) expect.truthy(false, 'flag')"),
            "ok: callable\nFAIL: expected a true value, got nil\nFAIL: flag: expected a true value, got false\n");
  EXPECT_EQ(
      checks(
          "expect.falsy(nil, 'a') expect.falsy(0, 'b') expect.is_nil(nil) expect.is_nil(meshedit.cube():edge(2), 'c')"),
      "ok: a\nFAIL: b: expected nil or false, got 0\nok: \nFAIL: c: expected nil, got e2\n");
}

TEST(Expect, EqualNamesTheFirstDifference) {
  EXPECT_EQ(checks("expect.equal(3, 3, 'n') expect.equal(3, 3.0) expect.equal('a', 'b', 's')"),
            "ok: n\nok: \nFAIL: s: expected \"b\", got \"a\"\n");
  EXPECT_EQ(checks("expect.equal({1, {x = 2}}, {1, {x = 3}}, 'deep') expect.equal({1, 2}, {1, 2, 3})"),
            "FAIL: deep: [2].x: expected 3, got 2\nFAIL: expected 3 items, got 2\n");
  EXPECT_EQ(checks("expect.equal({a = 1, b = 2}, {a = 1}, 'extra')"), "FAIL: extra: unexpected key \"b\"\n");
  EXPECT_EQ(checks("local m = meshedit.cube()\n"
                   "expect.equal(m:halfedge(3).next, m:halfedge(3).next, 'same handle')\n"
                   "expect.equal(m:edge(1), m:edge(2), 'other edge')\n"
                   "expect.equal(m:edge(1), m:copy():edge(1), 'other mesh')\n"
                   "expect.equal(m, m:copy(), 'mesh identity')\n"
                   "expect.equal(meshedit.vec3(1, 2, 3), {1, 2, 3}, 'points')"),
            "ok: same handle\nFAIL: other edge: expected e2, got e1\nFAIL: other mesh: expected e1, got e1\n"
            "FAIL: mesh identity: expected the same mesh, got another one\nok: points\n");
}

TEST(Expect, NearComparesNumbersPointsAndLists) {
  EXPECT_EQ(checks("expect.near(0.1 + 0.2, 0.3, 1e-12, 'sum') expect.near(1, 1.5, 0.1)"),
            "ok: sum\nFAIL: expected 1.5, got 1, off by 0.5 (tolerance 0.1)\n");
  EXPECT_EQ(checks("local v = meshedit.vec3\n"
                   "expect.near({v(0, 0, 0), v(1, 0, 0)}, {v(0, 0, 0), v(1, 0, 1e-9)}, 1e-6, 'points')\n"
                   "expect.near({v(0, 0, 0), v(0.25, 0, 0)}, {v(0, 0, 0), v(0.5, 0, 0)}, 1e-6, 'step')\n"
                   "expect.near({v(0, 0, 0)}, {v(0, 0, 0), v(1, 1, 1)}, 1e-6, 'dropped')\n"
                   "expect.near(nil, v(1, 2, 3), 1e-6, 'nothing')"),
            "ok: points\nFAIL: step: [2]: expected (0.5, 0, 0), got (0.25, 0, 0), 0.25 away (tolerance 1e-06)\n"
            "FAIL: dropped: expected 2 items, got 1\nFAIL: nothing: expected the point (1, 2, 3), got nil\n");
}

TEST(Expect, MeshChecksUseTheCore) {
  EXPECT_EQ(checks("local m = meshedit.cube()\n"
                   "expect.valid(m, 'fresh cube')\n"
                   "m:face(0).halfedge = m:face(1).halfedge\n"
                   "expect.valid(m, 'broken')\n"
                   "expect.valid(nil, 'no mesh')"),
            "ok: fresh cube: the mesh is valid\n"
            "FAIL: broken: the mesh is not valid: f0: f0.halfedge is h3, but h3.face is f1\n"
            "FAIL: no mesh: expected a mesh, got nil\n");
  EXPECT_EQ(checks("local m = meshedit.cube()\n"
                   "local r = m:copy()\n"
                   "expect.mesh_equal(m, r, 1e-9, 'copy')\n"
                   "expect.same_pointers(m, r, 0, 'copy')\n"
                   "m:vertex(2).position = {5, 5, 5}\n"
                   "expect.mesh_equal(m, r, nil, 'moved')\n"
                   "expect.counts(m, {vertices = 8, faces = 12, edges = 18, halfedges = 36, boundaries = 0}, 'cube')\n"
                   "expect.counts(m, {vertices = 9, faces = 11})"),
            "ok: copy: same mesh as the reference\nok: copy: same pointers as the reference\n"
            "FAIL: moved: your vertex v2 at (5, 5, 5) has no match in the reference; the nearest is reference v7 at "
            "(0.5, 0.5, 0.5), 7.794228634059948 away (already matched to your v7); reference vertex v2 at "
            "(-0.5, 0.5, -0.5) has no match in yours; the nearest is your v0 at (-0.5, -0.5, -0.5), 1 away (already "
            "matched to reference v0); 4 of your faces and 4 of the reference's touch a vertex without a match and "
            "were not compared; ... (4 in all)\n"
            "ok: cube: counts as expected\nFAIL: vertices: expected 9, got 8; faces: expected 11, got 12\n");
}

TEST(Expect, ScorePassAndFail) {
  EXPECT_EQ(checks("expect.pass('fine') expect.fail('wrong') expect.score(0.25) expect.score(0.5, 'half')"),
            "ok: fine\nFAIL: wrong\nFAIL: half\nFRACTION: 0.500000\n");
  EXPECT_EQ(checks("expect.score(2)"), "END: suite.lua:2: bad argument #1 to 'score' (must be between 0 and 1)\n");
}

TEST(Expect, ExerciseOfAnUnknownNameIsAnErrorAtTheSuitesLine) {
  EXPECT_EQ(checks("expect.exercise('flop', {}, nil, nil)"),
            "END: suite.lua:2: expect.exercise: no exercise is called 'flop'; the exercises are curve, patch, normals, "
            "flip, split, upsample\n");
}

}  // namespace
}  // namespace meshedit
