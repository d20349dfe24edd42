// Undo/redo by snapshots, and the field-by-field diff of two meshes.
//
// The mesh is a copyable value and ids are never reused, so restoring a snapshot restores every id
// exactly: pointer-table rows stay put, handles made before an operation stay valid after its undo,
// handles made after it read as dead.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "core/halfedge_mesh.h"

namespace meshedit {

// One changed field: (element, field, old, new), values printed with the id formatter ("h12", "b0", "-"
// for an invalid id), positions as "(0.5, 0, 1)" with each coordinate in the shortest form that reads back
// to the same double (value_format.h), liveness as "alive"/"dead".
struct FieldChange {
  ElementRef element;
  std::string field;   // "next" "twin" "vertex" "edge" "face" "halfedge" "position" "alive"
  std::string before;
  std::string after;
};

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
  explicit History(size_t max_depth = 256) : max_depth_(max_depth) {}

  // Records that an operation called `label` turned `before` into the current mesh. Clears redo.
  // When more than max_depth entries are kept, the oldest is dropped.
  void record(std::string label, HalfedgeMesh before);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  const std::string& undo_label() const;  // label of what undo would revert ("" if none)
  const std::string& redo_label() const;
  size_t undo_depth() const { return undo_.size(); }

  // Replaces `mesh` by the state before the last recorded operation; the replaced state goes to redo.
  // Returns false (and changes nothing) when there is nothing to undo. Afterwards mesh.version() is larger
  // than it was before the call and than the restored snapshot's own version.
  bool undo(HalfedgeMesh& mesh);
  // The reverse of undo (same rules); record() empties the redo list.
  bool redo(HalfedgeMesh& mesh);
  void clear();

 private:
  struct Entry {
    std::string label;
    HalfedgeMesh mesh;
  };
  size_t max_depth_;
  std::deque<Entry> undo_;
  std::vector<Entry> redo_;
};

}  // namespace meshedit
