// QualityGovernor (render/quality_governor.h): slow frames drop multisampling, the wireframe and the back sides in
// that order; it comes back up only with clear room, does not flicker, passes over single spikes and the frame that
// opened the mesh, and leaves alone what the user chose (the wireframe) or what would change nothing.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "render/quality_governor.h"

namespace meshedit {
namespace {

// A view whose frame costs a fixed time per level (0 full .. 3 cheapest): each frame is drawn at the governor's level
// and its time fed back, as the window does. Returns the levels frame by frame ("0001112...").
std::string run(QualityGovernor& governor, const std::array<double, kQualitySteps + 1>& cost_ms, int frames) {
  std::string levels;
  for (int i = 0; i < frames; ++i) {
    const int level = governor.level();
    levels += char('0' + level);
    governor.measured(cost_ms[size_t(level)]);
  }
  return levels;
}

int moves(const std::string& levels) {
  int count = 0;
  for (size_t i = 1; i < levels.size(); ++i) count += levels[i] != levels[i - 1];
  return count;
}

QualityGovernor started_at(int level) {
  QualityGovernor governor;
  governor.reset(level);
  return governor;
}

TEST(QualityGovernor, SlowFramesDropMultisamplingThenTheWireframeThenTheBackSides) {
  QualityGovernor governor = started_at(0);
  // The first frame after reset is the one that opened the mesh: not counted. Then three slow frames per step.
  EXPECT_EQ(run(governor, {80, 80, 80, 80}, 12), "000011122233");
  EXPECT_TRUE(governor.drops(QualityStep::Multisampling));
  EXPECT_TRUE(governor.drops(QualityStep::Wireframe));
  EXPECT_TRUE(governor.drops(QualityStep::BackSides));
  EXPECT_DOUBLE_EQ(governor.slow_ms(), 80.0);

  QualityGovernor partly = started_at(0);
  run(partly, {80, 80, 80, 80}, 4);
  EXPECT_TRUE(partly.drops(QualityStep::Multisampling));
  EXPECT_FALSE(partly.drops(QualityStep::Wireframe));
  EXPECT_FALSE(partly.drops(QualityStep::BackSides));
}

TEST(QualityGovernor, StopsAtTheFirstLevelUnderTheThresholdAndStaysThereInTheBand) {
  // 62 ms at full quality, 31 without multisampling: 31 is under 40 (no further down) and, with the ratio it measured
  // (62 / 31 = 2), predicts 62 at full quality (not under 25): it stays, never flickering.
  QualityGovernor governor = started_at(0);
  const std::string levels = run(governor, {62, 31, 18, 12}, 300);
  EXPECT_EQ(governor.level(), 1);
  EXPECT_EQ(moves(levels), 1) << levels;
  EXPECT_DOUBLE_EQ(governor.ratio(QualityStep::Multisampling), 2.0);
}

TEST(QualityGovernor, ComesBackUpWhenThePredictedCostIsClearlyUnderTheUpThreshold) {
  // Started at the cheapest level (a large mesh's guess) on a fast machine: each step back is predicted at 1.4 times
  // the frame (the default ratio) and taken while that is under 25 ms, up to full quality.
  QualityGovernor fast = started_at(kQualitySteps);
  const std::string levels = run(fast, {8, 6, 5, 4}, 40);
  EXPECT_EQ(fast.level(), 0) << levels;
  EXPECT_FALSE(fast.drops_anything());
  EXPECT_EQ(moves(levels), 3) << levels;

  // Frames of 18 ms at the cheapest level predict 25.2 with the back sides: not under 25, nothing moves.
  QualityGovernor band = started_at(kQualitySteps);
  EXPECT_EQ(moves(run(band, {50, 40, 26, 18}, 200)), 0);
  EXPECT_EQ(band.level(), kQualitySteps);
}

TEST(QualityGovernor, AStepUpThatTurnsOutSlowComesBackOnceAndIsNotTriedAgain) {
  // Without multisampling 12 ms, predicted 16.8 with it (the default ratio), but it really costs 45: the governor
  // tries, measures, returns after three frames, and knows the ratio (45 / 12) from then on.
  QualityGovernor governor = started_at(1);
  const std::string levels = run(governor, {45, 12, 8, 6}, 300);
  EXPECT_EQ(governor.level(), 1);
  EXPECT_EQ(moves(levels), 2) << levels;
  EXPECT_NEAR(governor.ratio(QualityStep::Multisampling), 45.0 / 12.0, 1e-9);
}

TEST(QualityGovernor, RecoversWhenFramesGetCheaperAndDropsAgainWhenTheyGetDearer) {
  QualityGovernor governor = started_at(0);
  run(governor, {90, 60, 45, 30}, 40);
  EXPECT_EQ(governor.level(), 3);
  // The view got cheaper (zoomed out, a smaller window): back to full quality.
  run(governor, {20, 10, 7, 5}, 60);
  EXPECT_EQ(governor.level(), 0);
  run(governor, {90, 60, 45, 30}, 40);
  EXPECT_EQ(governor.level(), 3);
}

TEST(QualityGovernor, SingleSpikesAndTheFirstFrameAfterResetDoNotMoveIt) {
  QualityGovernor governor = started_at(0);
  governor.measured(900.0);  // opening the file and uploading the mesh
  for (int i = 0; i < 200; ++i) governor.measured(i % 3 == 1 ? 300.0 : 10.0);  // an edit every third frame
  EXPECT_EQ(governor.level(), 0);
  EXPECT_FALSE(governor.drops_anything());

  // Two slow frames in a row among fast ones do not either (three of five would).
  QualityGovernor pairs = started_at(0);
  for (int i = 0; i < 6; ++i) pairs.measured(10.0);  // a whole window (right after a move, three frames decide)
  for (int i = 0; i < 200; ++i) pairs.measured(i % 5 < 2 ? 300.0 : 10.0);
  EXPECT_EQ(pairs.level(), 0);

  // A spike at the cheapest level does not send it up or down either; nor does garbage.
  QualityGovernor bottom = started_at(kQualitySteps);
  bottom.measured(5.0);
  for (int i = 0; i < 100; ++i) bottom.measured(i % 4 == 0 ? 2.0 : 30.0);
  bottom.measured(-1.0);
  bottom.measured(0.0);
  EXPECT_EQ(bottom.level(), kQualitySteps);
}

TEST(QualityGovernor, TheUsersWireframeChoiceIsPassedOver) {
  QualityGovernor governor = started_at(0);
  QualitySteps steps;
  steps.wireframe = false;  // the user pressed W: theirs, shown or not
  governor.set_steps(steps);
  // Slow frames: multisampling goes, then the back sides; the wireframe never.
  const std::string levels = run(governor, {80, 80, 80, 80}, 12);
  EXPECT_EQ(moves(levels), 2) << levels;
  EXPECT_EQ(governor.level(), kQualitySteps);
  EXPECT_TRUE(governor.drops(QualityStep::Multisampling));
  EXPECT_FALSE(governor.drops(QualityStep::Wireframe));
  EXPECT_TRUE(governor.drops(QualityStep::BackSides));

  // Chosen while the governor had it off: from the next frame the wireframe is the user's; slow frames take the back
  // sides next.
  QualityGovernor dropped = started_at(0);
  run(dropped, {80, 80, 40.5, 40.5}, 7);
  ASSERT_EQ(dropped.level(), 2);
  ASSERT_TRUE(dropped.drops(QualityStep::Wireframe));
  dropped.set_steps(steps);
  EXPECT_FALSE(dropped.drops(QualityStep::Wireframe));
  EXPECT_TRUE(dropped.drops(QualityStep::Multisampling));
  run(dropped, {80, 80, 80, 80}, 3);
  EXPECT_EQ(dropped.level(), 3);
  EXPECT_FALSE(dropped.drops(QualityStep::Wireframe));
  EXPECT_TRUE(dropped.drops(QualityStep::BackSides));
}

TEST(QualityGovernor, StepsThatWouldChangeNothingArePassedOver) {
  // No samples in the framebuffer and an open mesh: the wireframe is the only thing to drop.
  QualityGovernor governor = started_at(0);
  QualitySteps steps;
  steps.multisampling = false;
  steps.back_sides = false;
  governor.set_steps(steps);
  EXPECT_EQ(run(governor, {80, 80, 80, 80}, 12), "000022222222");
  EXPECT_TRUE(governor.drops(QualityStep::Wireframe));
  EXPECT_FALSE(governor.drops(QualityStep::Multisampling));
  EXPECT_FALSE(governor.drops(QualityStep::BackSides));
  // And back up in one move when there is room.
  run(governor, {8, 8, 6, 6}, 10);
  EXPECT_EQ(governor.level(), 0);

  // Nothing to drop at all: it never moves.
  QualityGovernor stuck = started_at(0);
  stuck.set_steps({false, false, false});
  EXPECT_EQ(moves(run(stuck, {80, 80, 80, 80}, 50)), 0);
  EXPECT_FALSE(stuck.drops_anything());
}

TEST(QualityGovernor, ResetForgetsSamplesAndMeasuredRatios) {
  QualityGovernor governor = started_at(1);
  run(governor, {45, 12, 8, 6}, 30);
  ASSERT_GT(governor.ratio(QualityStep::Multisampling), 3.0);
  governor.measured(100.0);
  governor.measured(100.0);
  governor.reset(0);
  EXPECT_DOUBLE_EQ(governor.ratio(QualityStep::Multisampling), QualityRules().default_ratio[0]);
  EXPECT_DOUBLE_EQ(governor.slow_ms(), 0.0);
  governor.measured(100.0);  // ignored: the frame of the new mesh's upload
  governor.measured(100.0);
  governor.measured(100.0);
  EXPECT_EQ(governor.level(), 0);  // two samples, not the three a move down needs
  governor.measured(100.0);
  EXPECT_EQ(governor.level(), 1);
}

TEST(QualityGovernor, AMeasuredRatioIsHeldToMaxRatio) {
  // The frames got 16 times cheaper just as the back sides went (a panel closed): taken at its word, that ratio would
  // predict 80 ms for 5 ms frames and keep the back sides away for good. Held to 4, it predicts 20: they come back.
  QualityGovernor governor = started_at(2);
  run(governor, {80, 80, 80, 80}, 4);
  ASSERT_EQ(governor.level(), 3);
  run(governor, {5, 5, 5, 5}, 3);
  EXPECT_DOUBLE_EQ(governor.ratio(QualityStep::BackSides), QualityRules().max_ratio);
  run(governor, {5, 5, 5, 5}, 30);
  EXPECT_EQ(governor.level(), 0);
}

TEST(QualityGovernor, AViewChangeForgetsTheMeasuredRatiosButKeepsTheLevel) {
  // A ratio measured while the cost changed for another reason (the user hid the wireframe as the level moved) would
  // keep the step away: 45 / 12 says 12 ms frames would become 45. After view_changed() the default says 16.8.
  QualityGovernor governor = started_at(1);
  run(governor, {45, 12, 8, 6}, 30);
  ASSERT_EQ(governor.level(), 1);
  governor.view_changed();
  EXPECT_EQ(governor.level(), 1);
  EXPECT_DOUBLE_EQ(governor.ratio(QualityStep::Multisampling), QualityRules().default_ratio[0]);
  run(governor, {14, 12, 8, 6}, 10);
  EXPECT_EQ(governor.level(), 0);
}

}  // namespace
}  // namespace meshedit
