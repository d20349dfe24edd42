// ChangeJournal and MeshPatch: on random flips, splits, collapses and direct pointer writes over meshes with dead
// slots, the patch's diff equals diff() of the two states, applying it either way gives the other state exactly, and
// revert() restores contents and version(); direct array access, assignment, being moved from and the log cap make
// the journal fall back to an exact snapshot; a copy of a journaled mesh has no journal; History's patch entries
// undo and redo like snapshot entries, versions included.
#include <random>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include "core/change_journal.h"
#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_patch.h"
#include "core/mesh_storage.h"
#include "core/primitives.h"
#include "support/diff_expect.h"
#include "support/fall_back_writes.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

TEST(ChangeJournal, PatchOfRandomEditsMatchesDiffAndAppliesBothWays) {
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE(seed);
    HalfedgeMesh mesh = testing::edited_torus(seed);
    std::mt19937 random(seed);
    for (int step = 0; step < 8; ++step) {
      const HalfedgeMesh before = mesh;
      MeshPatch patch;
      {
        ChangeJournal journal(mesh);
        testing::random_edit_or_write(mesh, random);
        ASSERT_FALSE(journal.has_snapshot());
        patch = make_patch(journal, mesh);
      }
      const std::vector<FieldChange> expected = diff(before, mesh);
      testing::expect_same_diff(patch_diff(patch), expected);
      EXPECT_EQ(patch_change_count(patch, 1000000), expected.size());
      testing::expect_same_diff(patch_diff(patch.reversed()), diff(mesh, before));

      HalfedgeMesh back = mesh;
      patch.apply(back, false);
      EXPECT_TRUE(back.same_as(before));
      EXPECT_EQ(back.num_vertices(), before.num_vertices());
      EXPECT_EQ(back.num_halfedges(), before.num_halfedges());
      EXPECT_EQ(back.num_edges(), before.num_edges());
      EXPECT_EQ(back.num_faces(), before.num_faces());
      HalfedgeMesh forward = before;
      patch.apply(forward, true);
      EXPECT_TRUE(forward.same_as(mesh));
      EXPECT_EQ(forward.num_edges(), mesh.num_edges());
      EXPECT_EQ(forward.num_faces(), mesh.num_faces());
    }
  }
}

TEST(ChangeJournal, RevertRestoresContentsAndVersion) {
  for (uint32_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    HalfedgeMesh mesh = testing::edited_torus(seed);
    const HalfedgeMesh before = mesh;
    std::mt19937 random(seed);
    ChangeJournal journal(mesh);
    for (int step = 0; step < 5; ++step) testing::random_edit_or_write(mesh, random);
    ASSERT_NE(mesh.version(), before.version());
    journal.revert();
    EXPECT_TRUE(mesh.same_as(before));
    EXPECT_EQ(mesh.version(), before.version());
    EXPECT_EQ(mesh.num_vertices(), before.num_vertices());
    EXPECT_EQ(mesh.num_halfedges(), before.num_halfedges());
    EXPECT_EQ(mesh.num_faces(), before.num_faces());
    EXPECT_FALSE(journal.attached());
  }
}

TEST(ChangeJournal, RevertKeepsAProvenMeshProven) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_icosahedron());
  ASSERT_TRUE(mesh.proven_valid_triangles());
  const HalfedgeMesh before = mesh;
  ChangeJournal journal(mesh);
  ASSERT_TRUE(flip(mesh, EdgeId(3)).ok());
  EXPECT_FALSE(mesh.proven_valid_triangles());
  journal.revert();
  EXPECT_TRUE(mesh.same_as(before));
  EXPECT_EQ(mesh.version(), before.version());
  EXPECT_TRUE(mesh.proven_valid_triangles());
}

TEST(ChangeJournal, IsNotCopiedWithTheMesh) {
  HalfedgeMesh mesh = testing::edited_torus(3);
  ChangeJournal journal(mesh);
  HalfedgeMesh copy = mesh;
  EXPECT_EQ(MeshStorage::journal(copy), nullptr);
  EXPECT_EQ(MeshStorage::journal(mesh), &journal);
  copy.set_next(HalfedgeId(0), HalfedgeId(5));
  HalfedgeMesh assigned;
  assigned = copy;
  assigned.set_next(HalfedgeId(1), HalfedgeId(5));
  EXPECT_TRUE(journal.log().empty());
  EXPECT_FALSE(journal.has_snapshot());
  mesh.set_next(HalfedgeId(0), HalfedgeId(5));
  EXPECT_EQ(journal.log().size(), 1u);
}

