// Tests of the patch view's state: the setters clamp, and the tessellation cache rebuilds only when the patches or
// the resolution change, with new mesh versions, and says why when the patches do not make a mesh.
#include "document/patch_view_state.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "support/test_patches.h"

namespace meshedit {
namespace {

using glm::dvec3;

using testing::bumpy_patch;
using testing::expect_same;
using testing::flat_patch;

TEST(PatchView, SettersClamp) {
  PatchViewState state = make_patch_view({bumpy_patch(), bumpy_patch(5.0)});
  set_resolution(state, 0);
  EXPECT_EQ(state.resolution, 1);
  set_resolution(state, 1000);
  EXPECT_EQ(state.resolution, kMaxPatchViewResolution);
  select_patch(state, 7);
  EXPECT_EQ(state.selected_patch, 1);
  select_patch(state, -3);
  EXPECT_EQ(state.selected_patch, 0);
  set_probe(state, 1.5, -0.25);
  EXPECT_EQ(state.u, 1.0);
  EXPECT_EQ(state.v, 0.0);
  set_probe(state, std::nan(""), 0.75);
  EXPECT_EQ(state.u, 1.0);
  EXPECT_EQ(state.v, 0.75);
  EXPECT_EQ(make_patch_view({}).resolution, kDefaultPatchResolution);
}

// ---- tessellation cache ----------------------------------------------------------------------------

TEST(PatchView, TessellationIsRebuiltOnlyWhenPatchesOrResolutionChange) {
  PatchViewState state = make_patch_view({flat_patch()});
  EXPECT_EQ(state.tessellation.rebuilds, 0u);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);
  ASSERT_TRUE(state.tessellation.mesh.has_value());
  EXPECT_EQ(state.tessellation.polygons.num_vertices(), 17u * 17u);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 2u * 16u * 16u);
  EXPECT_TRUE(state.tessellation.error.empty());
  const uint64_t first_version = state.tessellation.mesh->version();

  // Idle frames, and the same data assigned again: nothing is rebuilt.
  EXPECT_FALSE(update_tessellation(state));
  state.patches = {flat_patch()};
  state.u = 0.1;
  state.selected_patch = 0;
  EXPECT_FALSE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);

  set_resolution(state, 4);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 2u);
  EXPECT_EQ(state.tessellation.polygons.num_vertices(), 25u);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 32u);
  expect_same(state.tessellation.polygons.positions[6], dvec3(0.75, 0.75, 0.0));  // vertex j*(n+1)+i at (i/n, j/n)*3
  ASSERT_TRUE(state.tessellation.mesh.has_value());
  const uint64_t second_version = state.tessellation.mesh->version();
  EXPECT_GT(second_version, first_version);  // a renderer caching by version sees the new mesh

  state.patches[0].at(1, 1).z = 0.5;  // one control point moved
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 3u);
  EXPECT_GT(state.tessellation.mesh->version(), second_version);
  EXPECT_FALSE(update_tessellation(state));

  state.patches.push_back(bumpy_patch(10.0));  // a patch added
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 4u);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 2u * 2u * 4u * 4u);
}

TEST(PatchView, NaNPatchesDoNotRebuildEveryFrame) {
  BezierPatch broken = flat_patch();
  broken.at(2, 2).x = std::numeric_limits<double>::quiet_NaN();
  PatchViewState state = make_patch_view({broken});
  set_resolution(state, 2);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_FALSE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);
}

TEST(PatchView, ResolutionWrittenOutOfRangeIsClampedBeforeTessellating) {
  PatchViewState state = make_patch_view({flat_patch()});
  state.resolution = 100000;
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.resolution, kMaxPatchViewResolution);
  EXPECT_EQ(state.tessellation.resolution, kMaxPatchViewResolution);
  EXPECT_EQ(state.tessellation.polygons.num_faces(), 2u * 64u * 64u);
}

TEST(PatchView, InconsistentPatchesKeepPolygonsAndSayWhy) {
  // The same flat patch twice, the second with its rows reversed: the shared surface is used twice with
  // opposite orientations, which the tessellator splits apart or the builder refuses; either way nothing
  // throws out of update_tessellation, and the cache says what it has.
  BezierPatch flipped = flat_patch();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) flipped.at(r, c) = flat_patch().at(3 - r, c);
  }
  PatchViewState state = make_patch_view({flat_patch(), flipped});
  set_resolution(state, 2);
  EXPECT_TRUE(update_tessellation(state));
  EXPECT_EQ(state.tessellation.rebuilds, 1u);
  EXPECT_EQ(state.tessellation.mesh.has_value(), state.tessellation.error.empty());
  EXPECT_GT(state.tessellation.polygons.num_faces(), 0u);
}

}  // namespace
}  // namespace meshedit
