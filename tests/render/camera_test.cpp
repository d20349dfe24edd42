// OrbitCamera: pure math, checked against the conventions in render/camera.h.
#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render/camera.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::near;

BoundingBox box(glm::dvec3 lo, glm::dvec3 hi) {
  BoundingBox b;
  b.add(lo);
  b.add(hi);
  return b;
}

std::array<glm::dvec3, 8> corners(const BoundingBox& b) {
  std::array<glm::dvec3, 8> out;
  for (int i = 0; i < 8; ++i) {
    out[size_t(i)] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
  }
  return out;
}

// Every corner lands inside the viewport, in front of the eye and within the depth range.
void expect_all_corners_visible(const OrbitCamera& camera, const BoundingBox& b, Viewport viewport) {
  for (const glm::dvec3& c : corners(b)) {
    const ScreenPoint p = camera.project(c, viewport);
    EXPECT_TRUE(p.in_front);
    EXPECT_GT(p.pixel.x, 0.0) << c.x << " " << c.y << " " << c.z;
    EXPECT_LT(p.pixel.x, viewport.width);
    EXPECT_GT(p.pixel.y, 0.0);
    EXPECT_LT(p.pixel.y, viewport.height);
    EXPECT_GT(p.depth, 0.0);
    EXPECT_LT(p.depth, 1.0);
  }
}

double distance_to_ray(const Ray& ray, const glm::dvec3& p) {
  const glm::dvec3 d = p - ray.origin;
  return glm::length(d - ray.direction * glm::dot(d, ray.direction));
}

TEST(BoundingBox, StartsEmptyAndGrows) {
  BoundingBox b;
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.diagonal(), 0.0);
  b.add({1, 2, 3});
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.diagonal(), 0.0);
  b.add({-1, 0, 3});
  EXPECT_TRUE(near(b.min, {-1, 0, 3}, 0.0));
  EXPECT_TRUE(near(b.max, {1, 2, 3}, 0.0));
  EXPECT_TRUE(near(b.centre(), {0, 1, 3}, 0.0));
  EXPECT_DOUBLE_EQ(b.diagonal(), std::sqrt(8.0));
}

TEST(OrbitCamera, FitTargetsTheCentreFromTheThreeQuarterView) {
  OrbitCamera camera;
  const BoundingBox b = box({-1, 0, 2}, {3, 2, 4});
  camera.fit(b);
  EXPECT_TRUE(near(camera.target(), {1, 1, 3}, 0.0));
  EXPECT_DOUBLE_EQ(camera.yaw_degrees(), OrbitCamera::kDefaultYawDegrees);
  EXPECT_DOUBLE_EQ(camera.pitch_degrees(), OrbitCamera::kDefaultPitchDegrees);
  EXPECT_NEAR(glm::length(camera.eye() - camera.target()), camera.distance(), 1e-12);
}

TEST(OrbitCamera, FitIsTightTheOutermostCornerTouchesTheMargin) {
  // In a square viewport the corner furthest out lands at 1/1.15 of the way from the centre to the
  // nearest side: no closer (it would leave the margin) and no further (the mesh would look small).
  for (const BoundingBox& b : {box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}), box({-3, -2, 0}, {3.434, 2, 3.15})}) {
    OrbitCamera camera;
    camera.fit(b);
    const Viewport viewport{400, 400};
    double outermost = 0.0;
    for (const glm::dvec3& c : corners(b)) {
      const ScreenPoint p = camera.project(c, viewport);
      outermost = std::max({outermost, std::abs(p.pixel.x - 200.0) / 200.0, std::abs(p.pixel.y - 200.0) / 200.0});
    }
    EXPECT_NEAR(outermost, 1.0 / 1.15, 1e-9);
  }
}

