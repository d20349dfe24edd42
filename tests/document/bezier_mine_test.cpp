// "Mine" in the curve and patch views (bezier_mine.h): with the correct solutions (tests/exercise/solutions) every
// level and the probe point are the reference's bit for bit; a student file with a wrong point stops at that level
// and names the level, the point and both values; a Lua error and a syntax error keep curve.lua:LINE; levels run
// only as far as E shows them and are not run again while nothing changes; a saved file is reloaded. The views that
// draw it are tested in ui/bezier_mine_views_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/bezier.h"
#include "core/value_format.h"
#include "document/bezier_mine.h"
#include "document/bezier_mine_test_support.h"
#include "document/student_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using glm::dvec2;
using glm::dvec3;
namespace fs = std::filesystem;

using namespace document_testing;
using testing::read_text;

std::vector<dvec3> reference_level(int k, double t = 0.5) {
  std::vector<dvec3> points;
  for (const dvec2& p : kCubic) points.emplace_back(p.x, p.y, 0.0);
  return de_casteljau_levels(std::span<const dvec3>(points), t)[size_t(k)];
}

void expect_level(const std::vector<dvec3>& actual, const std::vector<dvec3>& expected, int k) {
  ASSERT_EQ(actual.size(), expected.size()) << "level " << k;
  for (size_t i = 0; i < actual.size(); ++i) EXPECT_EQ(format_position(actual[i]), format_position(expected[i])) << k;
}

// ---- the curve -------------------------------------------------------------------------------------------

TEST(BezierMine, TheSolutionsLevelsAreTheReferencesAndRunOnlyAsFarAsShown) {
  BezierMine mine(solutions());
  const CurveMineLevels& none = mine.curve_levels(kCubic, 0.5, 0);
  ASSERT_EQ(none.levels.size(), 1u);  // level 0 only: E has not been pressed, nothing ran
  EXPECT_EQ(none.message, "press E: each level comes from your evaluate_step");
  EXPECT_EQ(none.levels[0][1], dvec3(0.3, 0.6, 0.0));

  const CurveMineLevels& one = mine.curve_levels(kCubic, 0.5, 1);
  ASSERT_EQ(one.levels.size(), 2u);
  EXPECT_EQ(one.levels[1][0], dvec3(0.25, 0.475, 0.0));
  EXPECT_TRUE(testing::near(one.levels[1][2], dvec3(0.85, 0.6, 0.0), 1e-15));  // 0.85 to the last bit, not quite
  expect_level(one.levels[1], reference_level(1), 1);
  EXPECT_EQ(one.message, "level 1 is the reference's");

  const CurveMineLevels& all = mine.curve_levels(kCubic, 0.5, 3);
  ASSERT_EQ(all.levels.size(), 4u);
  for (int k = 1; k <= 3; ++k) expect_level(all.levels[size_t(k)], reference_level(k), k);
  EXPECT_TRUE(testing::near(all.levels[3][0], evaluate_curve(std::span<const dvec3>(reference_level(0)), 0.5), 1e-15));
  EXPECT_TRUE(all.complete());
  EXPECT_FALSE(all.failed());
  EXPECT_EQ(all.message, "levels 1 to 3 are the reference's: your curve point is right");

  // E wraps to level 0: what is on screen is what the message speaks of.
  EXPECT_EQ(mine.curve_levels(kCubic, 0.5, 0).message, "press E: each level comes from your evaluate_step");

  // Another t: levels from scratch, at the new t.
  const CurveMineLevels& moved = mine.curve_levels(kCubic, 0.25, 2);
  ASSERT_EQ(moved.levels.size(), 3u);
  expect_level(moved.levels[2], reference_level(2, 0.25), 2);
  EXPECT_EQ(mine.curve_file().loads(), 1u);
}

TEST(BezierMine, AWrongPointStopsAtItsLevelAndNamesLevelPointAndBothValues) {
  const fs::path folder = testing::scratch_dir();
  // The second point of every level is pushed up by 0.25.
  write_file(folder, "curve.lua",
             solution_with("curve.lua", kStepLine,
                           kStepLine + "    if i == 2 then result[i] = result[i] + meshedit.vec3(0, 0.25, 0) end\n"));
  BezierMine mine(folder);
  const CurveMineLevels& got = mine.curve_levels(kCubic, 0.5, 3);
  ASSERT_EQ(got.levels.size(), 2u) << "nothing is computed past the level that differs";
  EXPECT_EQ(got.failed_level, 1);
  EXPECT_TRUE(got.error.empty());
  EXPECT_EQ(got.wrong_point, 1);
  const std::vector<dvec3> want = reference_level(1);
  EXPECT_EQ(got.reference_point, want[1]);
  EXPECT_EQ(got.mine_point, want[1] + dvec3(0.0, 0.25, 0.0));
  EXPECT_EQ(got.levels[1][1], got.mine_point);  // the level drawn is yours, wrong point included
  EXPECT_EQ(got.levels[1][0], want[0]);
  expect_level(got.reference_level, want, 1);
  EXPECT_EQ(got.message, "level 1, point 2 of 3: yours is " + format_position(want[1] + dvec3(0.0, 0.25, 0.0)) +
                             ", the reference's is (0.55, 0.675, 0)");
  ASSERT_FALSE(got.details.empty());
  EXPECT_EQ(got.details[0], "point 2 is " + format_position(got.mine_point) + ", expected (0.55, 0.675, 0)");
  EXPECT_FALSE(got.complete());
}

