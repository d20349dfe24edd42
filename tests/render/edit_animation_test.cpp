// The pictures of a flip, split and collapse as they play (render/edit_animation.h), on the flip lesson's diamond
// a = (-1, 0, 0), b = (1, 0, 0), c = (0, 1, 0), d = (0, -1, 0): where every line's ends and every point are at the
// start, halfway and the end, that an undo plays the same pictures backward, and that time is clamped and eased.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "render/edit_animation.h"

namespace meshedit {
namespace {

const glm::dvec3 kA(-1, 0, 0), kB(1, 0, 0), kC(0, 1, 0), kD(0, -1, 0);
const EditAnimationLook kLook{{0.2f, 0.4f, 0.6f, 1.0f}, 5.0f, 12.0f};

void expect_near(const glm::dvec3& got, const glm::dvec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12);
  EXPECT_NEAR(got.y, want.y, 1e-12);
  EXPECT_NEAR(got.z, want.z, 1e-12);
}

void expect_line(const Overlay& overlay, size_t i, const glm::dvec3& start, const glm::dvec3& end) {
  SCOPED_TRACE("line " + std::to_string(i));
  ASSERT_LT(i, overlay.lines.size());
  ASSERT_EQ(overlay.lines[i].points.size(), 2u);
  expect_near(overlay.lines[i].points[0], start);
  expect_near(overlay.lines[i].points[1], end);
  EXPECT_EQ(overlay.lines[i].colour, kLook.colour);
  EXPECT_EQ(overlay.lines[i].width, kLook.line_width);
}

void expect_point(const Overlay& overlay, size_t i, const glm::dvec3& at, float size) {
  SCOPED_TRACE("point " + std::to_string(i));
  ASSERT_LT(i, overlay.points.size());
  expect_near(overlay.points[i].position, at);
  EXPECT_FLOAT_EQ(overlay.points[i].size, size);
}

void expect_same(const Overlay& got, const Overlay& want) {
  ASSERT_EQ(got.lines.size(), want.lines.size());
  ASSERT_EQ(got.points.size(), want.points.size());
  for (size_t i = 0; i < want.lines.size(); ++i) {
    expect_line(got, i, want.lines[i].points[0], want.lines[i].points[1]);
  }
  for (size_t i = 0; i < want.points.size(); ++i) expect_point(got, i, want.points[i].position, want.points[i].size);
}

TEST(EditAnimation, EasingIsSmoothstepAndSymmetric) {
  EXPECT_EQ(ease_in_out(0.0), 0.0);
  EXPECT_EQ(ease_in_out(0.5), 0.5);
  EXPECT_EQ(ease_in_out(1.0), 1.0);
  EXPECT_DOUBLE_EQ(ease_in_out(0.25), 0.15625);  // 3/16 - 2/64: slower than linear at the start
  EXPECT_DOUBLE_EQ(ease_in_out(0.75), 1.0 - ease_in_out(0.25));
  EXPECT_DOUBLE_EQ(operation_progress(0.25, PlayDirection::Forward), 0.15625);
  EXPECT_DOUBLE_EQ(operation_progress(0.25, PlayDirection::Backward), 0.84375);
}

TEST(EditAnimation, TimeIsClampedAndNanCountsAsTheStart) {
  EXPECT_EQ(ease_in_out(-2.0), 0.0);
  EXPECT_EQ(ease_in_out(7.0), 1.0);
  EXPECT_EQ(operation_progress(-1.0, PlayDirection::Forward), 0.0);
  EXPECT_EQ(operation_progress(3.0, PlayDirection::Forward), 1.0);
  EXPECT_EQ(operation_progress(3.0, PlayDirection::Backward), 0.0);
  EXPECT_EQ(operation_progress(std::numeric_limits<double>::quiet_NaN(), PlayDirection::Forward), 0.0);
  const EditAnimation flip{FlipMotion{kA, kB, kC, kD}, PlayDirection::Forward};
  expect_same(edit_animation_frame(flip, -0.5, kLook), edit_animation_frame(flip, 0.0, kLook));
  expect_same(edit_animation_frame(flip, 1.5, kLook), edit_animation_frame(flip, 1.0, kLook));
  expect_same(edit_overlay(flip.motion, 2.0, kLook), edit_overlay(flip.motion, 1.0, kLook));
}

TEST(EditAnimation, AFlippedEdgeTurnsInsideItsQuadFromABToDC) {
  const EditAnimation flip{FlipMotion{kA, kB, kC, kD}, PlayDirection::Forward};
  const Overlay start = edit_animation_frame(flip, 0.0, kLook);
  EXPECT_TRUE(start.on_top);
  ASSERT_EQ(start.lines.size(), 1u);
  expect_line(start, 0, kA, kB);
  ASSERT_EQ(start.points.size(), 2u);
  expect_point(start, 0, kA, kLook.point_size);
  expect_point(start, 1, kB, kLook.point_size);
  // Halfway the ends are halfway along the quad's sides a-d and b-c: the edge has turned counter-clockwise to y = x.
  const Overlay half = edit_animation_frame(flip, 0.5, kLook);
  expect_line(half, 0, {-0.5, -0.5, 0}, {0.5, 0.5, 0});
  expect_point(half, 0, {-0.5, -0.5, 0}, kLook.point_size);
  expect_point(half, 1, {0.5, 0.5, 0}, kLook.point_size);
  const Overlay end = edit_animation_frame(flip, 1.0, kLook);
  expect_line(end, 0, kD, kC);
  expect_point(end, 0, kD, kLook.point_size);
  expect_point(end, 1, kC, kLook.point_size);
}

TEST(EditAnimation, AnUndoneFlipPlaysTheSamePicturesBackward) {
  const EditAnimation forward{FlipMotion{kA, kB, kC, kD}, PlayDirection::Forward};
  const EditAnimation backward{FlipMotion{kA, kB, kC, kD}, PlayDirection::Backward};
  expect_line(edit_animation_frame(backward, 0.0, kLook), 0, kD, kC);
  expect_line(edit_animation_frame(backward, 1.0, kLook), 0, kA, kB);
  for (const double t : {0.0, 0.1, 0.3, 0.5, 0.8, 1.0}) {
    SCOPED_TRACE(t);
    expect_same(edit_animation_frame(backward, t, kLook), edit_animation_frame(forward, 1.0 - t, kLook));
  }
  // And it is not the forward play: at t = 0.1 the two differ.
  const Overlay f = edit_animation_frame(forward, 0.1, kLook), b = edit_animation_frame(backward, 0.1, kLook);
  EXPECT_GT(glm::length(f.lines[0].points[0] - b.lines[0].points[0]), 0.5);
}

TEST(EditAnimation, ASplitsNewVertexGrowsAtTheMidpointWithItsNewEdges) {
  const EditAnimation split{SplitMotion{kA, kB, {0, 0, 0}, {kC, kD}}, PlayDirection::Forward};
  const Overlay start = edit_animation_frame(split, 0.0, kLook);
  EXPECT_TRUE(start.lines.empty());  // only the edge a-b, which the mesh draws
  EXPECT_TRUE(start.points.empty());
  const Overlay half = edit_animation_frame(split, 0.5, kLook);
  ASSERT_EQ(half.lines.size(), 2u);
  expect_line(half, 0, {0, 0, 0}, {0, 0.5, 0});
  expect_line(half, 1, {0, 0, 0}, {0, -0.5, 0});
  ASSERT_EQ(half.points.size(), 1u);
  expect_point(half, 0, {0, 0, 0}, kLook.point_size * 0.5f);
  const Overlay end = edit_animation_frame(split, 1.0, kLook);
  expect_line(end, 0, {0, 0, 0}, kC);
  expect_line(end, 1, {0, 0, 0}, kD);
  expect_point(end, 0, {0, 0, 0}, kLook.point_size);
  // Undone: the new edges shrink back into m, which shrinks away.
  const EditAnimation undone{split.motion, PlayDirection::Backward};
  expect_same(edit_animation_frame(undone, 0.25, kLook), edit_animation_frame(split, 0.75, kLook));
  EXPECT_TRUE(edit_animation_frame(undone, 1.0, kLook).lines.empty());
}

TEST(EditAnimation, ASplitVertexAwayFromTheMidpointMovesThereFromIt) {
  const EditAnimation split{SplitMotion{kA, kB, {0.5, 0, 0}, {kC}}, PlayDirection::Forward};
  const Overlay half = edit_animation_frame(split, 0.5, kLook);
  expect_point(half, 0, {0.25, 0, 0}, kLook.point_size * 0.5f);
  expect_line(half, 0, {0.25, 0, 0}, {0.125, 0.5, 0});
}

TEST(EditAnimation, ACollapsesEndsSlideTogetherPullingTheirEdges) {
  const CollapseMotion motion{kA, kB, {0, 0, 0}, {kC, kD}, {kC, kD}};
  const EditAnimation collapse{motion, PlayDirection::Forward};
  const Overlay start = edit_animation_frame(collapse, 0.0, kLook);
  ASSERT_EQ(start.lines.size(), 5u);
  expect_line(start, 0, kA, kC);
  expect_line(start, 1, kA, kD);
  expect_line(start, 2, kB, kC);
  expect_line(start, 3, kB, kD);
  expect_line(start, 4, kA, kB);
  ASSERT_EQ(start.points.size(), 2u);
  expect_point(start, 0, kA, kLook.point_size);
  expect_point(start, 1, kB, kLook.point_size);
  const Overlay half = edit_animation_frame(collapse, 0.5, kLook);
  ASSERT_EQ(half.lines.size(), 5u);
  expect_line(half, 0, {-0.5, 0, 0}, kC);
  expect_line(half, 3, {0.5, 0, 0}, kD);
  expect_line(half, 4, {-0.5, 0, 0}, {0.5, 0, 0});
  expect_point(half, 0, {-0.5, 0, 0}, kLook.point_size);
  expect_point(half, 1, {0.5, 0, 0}, kLook.point_size);
  // Met: the edge between them is gone and one point is left, with the edges to c and d from it.
  const Overlay end = edit_animation_frame(collapse, 1.0, kLook);
  ASSERT_EQ(end.lines.size(), 4u);
  expect_line(end, 0, {0, 0, 0}, kC);
  expect_line(end, 3, {0, 0, 0}, kD);
  ASSERT_EQ(end.points.size(), 1u);
  expect_point(end, 0, {0, 0, 0}, kLook.point_size);
  const EditAnimation undone{motion, PlayDirection::Backward};
  expect_same(edit_animation_frame(undone, 0.0, kLook), end);
  expect_same(edit_animation_frame(undone, 1.0, kLook), start);
}

}  // namespace
}  // namespace meshedit