TEST(OrbitCamera, FitPutsEveryBoxCornerInsideTheViewportAtAnyAspect) {
  const BoundingBox boxes[] = {box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}), box({-3, -2, 0}, {3.434, 2, 3.15}),
                               box({100, 100, 100}, {100.001, 100.5, 100.002}), box({0, 0, 0}, {10, 0.01, 0.01})};
  const Viewport viewports[] = {{256, 256}, {1280, 800}, {300, 900}, {1, 1000}};
  for (UpAxis up : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
    for (const BoundingBox& b : boxes) {
      for (Viewport v : viewports) {
        OrbitCamera camera;
        camera.set_up_axis(up);
        camera.fit(b);
        SCOPED_TRACE(::testing::Message() << "viewport " << v.width << "x" << v.height);
        expect_all_corners_visible(camera, b, v);
      }
    }
  }
}

TEST(OrbitCamera, FitLookingFromADirectionSeesTheBoxFromThereAndResetReturnsThere) {
  const BoundingBox b = box({-3, -2, 0}, {3.434, 2, 3.15});
  const glm::dvec3 directions[] = {{-1, -1, 0}, {0, 0, -1}, {0.2, -3, 1}, {0, 1, 0}};
  for (UpAxis up : {UpAxis::Y, UpAxis::Z}) {
    for (const glm::dvec3& direction : directions) {
      OrbitCamera camera;
      camera.set_up_axis(up);
      camera.fit_looking_from(b, direction);
      SCOPED_TRACE(::testing::Message() << direction.x << " " << direction.y << " " << direction.z);
      const glm::dvec3 seen_from = glm::normalize(camera.eye() - camera.target());
      const glm::dvec3 wanted = glm::normalize(direction);
      // Straight along up is as close as the pitch clamp lets it be (89 degrees).
      const bool along_up = std::abs(glm::dot(wanted, camera.up_vector())) > 0.9999;
      EXPECT_GT(glm::dot(seen_from, wanted), along_up ? std::cos(1.01 * 3.14159265358979 / 180.0) : 1.0 - 1e-12);
      EXPECT_TRUE(near(camera.target(), b.centre(), 1e-12));
      expect_all_corners_visible(camera, b, {400, 300});
      camera.orbit(120, -40);
      camera.zoom(3);
      camera.reset();
      EXPECT_TRUE(near(glm::normalize(camera.eye() - camera.target()), seen_from, 1e-12));
    }
  }
  // No direction is the three-quarter view, as fit() gives it.
  OrbitCamera plain, none;
  plain.fit(b);
  none.fit_looking_from(b, glm::dvec3(0.0));
  EXPECT_TRUE(near(none.eye(), plain.eye(), 0.0));
  none.fit_looking_from(b, glm::dvec3(std::nan(""), 1, 0));
  EXPECT_TRUE(near(none.eye(), plain.eye(), 0.0));
}

TEST(OrbitCamera, EmptyOrPointBoxesStillGiveAUsableView) {
  OrbitCamera camera;
  camera.fit(BoundingBox{});
  EXPECT_TRUE(near(camera.target(), {0, 0, 0}, 0.0));
  expect_all_corners_visible(camera, box({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}), {100, 100});
  BoundingBox point;
  point.add({2, 3, 4});
  camera.fit(point);
  EXPECT_TRUE(near(camera.target(), {2, 3, 4}, 0.0));
  EXPECT_GT(camera.distance(), 0.0);
  EXPECT_GT(camera.near_plane(), 0.0);
  EXPECT_LT(camera.near_plane(), camera.distance());
}

TEST(OrbitCamera, ZUpIsTheDefault) {
  const OrbitCamera camera;
  EXPECT_EQ(camera.up_axis(), UpAxis::Z);
  EXPECT_TRUE(near(camera.up_vector(), {0, 0, 1}, 0.0));
  // The default view looks from the front (-y), the right (+x) and above (+z).
  EXPECT_LT(camera.eye().y, 0.0);
  EXPECT_GT(camera.eye().x, 0.0);
  EXPECT_GT(camera.eye().z, 0.0);
}

