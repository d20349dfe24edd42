// add_arrow: the shaft ends where the head begins, the head's tip is the arrow's end, a fifth of its length, and lies
// across the view; an arrow seen end on still gets a head; nothing for a zero-length or non-finite arrow.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "render/arrow_overlay.h"

namespace meshedit {
namespace {

TEST(ArrowOverlay, AShaftAndAHeadFacingTheEye) {
  Overlay overlay;
  const glm::vec4 blue(0.0f, 0.45f, 0.7f, 1.0f);
  add_arrow(overlay, {0, 0, 0}, {0, 0, 1}, {5, 0, 0.5}, blue, 3.0f);
  ASSERT_EQ(overlay.lines.size(), 2u);
  const OverlayPolyline& shaft = overlay.lines[0];
  const OverlayPolyline& head = overlay.lines[1];
  ASSERT_EQ(shaft.points.size(), 2u);
  EXPECT_EQ(shaft.points[0], glm::dvec3(0, 0, 0));
  EXPECT_NEAR(glm::distance(shaft.points[1], glm::dvec3(0, 0, 0.8)), 0.0, 1e-12);
  ASSERT_EQ(head.points.size(), 3u);
  EXPECT_TRUE(head.closed);
  EXPECT_EQ(head.points[0], glm::dvec3(0, 0, 1));
  // Seen from +x, the barbs spread along y: the head's plane faces the eye.
  EXPECT_NEAR(head.points[1].x, 0.0, 1e-12);
  EXPECT_NEAR(std::abs(head.points[1].y), 0.5 * kArrowHeadWidth * kArrowHeadFraction, 1e-12);
  EXPECT_NEAR(head.points[1].z, 0.8, 1e-12);
  EXPECT_NEAR(head.points[1].y, -head.points[2].y, 1e-12);
  EXPECT_EQ(head.colour, blue);
  EXPECT_EQ(shaft.width, 3.0f);
}

TEST(ArrowOverlay, SeenEndOnItStillHasAHead) {
  Overlay overlay;
  add_arrow(overlay, {0, 0, 0}, {0, 0, 2}, {0, 0, 10}, glm::vec4(1.0f), 2.0f);
  ASSERT_EQ(overlay.lines.size(), 2u);
  const OverlayPolyline& head = overlay.lines[1];
  EXPECT_NEAR(glm::distance(head.points[1], head.points[2]), kArrowHeadWidth * kArrowHeadFraction * 2.0, 1e-12);
  EXPECT_NEAR(head.points[1].z, 1.6, 1e-12);
}

TEST(ArrowOverlay, NothingForAnArrowThatIsNotThere) {
  Overlay overlay;
  add_arrow(overlay, {1, 1, 1}, {1, 1, 1}, {0, 0, 5}, glm::vec4(1.0f), 2.0f);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  add_arrow(overlay, {0, 0, 0}, {nan, 0, 0}, {0, 0, 5}, glm::vec4(1.0f), 2.0f);
  EXPECT_TRUE(overlay.lines.empty());
}

}  // namespace
}  // namespace meshedit