TEST(BezierMine, AMistakeInALaterLevelIsShownWhenEReachesIt) {
  const fs::path folder = testing::scratch_dir();
  // Wrong only on 3 points (level 2 of a cubic): the first point is copied instead of interpolated.
  write_file(folder, "curve.lua",
             solution_with("curve.lua", kStepLine,
                           kStepLine + "    if #points == 3 and i == 1 then result[i] = points[i] end\n"));
  BezierMine mine(folder);
  const CurveMineLevels& first = mine.curve_levels(kCubic, 0.5, 1);
  EXPECT_FALSE(first.failed());
  EXPECT_EQ(first.message, "level 1 is the reference's");

  const CurveMineLevels& second = mine.curve_levels(kCubic, 0.5, 2);
  EXPECT_EQ(second.failed_level, 2);
  EXPECT_EQ(second.wrong_point, 0);
  EXPECT_EQ(second.mine_point, dvec3(0.25, 0.475, 0.0));  // level 1's first point, copied
  EXPECT_EQ(second.reference_point, reference_level(2)[0]);
  EXPECT_EQ(second.reference_point, dvec3(0.4, 0.575, 0.0));
  EXPECT_EQ(second.message, "level 2, point 1 of 2: yours is (0.25, 0.475, 0), the reference's is (0.4, 0.575, 0)");
  // Back at level 1 (E wrapped round, then once more), level 1 alone is spoken of.
  EXPECT_EQ(mine.curve_levels(kCubic, 0.5, 1).message, "level 1 is the reference's");
}

TEST(BezierMine, AMissingPointIsNamedByTheChecker) {
  const fs::path folder = testing::scratch_dir();
  write_file(folder, "curve.lua", solution_with("curve.lua", "for i = 1, #points - 1 do", "for i = 1, #points - 2 do"));
  BezierMine mine(folder);
  const CurveMineLevels& got = mine.curve_levels(kCubic, 0.5, 1);
  EXPECT_EQ(got.failed_level, 1);
  EXPECT_EQ(got.wrong_point, -1);
  ASSERT_EQ(got.levels.size(), 2u);
  EXPECT_EQ(got.levels[1].size(), 2u);
  EXPECT_EQ(got.message,
            "level 1: point 3 of the step is missing (got 2 points, expected 3): n points give n - 1, so "
            "the loop runs i = 1, ..., n - 1");
}

TEST(BezierMine, ALuaErrorKeepsFileAndLineAndNothingThrows) {
  const fs::path folder = testing::scratch_dir();
  write_file(folder, "curve.lua",
             "function evaluate_step(points, t)\n"
             "  local result = {}\n"
             "  for i = 1, #points - 1 do\n"
             "    result[i] = (1 - t) * points[i] + t * points[i + 2]\n"
             "  end\n"
             "  return result\n"
             "end\n");
  BezierMine mine(folder);
  EXPECT_EQ(mine.curve_levels(kCubic, 0.5, 0).message, "press E: each level comes from your evaluate_step");
  const CurveMineLevels& got = mine.curve_levels(kCubic, 0.5, 1);
  EXPECT_EQ(got.failed_level, 1);
  EXPECT_EQ(got.levels.size(), 1u);
  EXPECT_EQ(got.error.rfind("curve.lua:4:", 0), 0u) << got.error;
  EXPECT_EQ(got.message, got.error + " (computing level 1)");
  expect_level(got.reference_level, reference_level(1), 1);

  // The template returns nil: an error the student sees at once, and the view goes on.
  BezierMine templates(default_student_folder());
  const CurveMineLevels& nil = templates.curve_levels(kCubic, 0.5, 1);
  EXPECT_EQ(nil.message, "evaluate_step returned nil; it must return a list of points (computing level 1)");
}

TEST(BezierMine, ASyntaxErrorIsShownBeforeAnyLevelAndTheFileIsNotReloadedEveryFrame) {
  const fs::path folder = testing::scratch_dir();
  write_file(folder, "curve.lua", "function evaluate_step(points, t)\n  return {\nend\n");
  BezierMine mine(folder);
  for (int frame = 0; frame < 5; ++frame) {
    const CurveMineLevels& got = mine.curve_levels(kCubic, 0.5, 0);
    EXPECT_TRUE(got.load_failed);
    EXPECT_EQ(got.message.rfind("curve.lua:3:", 0), 0u) << got.message;
  }
  EXPECT_EQ(mine.curve_file().loads(), 1u);

  // Saved fixed: reloaded on the next frame, levels from the new code.
  write_file(folder, "curve.lua", read_text(solutions() / "curve.lua"));
  const CurveMineLevels& fixed = mine.curve_levels(kCubic, 0.5, 3);
  EXPECT_EQ(mine.curve_file().loads(), 2u);
  EXPECT_FALSE(fixed.load_failed);
  EXPECT_TRUE(fixed.complete());
}