TEST(OrbitCamera, YUpFrontViewLooksDownMinusZAndZUpDownPlusY) {
  OrbitCamera camera;
  camera.set_up_axis(UpAxis::Y);
  camera.fit(box({-1, -1, -1}, {1, 1, 1}));
  camera.orbit(OrbitCamera::kDefaultYawDegrees * M_PI / 180 / OrbitCamera::kRadiansPerPixel,
               -OrbitCamera::kDefaultPitchDegrees * M_PI / 180 / OrbitCamera::kRadiansPerPixel);
  EXPECT_NEAR(camera.yaw_degrees(), 0.0, 1e-9);
  EXPECT_NEAR(camera.pitch_degrees(), 0.0, 1e-9);
  EXPECT_TRUE(near(camera.forward_direction(), {0, 0, -1}, 1e-12));
  EXPECT_TRUE(near(camera.right_direction(), {1, 0, 0}, 1e-12));
  EXPECT_TRUE(near(camera.screen_up_direction(), {0, 1, 0}, 1e-12));
  camera.set_up_axis(UpAxis::Z);
  EXPECT_TRUE(near(camera.forward_direction(), {0, 1, 0}, 1e-12));
  EXPECT_TRUE(near(camera.right_direction(), {1, 0, 0}, 1e-12));
  EXPECT_TRUE(near(camera.screen_up_direction(), {0, 0, 1}, 1e-12));
}

// COLLADA's frame for each up axis (core/up_axis.h): the front view's right, up and towards-the-viewer axes.
struct AxisFrameCase {
  UpAxis up;
  glm::dvec3 right, up_vector, towards_viewer;
};
constexpr double kPiOver180 = M_PI / 180.0;

