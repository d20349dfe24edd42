// Undo/redo by snapshots or patches, and the field-by-field diff of two meshes.
//
// The mesh is a copyable value and ids are never reused, so restoring a state restores every id exactly: pointer-table
// rows stay put, handles made before an operation stay valid after its undo, handles made after it read as dead.
// An entry is either a whole snapshot of the state before (any change) or a patch (mesh_patch.h: the slots an edit
// touched, before and after, for local edits): a patch is undone and redone in time proportional to the edit. Both
// kinds give the same meshes and the same version() numbers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/field_change.h"
#include "core/halfedge_mesh.h"
#include "core/mesh_patch.h"

namespace meshedit {

// Every field that differs between two states of one mesh, in order of kind (vertices, halfedges,
// edges, faces, boundaries), then id, then field in this order:
//   vertex: halfedge, position, alive     halfedge: next, twin, vertex, edge, face, alive
//   edge: halfedge, alive                 face, boundary: halfedge, alive
// Elements that exist only in `after` (created) list all their fields with before = "-". Dead elements are
// compared too (a change to a dead slot is still a change). Positions compare bit for bit. A slot only in
// `before` cannot happen for two states of one mesh since ids are not reused; if it does (arguments
// swapped), its fields are listed with after = "-".
std::vector<FieldChange> diff(const HalfedgeMesh& before, const HalfedgeMesh& after);

class History {
 public:
  // At most `max_depth` undo entries; and while they hold more than `max_bytes` in all (a snapshot its mesh's
  // memory_bytes(), a patch its slots), the oldest are dropped, but never below kMinDepth entries: a snapshot of a
  // huge mesh still gets a few steps, and small local edits get up to max_depth whatever the mesh's size.
  static constexpr size_t kMinDepth = 4;
  explicit History(size_t max_depth = 256, size_t max_bytes = SIZE_MAX)
      : max_depth_(max_depth), max_bytes_(max_bytes) {}

  // Records that an operation called `label` turned `before` into the current mesh. Clears redo, then drops the
  // oldest entries past the limits above.
  void record(std::string label, HalfedgeMesh before);
  // The same for an edit given as a patch from the state before to the current mesh; `version_before` is the
  // mesh's version() before the edit (what a snapshot would have carried).
  void record(std::string label, MeshPatch patch, uint64_t version_before);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  const std::string& undo_label() const;  // label of what undo would revert ("" if none)
  const std::string& redo_label() const;
  size_t undo_depth() const { return undo_.size(); }
  std::vector<std::string> undo_labels() const;  // of every entry undo can revert, the oldest first

  // Replaces `mesh` by the state before the last recorded operation; the replaced state goes to redo.
  // Returns false (and changes nothing) when there is nothing to undo. Afterwards mesh.version() is larger
  // than it was before the call and than the restored snapshot's own version. All or nothing, out of memory too: the
  // mesh and both lists as they were.
  bool undo(HalfedgeMesh& mesh);
  // The reverse of undo (same rules); record() empties the redo list.
  bool redo(HalfedgeMesh& mesh);
  // Empties both lists (allocates nothing); reset() also sets the limits, as the constructor does.
  void clear();
  void reset(size_t max_depth, size_t max_bytes);

  // The patch of the entry undo() (redo()) would apply next, or null when that entry is a snapshot or there is
  // none. Its direction is the original edit's: undo applies it backward, redo forward.
  const MeshPatch* undo_patch() const;
  const MeshPatch* redo_patch() const;
  // The snapshot of the entry undo() (redo()) would apply next, which is the state it restores, or null when that
  // entry is a patch or there is none.
  const HalfedgeMesh* undo_snapshot() const;
  const HalfedgeMesh* redo_snapshot() const;

 private:
  struct Entry {
    std::string label;
    std::optional<HalfedgeMesh> mesh;  // a snapshot of the state this entry restores, or
    std::optional<MeshPatch> patch;    // the edit between the two states (before -> after)
    uint64_t version = 0;              // with a patch: the version() a snapshot of the restored state would carry
  };
  // Moves `mesh` to the state `entry` restores; `entry` then describes the way back (for the other list).
  static void step(Entry& entry, HalfedgeMesh& mesh, bool forward);
  static size_t bytes_of(const Entry& entry);
  // Drops the oldest undo entries past max_depth_, and past max_bytes_ down to kMinDepth.
  void trim();
  size_t max_depth_;
  size_t max_bytes_;
  std::deque<Entry> undo_;
  std::vector<Entry> redo_;
};

}  // namespace meshedit
