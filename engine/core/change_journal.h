// ChangeJournal: records what an edit overwrites in a mesh, so the document can undo it, diff it and refuse it in
// time proportional to the edit instead of copying the whole mesh (mesh_patch.h turns a journal into an undo patch).
//
// Use: attach a journal to a mesh (the constructor), run the edit, then either revert() (a refused or throwing edit)
// or take the result: a patch (make_patch) or, after a fall-back, the full snapshot (take_snapshot). A journal whose
// fall-back ran out of memory has neither (state_before_lost): the edit cannot be undone, and its caller must say so.
//
// Invariants:
// - While attached, every write through the mesh's members logs the written slot's old values first (an append-only
//   log; the first entry of a slot holds its value before the edit). Slots appended by the edit are not logged:
//   they are the ids past the capacities the journal saw when it was attached.
// - Writes the journal cannot follow slot by slot (MeshStorage's direct array access, assigning to the mesh, moving
//   from it) and a log longer than `max_entries` make it fall back: it copies the mesh right then, reverts its log on
//   the copy, detaches and keeps that snapshot of the state before the edit.
// - A fall-back that cannot make its snapshot (std::bad_alloc: a mesh of millions of faces on a machine short of
//   memory) does not throw, since it may run inside the mesh's noexcept move: it drops the half-made snapshot and the
//   log, detaches and reports state_before_lost(). The mesh is left to the edit, untouched by the journal.
// - So a journal always yields exactly one of: (touched slots with their old values), (the whole state before), or,
//   after a failed fall-back, nothing (state_before_lost()).
// - revert() leaves the mesh exactly as it was when the journal was attached: contents, capacities, live counts,
//   version() and proven_valid_triangles(); except when state_before_lost(): then it leaves the mesh as the edit did
//   and returns false.
// - One journal per mesh at a time: attaching a second one (an edit nested in another) makes the first fall back to
//   its snapshot. The destructor detaches it. The journal is not copied with the mesh.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/halfedge_mesh.h"
#include "core/slot_values.h"

namespace meshedit {

class ChangeJournal {
 public:
  struct Entry {
    ElementKind kind;
    uint32_t slot;
    SlotValues old;  // the slot's values before this write
  };

  // Attaches to `mesh` (a journal already attached falls back first). The default cap: half the mesh's slots
  // (beyond that a snapshot is smaller than the log), at least 4096.
  explicit ChangeJournal(HalfedgeMesh& mesh, std::optional<size_t> max_entries = std::nullopt);
  ~ChangeJournal();
  ChangeJournal(const ChangeJournal&) = delete;
  ChangeJournal& operator=(const ChangeJournal&) = delete;

  // Stops listening to the mesh (the log and snapshot stay). Idempotent.
  void detach();
  bool attached() const;

  // True once the journal has fallen back to a full snapshot.
  bool has_snapshot() const { return snapshot_.has_value(); }
  // The state before the edit; only when has_snapshot(). take_snapshot() leaves the journal without it.
  const HalfedgeMesh& snapshot() const { return *snapshot_; }
  HalfedgeMesh take_snapshot();
  // True once a fall-back failed to make its snapshot (out of memory): no log, no snapshot, the edit cannot be undone.
  bool state_before_lost() const { return state_before_lost_; }

  // The log, in write order (empty after a fall-back), and what the mesh looked like when attached.
  const std::vector<Entry>& log() const { return log_; }
  const MeshShape& shape_before() const { return shape_before_; }
  uint64_t version_before() const { return version_before_; }

  // Detaches and puts the mesh back exactly as it was when the journal was attached. Returns false, leaving the mesh
  // as the edit left it, when state_before_lost().
  bool revert();

  // Called through the mesh's JournalLink: before one slot is written, and before a write it cannot follow.
  void note_write(ElementKind kind, uint32_t slot);
  void fall_back() noexcept;

  // How a fall-back copies the mesh: a plain copy. A test hook, the only way to make that copy fail on demand: tests
  // point it at a copier that throws std::bad_alloc (tests/support/failing_snapshots.h, which puts the copy back).
  // Nothing else sets it, and no test sets it while another thread may fall back.
  using SnapshotCopier = HalfedgeMesh (*)(const HalfedgeMesh&);
  static SnapshotCopier snapshot_copier;

 private:
  // Writes the logged old values back into `target` (newest first) and restores the shape and versions.
  void undo_log(HalfedgeMesh& target) const;

  HalfedgeMesh* mesh_;
  MeshShape shape_before_;
  uint64_t version_before_;
  uint64_t proven_before_;
  size_t max_entries_;
  std::vector<Entry> log_;
  std::optional<HalfedgeMesh> snapshot_;
  bool state_before_lost_ = false;
};

}  // namespace meshedit