TEST(OrbitCamera, EachUpAxisFrontViewIsColladasFrame) {
  const AxisFrameCase cases[] = {{UpAxis::X, {0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                 {UpAxis::Y, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                 {UpAxis::Z, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}}};
  for (const AxisFrameCase& c : cases) {
    SCOPED_TRACE(std::string(up_axis_name(c.up)));
    OrbitCamera camera;
    camera.set_up_axis(c.up);
    camera.fit(box({-1, -1, -1}, {1, 1, 1}));
    camera.set_angles(0, 0);
    EXPECT_EQ(camera.up_axis(), c.up);
    EXPECT_TRUE(near(camera.up_vector(), c.up_vector, 0.0));
    EXPECT_TRUE(near(camera.forward_direction(), -c.towards_viewer, 1e-12));
    EXPECT_TRUE(near(camera.right_direction(), c.right, 1e-12));
    EXPECT_TRUE(near(camera.screen_up_direction(), c.up_vector, 1e-12));
    EXPECT_TRUE(near(glm::cross(c.right, c.up_vector), c.towards_viewer, 0.0));  // right-handed
    camera.set_angles(90, 0);  // yaw turns the eye from the front towards the right
    EXPECT_TRUE(near((camera.eye() - camera.target()) / camera.distance(), c.right, 1e-12));
    camera.set_angles(0, 89);
    EXPECT_GT(glm::dot(camera.eye() - camera.target(), c.up_vector) / camera.distance(), 0.99);
  }
}

TEST(OrbitCamera, EachUpAxisShowsItsUpAxisUpAndYawTurnsAboutIt) {
  // A mesh standing along its up axis stands upright on screen in the fitted three-quarter view: its top is
  // straight above its centre, and orbiting sideways keeps it there.
  for (UpAxis up : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
    SCOPED_TRACE(std::string(up_axis_name(up)));
    OrbitCamera camera;
    camera.set_up_axis(up);
    camera.fit(box({-1, -1, -1}, {1, 1, 1}));
    const Viewport viewport{600, 400};
    for (double drag : {0.0, 80.0, -200.0}) {
      camera.orbit(drag, 0);
      const ScreenPoint centre = camera.project({0, 0, 0}, viewport);
      const ScreenPoint top = camera.project(camera.up_vector(), viewport);
      EXPECT_NEAR(top.pixel.x, centre.pixel.x, 1e-9);
      EXPECT_LT(top.pixel.y, centre.pixel.y - 50);
    }
    camera.reset();  // the eye is above the mesh (pitch 20 degrees towards the up axis) and in front of it
    const glm::dvec3 offset = (camera.eye() - camera.target()) / camera.distance();
    EXPECT_NEAR(glm::dot(offset, camera.up_vector()), std::sin(OrbitCamera::kDefaultPitchDegrees * kPiOver180), 1e-12);
    EXPECT_EQ(camera.up_axis(), up);
  }
}

TEST(OrbitCamera, ChangingTheUpAxisKeepsTheAnglesAboutTheNewAxis) {
  OrbitCamera camera;
  camera.fit(box({-1, -1, -1}, {1, 1, 1}));
  camera.set_angles(10, 30);
  camera.set_up_axis(UpAxis::X);
  EXPECT_NEAR(camera.yaw_degrees(), 10, 1e-12);
  EXPECT_NEAR(camera.pitch_degrees(), 30, 1e-12);
  EXPECT_NEAR(glm::dot(camera.eye() - camera.target(), glm::dvec3(1, 0, 0)) / camera.distance(),
              std::sin(30 * kPiOver180), 1e-12);
}

TEST(OrbitCamera, OrbitTurnsAroundTheTargetAndClampsPitch) {
  OrbitCamera camera;
  camera.fit(box({-1, -1, -1}, {1, 1, 1}));
  const glm::dvec3 target = camera.target();
  const double distance = camera.distance();
  const glm::dvec3 eye_before = camera.eye();
  camera.orbit(50, 0);  // drag right: the mesh turns right, so the eye swings left (yaw decreases)
  EXPECT_NEAR(camera.yaw_degrees(), OrbitCamera::kDefaultYawDegrees - 50 * 0.01 * 180 / M_PI, 1e-9);
  EXPECT_DOUBLE_EQ(camera.pitch_degrees(), OrbitCamera::kDefaultPitchDegrees);
  EXPECT_TRUE(near(camera.target(), target, 0.0));
  EXPECT_NEAR(glm::length(camera.eye() - target), distance, 1e-12);
  EXPECT_LT(camera.eye().x, eye_before.x);
  camera.orbit(0, 10);  // drag down: seen more from above
  EXPECT_NEAR(camera.pitch_degrees(), OrbitCamera::kDefaultPitchDegrees + 10 * 0.01 * 180 / M_PI, 1e-9);
  camera.orbit(0, 1e6);
  EXPECT_DOUBLE_EQ(camera.pitch_degrees(), 89.0);
  camera.orbit(0, -1e6);
  EXPECT_DOUBLE_EQ(camera.pitch_degrees(), -89.0);
  EXPECT_TRUE(near(camera.target(), target, 0.0));
}

TEST(OrbitCamera, ZoomScalesTheDistanceWithinLimits) {
  OrbitCamera camera;
  camera.fit(box({-1, -1, -1}, {1, 1, 1}));
  const double fitted = camera.distance();
  camera.zoom(1);
  EXPECT_DOUBLE_EQ(camera.distance(), fitted * OrbitCamera::kZoomPerStep);
  camera.zoom(-2);
  EXPECT_NEAR(camera.distance(), fitted / OrbitCamera::kZoomPerStep, 1e-12);
  camera.zoom(1000);
  EXPECT_DOUBLE_EQ(camera.distance(), fitted / 100);
  EXPECT_GT(camera.near_plane(), 0.0);
  EXPECT_LT(camera.near_plane(), camera.distance());  // the target is never clipped
  camera.zoom(-1000);
  EXPECT_DOUBLE_EQ(camera.distance(), fitted * 20);
  EXPECT_GT(camera.far_plane(), camera.distance() + 1.7);  // the whole box stays inside
}

TEST(OrbitCamera, PanMovesWhatIsUnderTheCursorWithTheDrag) {
  OrbitCamera camera;
  camera.fit(box({-1, -1, -1}, {1, 1, 1}));
  const Viewport viewport{800, 600};
  const glm::dvec3 old_target = camera.target();
  const ScreenPoint before = camera.project(old_target, viewport);
  EXPECT_NEAR(before.pixel.x, 400.0, 1e-9);
  EXPECT_NEAR(before.pixel.y, 300.0, 1e-9);
  camera.pan(30, -20, viewport);
  const ScreenPoint after = camera.project(old_target, viewport);
  EXPECT_NEAR(after.pixel.x, 430.0, 1e-6);
  EXPECT_NEAR(after.pixel.y, 280.0, 1e-6);
  // The target moved in the screen plane only.
  EXPECT_NEAR(glm::dot(camera.target() - old_target, camera.forward_direction()), 0.0, 1e-12);
}

TEST(OrbitCamera, ResetReturnsToTheFittedView) {
  OrbitCamera camera;
  camera.fit(box({0, 0, 0}, {2, 4, 6}));
  const glm::dvec3 eye = camera.eye();
  const glm::dvec3 target = camera.target();
  camera.orbit(123, -45);
  camera.zoom(3);
  camera.pan(10, 10, {640, 480});
  EXPECT_FALSE(near(camera.eye(), eye, 1e-6));
  camera.reset();
  EXPECT_TRUE(near(camera.eye(), eye, 1e-12));
  EXPECT_TRUE(near(camera.target(), target, 0.0));
}

TEST(OrbitCamera, RayThroughTheCentrePixelHitsTheTarget) {
  OrbitCamera camera;
  camera.fit(box({-2, 0, 1}, {4, 3, 2}));
  camera.orbit(-70, 35);
  camera.pan(15, 5, {640, 480});
  const Viewport viewport{640, 480};
  const Ray ray = camera.ray({320.0, 240.0}, viewport);
  EXPECT_TRUE(near(ray.origin, camera.eye(), 1e-12));
  EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-12);
  EXPECT_LT(distance_to_ray(ray, camera.target()), 1e-9);
  // And a ray through any pixel passes through the point that projects there.
  const glm::dvec3 p(0.5, 2.5, 1.25);
  const ScreenPoint s = camera.project(p, viewport);
  EXPECT_LT(distance_to_ray(camera.ray(s.pixel, viewport), p), 1e-9);
}

TEST(OrbitCamera, ProjectionIsBehindTheEyeForPointsBehindIt) {
  OrbitCamera camera;
  camera.fit(box({-1, -1, -1}, {1, 1, 1}));
  const glm::dvec3 behind = camera.eye() - camera.forward_direction() * 5.0;
  EXPECT_FALSE(camera.project(behind, {100, 100}).in_front);
}

}  // namespace
}  // namespace meshedit

