// MeshPatch::apply_as_edit: a patch taken from an edit, made again on a copy of the state before through the setters,
// gives the same mesh (contents and live counts), and a journal on the copy logs it slot by slot (no fall-back) into
// the same patch; a patch it cannot make that way is refused with the mesh untouched.
#include <algorithm>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/change_journal.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_patch.h"
#include "core/primitives.h"
#include "support/diff_expect.h"
#include "support/journaled_edit.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

using testing::patch_of;

void expect_same_shape(const MeshShape& a, const MeshShape& b) {
  for (int k = 0; k < kElementKindCount; ++k) {
    EXPECT_EQ(a.capacity[k], b.capacity[k]) << "kind " << k;
    EXPECT_EQ(a.live[k], b.live[k]) << "kind " << k;
  }
}

TEST(PatchAsEdit, MakesTheSameMeshThroughTheSetters) {
  size_t made = 0;
  for (uint32_t seed = 1; seed <= 60; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    HalfedgeMesh mesh = testing::edited_torus(seed);
    std::mt19937 random(seed);
    for (int step = 0; step < 6; ++step) {
      const HalfedgeMesh before = mesh;
      const MeshPatch patch = patch_of(mesh, [&](HalfedgeMesh& m) { testing::random_edit_or_write(m, random); });

      HalfedgeMesh copy = before;
      MeshPatch logged;
      {
        ChangeJournal journal(copy);
        ASSERT_TRUE(patch.apply_as_edit(copy));
        ASSERT_FALSE(journal.has_snapshot());
        logged = make_patch(journal, copy);
      }
      EXPECT_TRUE(copy.same_as(mesh));
      expect_same_shape(shape_of(copy), shape_of(mesh));
      testing::expect_same_diff(patch_diff(logged), patch_diff(patch));
      made += patch.slots.empty() ? 0 : 1;
    }
  }
  EXPECT_GT(made, 250u);
}

// Undoing a deletion revives a slot, and undoing a split drops slots: no setter does either.
TEST(PatchAsEdit, RefusesWhatNoSetterCanDo) {
  const HalfedgeMesh start = build_halfedge_mesh(make_torus(6, 5));
  HalfedgeMesh deleted = start;
  const MeshPatch deletion = patch_of(deleted, [](HalfedgeMesh& m) { m.delete_element(EdgeId(3)); });
  HalfedgeMesh split_mesh = start;
  const MeshPatch splitting = patch_of(split_mesh, [](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(3)).ok()); });

  for (const auto& [mesh, patch] :
       {std::pair{&deleted, deletion.reversed()}, std::pair{&split_mesh, splitting.reversed()}}) {
    HalfedgeMesh target = *mesh;
    const uint64_t version = target.version();
    EXPECT_FALSE(patch.apply_as_edit(target));
    EXPECT_TRUE(target.same_as(*mesh));
    EXPECT_EQ(target.version(), version);
  }
}

// The mesh must be in the patch's state before: the state after, or a state with another value in a listed slot, is
// refused untouched.
TEST(PatchAsEdit, RefusesAMeshNotInTheStateBefore) {
  const HalfedgeMesh start = build_halfedge_mesh(make_torus(6, 5));
  HalfedgeMesh flipped = start;
  const MeshPatch flip_patch = patch_of(flipped, [](HalfedgeMesh& m) { ASSERT_TRUE(flip(m, EdgeId(4)).ok()); });

  HalfedgeMesh twice = flipped;
  EXPECT_FALSE(flip_patch.apply_as_edit(twice));
  EXPECT_TRUE(twice.same_as(flipped));

  HalfedgeMesh moved = start;  // one listed halfedge holds another value
  const SlotChange& listed = *std::find_if(flip_patch.slots.begin(), flip_patch.slots.end(),
                                           [](const SlotChange& c) { return c.kind == ElementKind::Halfedge; });
  moved.set_twin(HalfedgeId(listed.slot), HalfedgeId(listed.slot));
  const HalfedgeMesh moved_before = moved;
  EXPECT_FALSE(flip_patch.apply_as_edit(moved));
  EXPECT_TRUE(moved.same_as(moved_before));
}

}  // namespace
}  // namespace meshedit
