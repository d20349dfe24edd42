// EditJournal: the undo history behind a script's mesh:undo() and mesh:redo(), for one mesh.
//
// Whole operations (flip, split, collapse, loop_subdivide, restore) are the undo points. Instead of a copy of
// the mesh per operation, the journal keeps one copy (the base, taken at the first operation) and every change
// made since, and undoes by replaying the changes up to the operation: an operation costs one small record, so
// a script can run thousands of them on a large mesh.
//
// Invariants:
// - While active, base + edits[0, applied) is the mesh's current state, and mesh.version() equals the version
//   the journal last saw. A change made past the journal (the host editing the mesh between two calls, another
//   Lua state) shows as another version: the journal is then dropped, never replayed onto the wrong state.
// - A change made after an undo discards what redo could have brought back (as in any editor).
// - At most max_edits changes are kept; one more drops the journal (the history is lost, not the mesh).
// - undo and redo change the mesh only when they return a label, and leave its version above every version it
//   had before.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"

namespace meshedit {

class EditJournal {
 public:
  static constexpr size_t kDefaultMaxEdits = size_t(1) << 18;

  explicit EditJournal(size_t max_edits = kDefaultMaxEdits) : max_edits_(max_edits) {}

  // Call before every change to the mesh. `operation` marks an undo point: with no journal running, it starts
  // one from a copy of the mesh as it is now.
  void before_change(const HalfedgeMesh& mesh, bool operation);
  // Call after the change with its record (an Operation edit is an undo point). Ignored while inactive.
  void after_change(const HalfedgeMesh& mesh, RecordedEdit edit);

  // Puts the mesh back as it was before the last operation in effect; returns that operation ("flip e3"), or
  // nothing (and changes nothing) when there is none.
  std::optional<std::string> undo(HalfedgeMesh& mesh);
  // Brings back the state the last undo left; nothing when there is nothing to redo.
  std::optional<std::string> redo(HalfedgeMesh& mesh);

  bool active() const { return base_ != nullptr; }
  size_t size() const { return edits_.size(); }
  // Bytes of the base copy (0 while inactive).
  size_t base_bytes() const { return base_ ? base_->memory_bytes() : 0; }

 private:
  void drop();
  // False (after dropping the journal) when the mesh changed past the journal.
  bool follows(const HalfedgeMesh& mesh);

  size_t max_edits_;
  std::unique_ptr<HalfedgeMesh> base_;
  std::vector<RecordedEdit> edits_;
  size_t applied_ = 0;              // edits in effect; below edits_.size() after an undo
  std::vector<size_t> operations_;  // indices of the Operation edits, ascending
  std::vector<size_t> redo_;        // values of applied_ that redo returns to, last first
  uint64_t version_ = 0;
};

}  // namespace meshedit
