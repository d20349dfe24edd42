// Bézier patches the patch view's tests share: a bumpy one with distinct control points and a flat one, and an exact
// comparison of points.
#pragma once

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include "core/bezier.h"

namespace meshedit::testing {

// A bumpy, non-planar patch with distinct control points: at(r, c) = (c + shift, r, z(r, c)).
inline BezierPatch bumpy_patch(double shift = 0.0) {
  static constexpr double kHeights[16] = {0.0,  0.5,  -0.25, 1.0, 0.75,  2.0,   1.5,  -0.5,
                                          -1.0, 0.25, 3.0,   0.5, 0.125, -0.75, 1.25, 2.5};
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = glm::dvec3(c + shift, r, kHeights[r * 4 + c]);
  }
  return patch;
}

// The plane z = 0 over [0,3]^2: tessellates to (n+1)^2 vertices and 2n^2 triangles.
inline BezierPatch flat_patch() {
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) patch.at(r, c) = glm::dvec3(c, r, 0.0);
  }
  return patch;
}

// Each coordinate bit for bit.
inline void expect_same(const glm::dvec3& actual, const glm::dvec3& expected) {
  EXPECT_EQ(actual.x, expected.x);
  EXPECT_EQ(actual.y, expected.y);
  EXPECT_EQ(actual.z, expected.z);
}

}  // namespace meshedit::testing
