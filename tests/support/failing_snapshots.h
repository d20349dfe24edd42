// FailingSnapshots: while one is alive, every change-journal fall-back fails as if copying the mesh ran out of memory
// (ChangeJournal::snapshot_copier throws std::bad_alloc), deterministically and without exhausting anything; the copier
// it replaced comes back when it goes. One at a time, on the test's own thread (the hook is a plain static).
#pragma once

#include <new>

#include "core/change_journal.h"

namespace meshedit::testing {

class FailingSnapshots {
 public:
  FailingSnapshots() : replaced_(ChangeJournal::snapshot_copier) { ChangeJournal::snapshot_copier = fail; }
  ~FailingSnapshots() { ChangeJournal::snapshot_copier = replaced_; }
  FailingSnapshots(const FailingSnapshots&) = delete;
  FailingSnapshots& operator=(const FailingSnapshots&) = delete;

 private:
  static HalfedgeMesh fail(const HalfedgeMesh&) { throw std::bad_alloc(); }
  ChangeJournal::SnapshotCopier replaced_;
};

}  // namespace meshedit::testing