namespace meshedit {
namespace {

TEST(OrbitCamera, SetAnglesDistanceAndTargetAreTakenAsGivenWithinTheirLimits) {
  OrbitCamera camera;
  camera.set_angles(45.0, 30.0);
  camera.set_distance(7.5);
  camera.set_target(glm::dvec3(1, 2, 3));
  EXPECT_NEAR(camera.yaw_degrees(), 45.0, 1e-12);
  EXPECT_NEAR(camera.pitch_degrees(), 30.0, 1e-12);
  EXPECT_EQ(camera.distance(), 7.5);
  EXPECT_EQ(camera.target(), glm::dvec3(1, 2, 3));
  EXPECT_NEAR(glm::length(camera.eye() - camera.target()), 7.5, 1e-12);

  camera.set_angles(400.0, 120.0);  // yaw wraps, pitch stops short of the pole
  EXPECT_NEAR(camera.yaw_degrees(), 40.0, 1e-9);
  EXPECT_NEAR(camera.pitch_degrees(), 89.0, 1e-9);
  camera.set_distance(-1.0);
  camera.set_distance(std::nan(""));
  camera.set_target(glm::dvec3(std::nan(""), 0, 0));
  camera.set_angles(std::nan(""), 10.0);  // only the finite angle is taken
  EXPECT_EQ(camera.distance(), 7.5);
  EXPECT_EQ(camera.target(), glm::dvec3(1, 2, 3));
  EXPECT_NEAR(camera.yaw_degrees(), 40.0, 1e-9);
  EXPECT_NEAR(camera.pitch_degrees(), 10.0, 1e-9);
}

}  // namespace
}  // namespace meshedit
