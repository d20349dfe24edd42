// History::undo and History::redo when memory runs out at each of their allocations in turn (FailingAllocations):
// either the step is taken, or std::bad_alloc comes out with the mesh (contents and version) and both lists exactly
// as they were; never a mesh half-way. Redo of a split grows every array and redo of a collapse needs dead bits the
// mesh has not got (it is rebuilt, so nothing is left over from the undo), so MeshPatch::apply's allocations are
// among those failed.
#include <functional>
#include <new>
#include <string>

#include <gtest/gtest.h>

#include "core/change_journal.h"
#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_patch.h"
#include "core/primitives.h"
#include "support/failing_allocations.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;

HalfedgeMesh torus() { return build_halfedge_mesh(make_torus(5, 7)); }

// A history holding one edit of a fresh torus, as a patch or as a snapshot, and the torus after the edit.
struct RecordedEdit {
  History history;
  HalfedgeMesh after;
};

RecordedEdit record_edit(const std::function<void(HalfedgeMesh&)>& edit, bool as_snapshot) {
  RecordedEdit recorded;
  HalfedgeMesh mesh = torus();
  const HalfedgeMesh before = mesh;
  if (as_snapshot) {
    edit(mesh);
    recorded.history.record("edit", before);
  } else {
    ChangeJournal journal(mesh);
    edit(mesh);
    journal.detach();
    recorded.history.record("edit", make_patch(journal, mesh), before.version());
  }
  recorded.after = mesh;
  return recorded;
}

// Runs the step on a copy of `history` and `mesh` (the torus as `original` or `edited`) with the Nth allocation
// failing (and every later one with Later::Fail), for N = 1, 2, ... until the step no longer fails: each time the
// step is taken exactly or nothing changed, and the lists then still step the mesh between the two states.
void expect_all_or_nothing(const History& history, const HalfedgeMesh& mesh, bool forward, const HalfedgeMesh& original,
                           const HalfedgeMesh& edited, FailingAllocations::Later later) {
  for (size_t n = 1;; ++n) {
    SCOPED_TRACE(n);
    History h = history;
    HalfedgeMesh m = mesh;
    bool threw = false, failed = false;
    {
      const FailingAllocations failing(n, later);
      try {
        forward ? h.redo(m) : h.undo(m);
      } catch (const std::bad_alloc&) {
        threw = true;
      }
      failed = failing.failed();
    }
    EXPECT_EQ(threw, failed);  // nothing in a step swallows a failure
    if (threw) {
      EXPECT_TRUE(m.same_as(mesh));
      EXPECT_EQ(m.version(), mesh.version());
      EXPECT_EQ(h.undo_depth(), history.undo_depth());
      EXPECT_EQ(h.can_redo(), history.can_redo());
      EXPECT_EQ(h.undo_label(), history.undo_label());
      EXPECT_EQ(h.redo_label(), history.redo_label());
    } else {
      EXPECT_TRUE(m.same_as(forward ? edited : original));
      EXPECT_GT(m.version(), mesh.version());
      EXPECT_EQ(h.can_undo(), forward);
      EXPECT_EQ(h.can_redo(), !forward);
    }
    const bool at_edited = m.same_as(edited);
    ASSERT_TRUE(at_edited ? h.undo(m) : h.redo(m));
    EXPECT_TRUE(m.same_as(at_edited ? original : edited));
    if (!failed) {
      EXPECT_GT(n, 1u);  // the step allocates: at least one failure was tried
      return;
    }
  }
}

void expect_undo_and_redo_all_or_nothing(const std::function<void(HalfedgeMesh&)>& edit, bool as_snapshot) {
  const HalfedgeMesh original = torus();
  for (const auto later : {FailingAllocations::Later::Succeed, FailingAllocations::Later::Fail}) {
    SCOPED_TRACE(later == FailingAllocations::Later::Fail ? "memory stays short" : "one allocation fails");
    RecordedEdit recorded = record_edit(edit, as_snapshot);
    {
      SCOPED_TRACE("undo");
      expect_all_or_nothing(recorded.history, recorded.after, false, original, recorded.after, later);
    }
    SCOPED_TRACE("redo");
    HalfedgeMesh undone = recorded.after;
    ASSERT_TRUE(recorded.history.undo(undone));
    const HalfedgeMesh rebuilt = torus();  // tight arrays and no dead bits: redo must allocate both
    ASSERT_TRUE(rebuilt.same_as(undone));
    expect_all_or_nothing(recorded.history, rebuilt, true, original, recorded.after, later);
  }
}

TEST(HistoryOutOfMemory, SplitPatchUndoesAndRedoesAllOrNothing) {
  expect_undo_and_redo_all_or_nothing([](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(4)).ok()); }, false);
}

TEST(HistoryOutOfMemory, CollapsePatchUndoesAndRedoesAllOrNothing) {
  expect_undo_and_redo_all_or_nothing([](HalfedgeMesh& m) { ASSERT_TRUE(collapse(m, EdgeId(4)).ok()); }, false);
}

TEST(HistoryOutOfMemory, SnapshotUndoesAndRedoesAllOrNothing) {
  expect_undo_and_redo_all_or_nothing([](HalfedgeMesh& m) { ASSERT_TRUE(loop_subdivide(m).ok); }, true);
}

}  // namespace
}  // namespace meshedit