TEST(ChangeJournal, WritesToAppendedSlotsAreNotLogged) {
  HalfedgeMesh mesh = testing::edited_torus(4);
  ChangeJournal journal(mesh);
  const VertexId v = mesh.new_vertex();
  mesh.set_position(v, {1, 1, 1});
  mesh.set_halfedge(v, HalfedgeId(0));
  EXPECT_TRUE(journal.log().empty());
}

// Falls back in `write`, then checks the snapshot is the state before and the journal stopped listening.
template <class Write>
void expect_fall_back(Write&& write, std::optional<size_t> cap = std::nullopt) {
  HalfedgeMesh mesh = testing::edited_torus(5);
  const HalfedgeMesh before = mesh;
  ChangeJournal journal(mesh, cap);
  mesh.set_next(HalfedgeId(0), HalfedgeId(7));  // logged, then undone on the snapshot
  mesh.new_vertex();
  write(mesh);
  ASSERT_TRUE(journal.has_snapshot());
  EXPECT_TRUE(journal.log().empty());
  EXPECT_FALSE(journal.attached());
  if (mesh.halfedge_capacity() > 7) mesh.set_next(HalfedgeId(1), HalfedgeId(7));  // not logged any more
  EXPECT_TRUE(journal.log().empty());
  journal.revert();  // through the snapshot
  EXPECT_TRUE(mesh.same_as(before));
  EXPECT_EQ(mesh.version(), before.version());
  EXPECT_EQ(mesh.num_vertices(), before.num_vertices());
}

TEST(ChangeJournal, BulkWritesFallBackToASnapshot) {
  for (const testing::FallBackWrite& w : testing::fall_back_writes()) {
    SCOPED_TRACE(w.name);
    expect_fall_back(w.write);
  }
}

TEST(ChangeJournal, ANestedJournalMakesTheOuterOneFallBack) {
  expect_fall_back([](HalfedgeMesh& m) {
    ChangeJournal inner(m);
    m.set_next(HalfedgeId(2), HalfedgeId(7));
    EXPECT_FALSE(inner.has_snapshot());
  });
}

TEST(ChangeJournal, LogCapFallsBack) {
  expect_fall_back(
      [](HalfedgeMesh& m) {
        for (int i = 0; i < 50; ++i) m.set_position(VertexId(i % m.vertex_capacity()), glm::dvec3(i));
      },
      20);
}

TEST(ChangeJournal, LoopSubdivisionFallsBackAndItsSnapshotIsExact) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(5, 7));
  const HalfedgeMesh before = mesh;
  ChangeJournal journal(mesh);
  ASSERT_TRUE(loop_subdivide(mesh).ok);
  journal.detach();
  ASSERT_TRUE(journal.has_snapshot());
  const HalfedgeMesh snapshot = journal.take_snapshot();
  EXPECT_TRUE(snapshot.same_as(before));
  EXPECT_EQ(snapshot.version(), before.version());
}

// A patch entry ends undo and redo with the version a snapshot entry of the same edit gives, even when the recorded
// state's version is above the mesh's (a snapshot restores its own version before moving above the one seen).
TEST(ChangeJournal, PatchEntriesGiveTheVersionsOfSnapshotEntries) {
  HalfedgeMesh with_patch = testing::edited_torus(8);
  with_patch.bump_version_above(5000);
  const HalfedgeMesh before = with_patch;
  MeshPatch patch;
  {
    ChangeJournal journal(with_patch);
    std::mt19937 random(8);
    while (with_patch.version() == before.version()) testing::random_edit_or_write(with_patch, random);
    patch = make_patch(journal, with_patch);
  }
  MeshStorage::set_versions(with_patch, 10, MeshStorage::proven_version(with_patch));
  HalfedgeMesh with_snapshot = with_patch;
  History patches, snapshots;
  patches.record("edit", patch, before.version());
  snapshots.record("edit", before);
  EXPECT_NE(patches.undo_patch(), nullptr);
  EXPECT_EQ(snapshots.undo_patch(), nullptr);
  for (const bool forward : {false, true, false}) {
    ASSERT_TRUE(forward ? patches.redo(with_patch) : patches.undo(with_patch));
    ASSERT_TRUE(forward ? snapshots.redo(with_snapshot) : snapshots.undo(with_snapshot));
    EXPECT_TRUE(with_patch.same_as(with_snapshot));
    EXPECT_EQ(with_patch.version(), with_snapshot.version());
    EXPECT_EQ(with_patch.num_halfedges(), with_snapshot.num_halfedges());
  }
  EXPECT_TRUE(with_patch.same_as(before));
}

}  // namespace
}  // namespace meshedit
