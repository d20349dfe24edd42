// ChangeJournal when a fall-back cannot allocate its snapshot (FailingSnapshots makes the copy throw std::bad_alloc):
// every way of falling back (direct array access, assignment, being moved from in the mesh's noexcept move, swap, a
// nested journal, the log cap, Loop subdivision's grow) returns normally instead of ending the program; the journal
// then reports the state before lost, holds neither snapshot nor log and has detached; the mesh is exactly what the
// same writes make of a mesh without a journal; revert() says it cannot and leaves the mesh alone; and a journal
// attached afterwards works as before.
#include <optional>
#include <utility>

#include <gtest/gtest.h>

#include "core/change_journal.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_storage.h"
#include "core/primitives.h"
#include "support/failing_snapshots.h"
#include "support/fall_back_writes.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

// Runs a logged write, an append and `write` (which falls back) under a journal whose snapshot fails, then checks
// the journal gave up cleanly and the mesh is what the same writes make without a journal.
template <class Write>
void expect_lost_fall_back(Write&& write, std::optional<size_t> cap = std::nullopt) {
  auto edit = [&](HalfedgeMesh& m) {
    m.set_next(HalfedgeId(0), HalfedgeId(7));  // logged, then dropped with the log
    m.new_vertex();
    write(m);
  };
  HalfedgeMesh expected = testing::edited_torus(5);
  edit(expected);

  HalfedgeMesh mesh = testing::edited_torus(5);
  const testing::FailingSnapshots failing;
  ChangeJournal journal(mesh, cap);
  edit(mesh);
  EXPECT_TRUE(journal.state_before_lost());
  EXPECT_FALSE(journal.has_snapshot());
  EXPECT_TRUE(journal.log().empty());
  EXPECT_FALSE(journal.attached());
  if (mesh.halfedge_capacity() > 7) {
    mesh.set_next(HalfedgeId(1), HalfedgeId(7));  // not logged any more
    expected.set_next(HalfedgeId(1), HalfedgeId(7));
  }
  EXPECT_TRUE(journal.log().empty());
  EXPECT_TRUE(mesh.same_as(expected));
  EXPECT_EQ(mesh.num_vertices(), expected.num_vertices());
  const uint64_t version = mesh.version();
  EXPECT_FALSE(journal.revert());
  EXPECT_TRUE(mesh.same_as(expected));
  EXPECT_EQ(mesh.version(), version);
}

TEST(JournalOutOfMemory, BulkWritesGiveUpTheStateBefore) {
  // Among them the mesh's noexcept move: a fall-back that threw from it would end the program.
  for (const testing::FallBackWrite& w : testing::fall_back_writes()) {
    SCOPED_TRACE(w.name);
    expect_lost_fall_back(w.write);
  }
}

TEST(JournalOutOfMemory, ANestedJournalGivesUpTheOuterOnesStateBefore) {
  expect_lost_fall_back([](HalfedgeMesh& m) {
    ChangeJournal inner(m);
    m.set_next(HalfedgeId(2), HalfedgeId(7));
    EXPECT_FALSE(inner.state_before_lost());
    EXPECT_EQ(inner.log().size(), 1u);
  });
}

TEST(JournalOutOfMemory, TheLogCapGivesUpTheStateBefore) {
  expect_lost_fall_back(
      [](HalfedgeMesh& m) {
        for (int i = 0; i < 50; ++i) m.set_position(VertexId(i % m.vertex_capacity()), glm::dvec3(i));
      },
      20);
}

TEST(JournalOutOfMemory, LoopSubdivisionKeepsItsResult) {
  HalfedgeMesh expected = build_halfedge_mesh(make_torus(5, 7));
  ASSERT_TRUE(loop_subdivide(expected).ok);
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(5, 7));
  const testing::FailingSnapshots failing;
  ChangeJournal journal(mesh);
  ASSERT_TRUE(loop_subdivide(mesh).ok);
  EXPECT_TRUE(journal.state_before_lost());
  EXPECT_FALSE(journal.has_snapshot());
  EXPECT_FALSE(journal.attached());
  EXPECT_TRUE(mesh.same_as(expected));
  EXPECT_EQ(mesh.num_faces(), expected.num_faces());
  EXPECT_TRUE(mesh.proven_valid_triangles());
}

TEST(JournalOutOfMemory, AJournalAttachedAfterwardsWorks) {
  HalfedgeMesh mesh = testing::edited_torus(6);
  {
    const testing::FailingSnapshots failing;
    ChangeJournal lost(mesh);
    MeshStorage::view(mesh).position[0] = glm::dvec3(9);
    ASSERT_TRUE(lost.state_before_lost());
  }
  const HalfedgeMesh before = mesh;
  ChangeJournal journal(mesh);
  mesh.set_next(HalfedgeId(0), HalfedgeId(7));
  MeshStorage::view(mesh).position[1] = glm::dvec3(4);
  ASSERT_TRUE(journal.has_snapshot());
  EXPECT_FALSE(journal.state_before_lost());
  EXPECT_TRUE(journal.revert());
  EXPECT_TRUE(mesh.same_as(before));
  EXPECT_EQ(mesh.version(), before.version());
}

}  // namespace
}  // namespace meshedit
