// Exercises defined in Lua on control points or a patch (scripted_exercise.h, takes = "points" / "patch"), on the
// shipped scripts/exercises/hodograph.lua and patch_normal.lua: their fields and fixtures; the correct solutions
// right on every fixture with the values the formulas give; each buggy fixture told its diagnosis first, then where
// the values differ; the comparison's words for lengths, nil and other values; the student's code in the exercises'
// sandbox and limits; a lesson's your_turn asking for them; and broken definitions named at their file:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/value_format.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/scripted_exercise.h"
#include "exercise/value_compare.h"
#include "lesson/lesson_headless.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

fs::path exercises() { return testing::source_dir() / "scripts" / "exercises"; }
fs::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }
fs::path buggy(const std::string& name) { return testing::source_dir() / "tests" / "grading" / "scripted" / name; }

Exercise hodograph_exercise() {
  static const Exercise id = register_scripted_exercise(ScriptedExercise::load(exercises() / "hodograph.lua"));
  return id;
}

Exercise patch_normal_exercise() {
  static const Exercise id = register_scripted_exercise(ScriptedExercise::load(exercises() / "patch_normal.lua"));
  return id;
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

// check_exercise of the student file `file` (copied as NAME.lua) on fixture `index` of `id`.
ExerciseReport check_fixture(Exercise id, const fs::path& file, size_t index, LuaLimits limits = {}) {
  const std::shared_ptr<const ScriptedExercise> definition = id.definition();
  const fs::path dir = testing::scratch_dir();
  fs::copy_file(file, dir / definition->info().file, fs::copy_options::overwrite_existing);
  auto code = load_student_file(dir / definition->info().file, limits);
  return check_exercise(*code, id, definition->input_of(definition->fixtures().at(index)));
}

// The message ScriptedExercise::load throws for a definition file holding `text`.
std::string load_error(const std::string& text) {
  const fs::path file = write(testing::scratch_dir(), "bad.lua", text);
  try {
    ScriptedExercise::load(file);
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "(it loaded)";
}

TEST(ValuesExercise, TheShippedDefinitionsLoadWithTheirFixtures) {
  const auto hodograph = ScriptedExercise::load(exercises() / "hodograph.lua");
  EXPECT_STREQ(hodograph->info().function, "hodograph");
  EXPECT_EQ(hodograph->input(), ScriptedExercise::Input::Points);
  EXPECT_TRUE(hodograph->takes_values());
  EXPECT_FALSE(hodograph->takes().has_value());
  ASSERT_EQ(hodograph->fixtures().size(), 5u);
  const ScriptedFixture& cubic = hodograph->fixtures()[0];
  EXPECT_EQ(cubic.name, "a cubic in the plane");
  EXPECT_EQ(cubic.points, 2.0);
  ASSERT_EQ(cubic.control.size(), 4u);
  EXPECT_EQ(cubic.control[1], glm::dvec3(1, 2, 0));  // {x, y}: z = 0
  EXPECT_EQ(hodograph->fixtures()[1].control[1], glm::dvec3(1, 1, 2));
  EXPECT_TRUE(cubic.args.empty());
  EXPECT_FALSE(cubic.mesh);

  const auto patch = ScriptedExercise::load(exercises() / "patch_normal.lua");
  EXPECT_EQ(patch->input(), ScriptedExercise::Input::Patch);
  ASSERT_EQ(patch->fixtures().size(), 4u);
  const ScriptedFixture& bump = patch->fixtures()[1];
  EXPECT_EQ(bump.patch.points[5], glm::dvec3(1, 1, 2));  // row 1, column 1
  EXPECT_EQ(bump.patch.points[3], glm::dvec3(3, 0, 0));  // row 0, column 3
  ASSERT_EQ(bump.args.size(), 2u);
  EXPECT_EQ(bump.args[0].kind, ExerciseValue::Kind::Number);
  EXPECT_EQ(bump.args[0].number, 0.3);
  EXPECT_EQ(bump.args[1].number, 0.7);
  EXPECT_EQ(patch->fixtures()[3].patch.points[4], glm::dvec3(0.3, 1, 0));
}

TEST(ValuesExercise, ARegisteredExerciseOnValuesIsNoMeshExercise) {
  const Exercise id = hodograph_exercise();
  EXPECT_EQ(find_exercise("hodograph"), id);
  EXPECT_FALSE(is_mesh_exercise(id));
  const ScriptedExercise& definition = *id.definition();
  EXPECT_EQ(definition.input_of(definition.fixtures()[0]).describe(id), "4 control points");
  const Exercise patch = patch_normal_exercise();
  const ScriptedExercise& normal = *patch.definition();
  EXPECT_EQ(normal.input_of(normal.fixtures()[1]).describe(patch), "a patch of 16 control points, then 0.3, 0.7");
}

TEST(ValuesExercise, TheHodographSolutionIsRightOnEveryFixture) {
  const Exercise id = hodograph_exercise();
  for (size_t i = 0; i < id.definition()->fixtures().size(); ++i) {
    const ExerciseReport report = check_fixture(id, solutions() / "hodograph.lua", i);
    EXPECT_TRUE(report.equal) << id.definition()->fixtures()[i].name << ": " << report.summary();
    EXPECT_TRUE(report.identical) << report.summary();
  }
  // The cubic's hodograph: 3 (P[i+1] - P[i]).
  const ExerciseReport cubic = check_fixture(id, solutions() / "hodograph.lua", 0);
  EXPECT_EQ(cubic.mine.returned, "a list of 3 points");
  ASSERT_EQ(cubic.mine.value.items.size(), 3u);
  EXPECT_EQ(cubic.mine.value.items[0].point, glm::dvec3(3, 6, 0));
  EXPECT_EQ(cubic.mine.value.items[1].point, glm::dvec3(6, 3, 0));
  EXPECT_EQ(cubic.mine.value.items[2].point, glm::dvec3(3, -9, 0));
  // A single point: no control points.
  const ExerciseReport single = check_fixture(id, solutions() / "hodograph.lua", 4);
  EXPECT_EQ(single.reference.returned, "an empty list");
  EXPECT_TRUE(single.equal);
}

TEST(ValuesExercise, TheForgottenFactorIsNamedFirstThenThePoints) {
  const ExerciseReport report = check_fixture(hodograph_exercise(), buggy("hodograph_no_factor.lua"), 0);
  EXPECT_FALSE(report.equal);
  ASSERT_EQ(report.differences.size(), 4u);
  EXPECT_EQ(report.differences[0],
            "your points are the differences P[i+1] - P[i] without the factor n: a curve of degree n = 3 (4 control "
            "points) has the derivative n * (P[i+1] - P[i]); multiply each by 3");
  EXPECT_EQ(report.differences[1], "point 1 of 3 differs: yours (1, 2, 0), the reference's (3, 6, 0)");
  EXPECT_EQ(report.differences[3], "point 3 of 3 differs: yours (1, -3, 0), the reference's (3, -9, 0)");
  EXPECT_EQ(report.total_differences, 4u);
  // A line's factor is 1: the same bug is right there.
  EXPECT_TRUE(check_fixture(hodograph_exercise(), buggy("hodograph_no_factor.lua"), 3).equal);
}

TEST(ValuesExercise, TheReversedDifferenceIsNamed) {
  const ExerciseReport report = check_fixture(hodograph_exercise(), buggy("hodograph_reversed.lua"), 1);
  EXPECT_FALSE(report.equal);
  ASSERT_GE(report.differences.size(), 2u);
  EXPECT_EQ(report.differences[0],
            "your points are n * (P[i] - P[i+1]): the difference is taken backwards, so C' points the wrong way along "
            "the curve; take P[i+1] - P[i] (the later point minus the earlier one)");
  EXPECT_EQ(report.differences[1], "point 1 of 2 differs: yours (-2, -2, -4), the reference's (2, 2, 4)");
}

TEST(ValuesExercise, ThePatchNormalSolutionIsRightOnEveryFixture) {
  const Exercise id = patch_normal_exercise();
  for (size_t i = 0; i < id.definition()->fixtures().size(); ++i) {
    const ExerciseReport report = check_fixture(id, solutions() / "patch_normal.lua", i);
    EXPECT_TRUE(report.equal) << id.definition()->fixtures()[i].name << ": " << report.summary();
    ASSERT_EQ(report.mine.value.kind, ExerciseValue::Kind::Point);
    EXPECT_NEAR(glm::length(report.mine.value.point), 1.0, 1e-12);
  }
  const ExerciseReport flat = check_fixture(id, solutions() / "patch_normal.lua", 0);
  EXPECT_EQ(flat.reference.value.point, glm::dvec3(0, 0, 1));
  EXPECT_EQ(flat.mine.returned, "(0, 0, 1)");
  // The bump at (0.3, 0.7) leans away from its top: its normal is not straight up.
  const ExerciseReport bump = check_fixture(id, solutions() / "patch_normal.lua", 1);
  EXPECT_LT(bump.reference.value.point.z, 0.99);
  EXPECT_GT(bump.reference.value.point.z, 0.0);
}

TEST(ValuesExercise, TheUnnormalisedNormalIsNamed) {
  const ExerciseReport report = check_fixture(patch_normal_exercise(), buggy("patch_normal_unnormalised.lua"), 0);
  EXPECT_FALSE(report.equal);
  ASSERT_EQ(report.differences.size(), 2u);
  EXPECT_EQ(report.differences[0],
            "your normal has length 9 (it is S_u x S_v itself); a normal is a unit vector: divide the cross product by "
            "its length (n / n:length(), or n:normalized())");
  EXPECT_EQ(report.differences[1], "yours returned (0, 0, 9), the reference (0, 0, 1) (8 apart)");
}

TEST(ValuesExercise, TheFlippedCrossProductIsNamed) {
  const ExerciseReport report = check_fixture(patch_normal_exercise(), buggy("patch_normal_flipped.lua"), 0);
  EXPECT_FALSE(report.equal);
  ASSERT_EQ(report.differences.size(), 2u);
  EXPECT_EQ(report.differences[0],
            "your normal (0, 0, -1) points the other way: it is along S_v x S_u; the normal is S_u:cross(S_v), the u "
            "tangent first");
  EXPECT_EQ(report.differences[1], "yours returned (0, 0, -1), the reference (0, 0, 1) (2 apart)");
}

TEST(ValuesExercise, TheTemplatesDefineTheirFunctionAndReturnNil) {
  const fs::path student = testing::source_dir() / "scripts" / "student";
  ExerciseReport report = check_fixture(hodograph_exercise(), student / "hodograph.lua", 0);
  EXPECT_FALSE(report.equal);
  EXPECT_EQ(report.differences, std::vector<std::string>{"yours returned nil, the reference a list of 3 points"});
  report = check_fixture(patch_normal_exercise(), student / "patch_normal.lua", 0);
  EXPECT_EQ(report.differences, std::vector<std::string>{"yours returned nil, the reference (0, 0, 1)"});
}

TEST(ValuesExercise, TheComparisonSaysWhereTheValuesDiffer) {
  const ExerciseValue three = ExerciseValue::of_points({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  const ExerciseValue four = ExerciseValue::of_points({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
  ValueComparison c = compare_values(four, three, 1e-9, 20);
  EXPECT_FALSE(c.equal);
  EXPECT_EQ(c.differences, std::vector<std::string>{"yours returned 4 points, the reference 3"});
  c = compare_values(ExerciseValue{}, three, 1e-9, 20);
  EXPECT_EQ(c.differences, std::vector<std::string>{"yours returned nil, the reference a list of 3 points"});
  c = compare_values(ExerciseValue::of_number(0.5), ExerciseValue::of_number(0.25), 1e-9, 20);
  EXPECT_EQ(c.differences, std::vector<std::string>{"yours returned 0.5, the reference 0.25 (0.25 apart)"});
  // Lists of lists: named by where they are.
  const ExerciseValue mine = ExerciseValue::of_list(
      {ExerciseValue::of_points({{1, 2, 0}}), ExerciseValue::of_list({ExerciseValue::of_number(1)})});
  const ExerciseValue reference =
      ExerciseValue::of_list({ExerciseValue::of_points({{1.5, 2, 0}}),
                              ExerciseValue::of_list({ExerciseValue::of_number(1), ExerciseValue::of_number(2)})});
  c = compare_values(mine, reference, 1e-9, 20);
  EXPECT_EQ(c.differences,
            (std::vector<std::string>{"list 1 of 2, point 1 of 1 differs: yours (1, 2, 0), the reference's (1.5, 2, 0)",
                                      "list 2 of 2: yours has 1 number, the reference's 2"}));
  // Within the tolerance: equal, not identical; a list of numbers compares with a point.
  c = compare_values(ExerciseValue::of_point({1, 2, 1e-12}), ExerciseValue::of_point({1, 2, 0}), 1e-9, 20);
  EXPECT_TRUE(c.equal);
  EXPECT_FALSE(c.identical);
  EXPECT_DOUBLE_EQ(c.worst, 1e-12);
  c = compare_values(ExerciseValue::of_list({ExerciseValue::of_number(1), ExerciseValue::of_number(2)}),
                     ExerciseValue::of_point({1, 2, 0}), 1e-9, 20);
  EXPECT_TRUE(c.equal);
}

TEST(ValuesExercise, WhatTheStudentReturnsIsReadAsAValue) {
  const Exercise id = hodograph_exercise();
  const fs::path dir = testing::scratch_dir();
  auto check = [&](const std::string& body) {
    write(dir, "hodograph.lua", "function hodograph(points)\n" + body + "\nend\n");
    auto code = load_student_file(dir / "hodograph.lua");
    const ScriptedExercise& definition = *id.definition();
    return check_exercise(*code, id, definition.input_of(definition.fixtures()[0]));
  };
  ExerciseReport report = check("  return nil");
  ASSERT_FALSE(report.differences.empty());
  EXPECT_EQ(report.differences.back(), "yours returned nil, the reference a list of 3 points");
  report = check("  return 'three'");
  EXPECT_EQ(report.differences.back(), "yours returned a string, the reference a list of 3 points");
  report = check("  return { points[1], 'x', points[2] }");
  EXPECT_EQ(report.differences.back(), "point 3 of 3 differs: yours (1, 2, 0), the reference's (3, -9, 0)");
  EXPECT_EQ(report.differences[report.differences.size() - 2],
            "point 2 of 3 differs: yours is a string, the reference's (6, 3, 0)");
  // Plain tables {x, y, z} are points too; changing the list it was given changes nothing of the reference's.
  report = check(
      "  local n, out = #points - 1, {}\n  for i = 1, n do local d = n * (points[i + 1] - points[i]); "
      "out[i] = {d.x, d.y, d.z} end\n  points[1] = nil\n  return out");
  EXPECT_TRUE(report.equal) << report.summary();
}

TEST(ValuesExercise, TheStudentsCodeRunsInTheExercisesSandboxAndLimits) {
  const Exercise id = hodograph_exercise();
  const fs::path dir = testing::scratch_dir();
  const ScriptedExercise& definition = *id.definition();
  write(dir, "hodograph.lua", "function hodograph(points)\n  return meshedit.curve(points):levels(0.5)\nend\n");
  auto hidden = load_student_file(dir / "hodograph.lua");
  ExerciseReport report = check_exercise(*hidden, id, definition.input_of(definition.fixtures()[0]));
  EXPECT_FALSE(report.equal);
  EXPECT_NE(report.mine.error.find("hodograph.lua:2: meshedit.curve is hidden from your code"), std::string::npos)
      << report.mine.error;

  write(dir, "hodograph.lua", "function hodograph(points)\n  while true do end\nend\n");
  LuaLimits limits;
  limits.instructions = 200000;
  auto runaway = load_student_file(dir / "hodograph.lua", limits);
  report = check_exercise(*runaway, id, definition.input_of(definition.fixtures()[0]));
  EXPECT_FALSE(report.equal);
  EXPECT_NE(report.mine.limit, ScriptError::Limit::None);
  ASSERT_EQ(report.differences.size(), 2u);
  EXPECT_EQ(report.differences[1], definition.hint());
}

TEST(ValuesExercise, ALessonsYourTurnAsksForIt) {
  hodograph_exercise();
  patch_normal_exercise();
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = write(dir, "lesson.lua", R"lua(lesson { title = "Derivatives" }
step("Your turn", function()
  your_turn { exercise = "hodograph", control = { {0, 0}, {1, 2}, {3, 3}, {4, 0} } }
  your_turn { exercise = "patch_normal", patch = meshedit.patch({
    {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0, 1, 0}, {1, 1, 1}, {2, 1, 1}, {3, 1, 0},
    {0, 2, 0}, {1, 2, 1}, {2, 2, 1}, {3, 2, 0}, {0, 3, 0}, {1, 3, 0}, {2, 3, 0}, {3, 3, 0} }), args = { 0.5, 0.5 } }
  say "right"
end)
)lua");
  const fs::path right =
      write(dir, "right.lua", "return { [1] = { {your_turn = \"right\"}, {your_turn = \"right\"} } }\n");
  const fs::path hodograph_only = write(dir, "hodograph_lesson.lua", R"lua(lesson { title = "Hodograph" }
step("Your turn", function()
  your_turn { exercise = "hodograph", control = { {0, 0}, {1, 2}, {3, 3}, {4, 0} } }
  say "right"
end)
)lua");
  std::ostringstream out;
  HeadlessOutcome outcome = run_lesson_headless(lesson, right, out, LessonRunner::default_limits(), solutions());
  EXPECT_EQ(outcome.failure, "") << out.str();
  EXPECT_NE(out.str().find("  > your turn hodograph.lua: right"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("  > your turn patch_normal.lua: right"), std::string::npos) << out.str();

  fs::create_directories(dir / "buggy");
  fs::copy_file(buggy("hodograph_no_factor.lua"), dir / "buggy" / "hodograph.lua");
  const fs::path wrong =
      write(dir, "wrong.lua", "return { [1] = { {your_turn = \"wrong\", feedback = \"without the factor n\"} } }\n");
  std::ostringstream out2;
  outcome = run_lesson_headless(hodograph_only, wrong, out2, LessonRunner::default_limits(), dir / "buggy");
  EXPECT_EQ(outcome.failure, "") << out2.str();
  EXPECT_NE(out2.str().find("  > your turn hodograph.lua: wrong: your points are the differences P[i+1] - P[i] "
                            "without the factor n"),
            std::string::npos)
      << out2.str();
}

TEST(ValuesExercise, ABrokenDefinitionIsNamedAtItsLine) {
  const std::string head = R"lua(exercise {
  name = "minimal_values", file = "minimal.lua", call = "do_it",
  reference = function(points) return points end,
)lua";
  EXPECT_EQ(load_error(head + "  takes = \"point\" }\n"),
            "bad.lua:1: exercise: takes must be vertex, edge, face, halfedge, mesh, points or patch, got 'point'");
  EXPECT_EQ(load_error(head + "  takes = \"points\", fixtures = { { control = { {0, 0}, \"p\" } } } }\n"),
            "bad.lua:1: exercise: fixtures[1].control point 2 must be a point {x, y} or {x, y, z}, got string");
  EXPECT_EQ(load_error(head + "  takes = \"points\", fixtures = { { name = \"none\" } } }\n"),
            "bad.lua:1: exercise: fixtures[1].control must be a list of points like {{0, 0}, {1, 2}}, got nil");
  EXPECT_EQ(
      load_error(head + "  takes = \"points\", fixtures = { { control = {{0, 0}}, mesh = meshedit.cube() } } }\n"),
      "bad.lua:1: exercise: fixtures[1]: unknown field 'mesh' (fields: name, control, args, points)");
  EXPECT_EQ(load_error(head + "  takes = \"points\", fixtures = { { control = {{0, 0}}, args = { 1, \"t\" } } } }\n"),
            "bad.lua:1: exercise: fixtures[1].args[2] must be a number, a point or a list of them, got a string");
  EXPECT_EQ(load_error(head + "  takes = \"points\", fixtures = { { control = {{0, 0}}, points = 0 } } }\n"),
            "bad.lua:1: exercise: fixtures[1].points must be a number above 0 (the test's score), got number");
  EXPECT_EQ(load_error(head + "  takes = \"patch\", fixtures = { { patch = { {0, 0}, {1, 0} } } } }\n"),
            "bad.lua:1: exercise: fixtures[1].patch must be 16 points row by row, 4 rows of 4 points, or "
            "meshedit.patch(...), got 2 points");
  EXPECT_EQ(
      load_error(head + "  takes = \"patch\", fixtures = { { patch = { {{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {{0, 1}}, {}, "
                        "{} } } } }\n"),
      "bad.lua:1: exercise: fixtures[1].patch row 2 must hold 4 points, got 1");
  EXPECT_EQ(load_error(head + "  takes = \"points\", tolerance = -1 }\n"),
            "bad.lua:1: exercise: tolerance must be a number of 0 or more, got number");
  EXPECT_EQ(load_error(head + "  takes = \"mesh\", tolerance = 0.1 }\n"),
            "bad.lua:1: exercise: tolerance is for exercises that take points or a patch");
}

TEST(ValuesExercise, AToleranceFieldDecidesWhatIsClose) {
  const fs::path dir = testing::scratch_dir();
  const fs::path file = write(dir, "rounded.lua", R"lua(exercise {
  name = "rounded_middle", file = "rounded.lua", call = "middle", takes = "points", tolerance = 0.01,
  reference = function(points, t) return points[1] * (1 - t) + points[#points] * t end,
  fixtures = { { name = "a segment", control = { {0, 0}, {1, 1} }, args = { 0.5 } } },
}
)lua");
  const Exercise id = register_scripted_exercise(ScriptedExercise::load(file));
  const ScriptedExercise& definition = *id.definition();
  EXPECT_EQ(definition.tolerance(definition.input_of(definition.fixtures()[0])), 0.01);
  write(dir, "rounded.lua", "function middle(points, t)\n  return meshedit.vec3(0.505, 0.5, 0)\nend\n");
  auto close = load_student_file(dir / "rounded.lua");
  ExerciseReport report = check_exercise(*close, id, definition.input_of(definition.fixtures()[0]));
  EXPECT_TRUE(report.equal) << report.summary();
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_EQ(report.notes[0], "your values differ from the reference's by at most " + format_number(0.505 - 0.5) +
                                 " (rounding; accepted)");
  write(dir, "rounded.lua", "function middle(points, t)\n  return meshedit.vec3(0.52, 0.5, 0)\nend\n");
  auto far = load_student_file(dir / "rounded.lua");
  report = check_exercise(*far, id, definition.input_of(definition.fixtures()[0]));
  EXPECT_FALSE(report.equal);
  EXPECT_EQ(report.summary(), "different: yours returned (0.52, 0.5, 0), the reference (0.5, 0.5, 0) (" +
                                  format_number(0.52 - 0.5) + " apart)");
}

TEST(ValuesExercise, AReferenceStoppedByALimitSaysWhichLimit) {
  const fs::path file = write(testing::scratch_dir(), "greedy.lua", R"lua(exercise {
  name = "greedy_reference", file = "greedy.lua", call = "greedy", takes = "points",
  reference = function(points) return #string.rep("x", 1 << 30) end,
  fixtures = { { name = "one point", control = { {0, 0} } } },
}
)lua");
  const Exercise id = register_scripted_exercise(ScriptedExercise::load(file));
  const ScriptedExercise& definition = *id.definition();
  const ExerciseOutcome outcome = definition.run_reference(definition.input_of(definition.fixtures()[0]));
  EXPECT_FALSE(outcome.ran);
  EXPECT_EQ(outcome.limit, ScriptError::Limit::Memory);
  EXPECT_FALSE(outcome.out_of_memory) << "the cap is the definition's limit, not the machine running out";
  EXPECT_EQ(outcome.error.rfind("the exercise's reference failed: ", 0), 0u) << outcome.error;
  EXPECT_NE(outcome.error.find("memory limit exceeded (512 MB)"), std::string::npos) << outcome.error;
}

}  // namespace
}  // namespace meshedit