TEST(BezierMine, NothingRunsAgainWhileNothingChanges) {
  const fs::path folder = testing::scratch_dir();
  // A function that may run once per input: a second call for the same level would be an error.
  write_file(folder, "curve.lua",
             "local seen = {}\n"
             "function evaluate_step(points, t)\n"
             "  local key = #points .. ' ' .. t .. ' ' .. tostring(points[1])\n"
             "  if seen[key] then error('run twice on ' .. key) end\n"
             "  seen[key] = true\n"
             "  local result = {}\n"
             "  for i = 1, #points - 1 do result[i] = (1 - t) * points[i] + t * points[i + 1] end\n"
             "  return result\n"
             "end\n");
  BezierMine mine(folder);
  for (int frame = 0; frame < 4; ++frame) EXPECT_FALSE(mine.curve_levels(kCubic, 0.5, 3).failed()) << frame;
  EXPECT_TRUE(mine.curve().complete());
  // A point dragged: computed again (new inputs), still without a repeat.
  std::vector<dvec2> dragged = kCubic;
  dragged[0] = {0.1, 0.3};
  EXPECT_TRUE(mine.curve_levels(dragged, 0.5, 3).complete()) << mine.curve().message;
  // The same save again (new time): reloaded, so run again on a fresh `seen`.
  write_file(folder, "curve.lua", read_text(folder / "curve.lua"));
  EXPECT_TRUE(mine.curve_levels(dragged, 0.5, 3).complete()) << mine.curve().message;
  EXPECT_EQ(mine.curve_file().loads(), 2u);
}

TEST(BezierMine, AWrongFileSavedRightIsReloaded) {
  const fs::path folder = testing::scratch_dir();
  write_file(
      folder, "curve.lua",
      solution_with("curve.lua", "(1 - t) * points[i] + t * points[i + 1]", "t * points[i] + (1 - t) * points[i + 1]"));
  BezierMine mine(folder);
  const CurveMineLevels& swapped = mine.curve_levels(kCubic, 0.25, 1);
  EXPECT_EQ(swapped.failed_level, 1);
  ASSERT_FALSE(swapped.details.empty());
  EXPECT_EQ(swapped.details[0].rfind("the weights are swapped", 0), 0u) << swapped.details[0];
  write_file(folder, "curve.lua", read_text(solutions() / "curve.lua"));
  EXPECT_FALSE(mine.curve_levels(kCubic, 0.25, 1).failed());
  EXPECT_EQ(mine.curve().message, "level 1 is the reference's");
}

// ---- the patch probe -------------------------------------------------------------------------------------

TEST(BezierMine, TheSolutionsProbePointIsTheReferences) {
  BezierMine mine(solutions());
  const PatchMinePoint& got = mine.patch_point(hill(), 0.3, 0.8);
  EXPECT_TRUE(got.ran);
  EXPECT_TRUE(got.equal);
  EXPECT_EQ(got.mine, evaluate_patch(hill(), 0.3, 0.8));
  EXPECT_EQ(got.reference, evaluate_patch(hill(), 0.3, 0.8));
  EXPECT_EQ(got.message, "yours is the reference's P(0.3, 0.8) = " + format_position(got.reference));
  // x follows u along the rows, y follows v: (3 * 0.3, 3 * 0.8) on this hill.
  EXPECT_TRUE(testing::near(got.mine, dvec3(0.9, 2.4, got.mine.z), 1e-12));
}

// ---- the file --------------------------------------------------------------------------------------------

TEST(StudentFile, AMissingFileSaysSoAndLoadsOnceItExists) {
  const fs::path folder = testing::scratch_dir();
  StudentFile file(folder / "curve.lua");
  EXPECT_FALSE(file.ensure_loaded());
  EXPECT_EQ(file.error(), "cannot open " + (folder / "curve.lua").string());
  EXPECT_EQ(file.code(), nullptr);
  write_file(folder, "curve.lua", read_text(solutions() / "curve.lua"));
  EXPECT_TRUE(file.changed());
  EXPECT_TRUE(file.ensure_loaded());
  EXPECT_TRUE(file.error().empty());
  ASSERT_NE(file.code(), nullptr);
  EXPECT_TRUE(file.code()->defines(Exercise::CurveStep));
  EXPECT_FALSE(file.changed());
  const size_t loads = file.loads();
  EXPECT_TRUE(file.ensure_loaded());
  EXPECT_EQ(file.loads(), loads);
}

}  // namespace
}  // namespace meshedit
