// MeshPatch: one edit as the slots it touched, each with its values before and after, plus the mesh's shape before
// and after. Undo applies it backward, redo forward, in time proportional to the edit; its field diff equals core
// diff() of the two states (history.h), in the same order and text.
//
// Invariants:
// - `slots` is sorted by (kind in ElementKind order, slot), each slot once, and holds every slot whose values differ
//   between the two states: touched slots that existed before, and every slot appended by the edit. A slot exists
//   in a state when it is below that state's capacity of its kind; `before` / `after` of a slot that does not exist
//   in that state are unused.
// - apply() sets the shape first, then writes only slots below the target state's capacities, so it never writes
//   outside the arrays, whatever mesh it is given; on the state it was made from it gives the other state exactly
//   (contents and live counts). It does not touch version(): History and the document set it.
// - apply() allocates only before its first write, so out of memory it keeps the rule of docs/ARCHITECTURE.md
//   (Memory running out); once it writes, it finishes. So an undo or redo never stops half-way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/change_journal.h"
#include "core/field_change.h"
#include "core/halfedge_mesh.h"
#include "core/slot_values.h"

namespace meshedit {

struct SlotChange {
  ElementKind kind;
  uint32_t slot;
  SlotValues before;
  SlotValues after;
};

// The order of MeshPatch::slots as one number: by kind (ElementKind order), then slot.
inline uint64_t slot_key(ElementKind kind, uint32_t slot) { return (uint64_t(kind) << 32) | slot; }
inline uint64_t slot_key(const SlotChange& change) { return slot_key(change.kind, change.slot); }

struct MeshPatch {
  MeshShape shape_before;
  MeshShape shape_after;
  std::vector<SlotChange> slots;

  // The same change the other way round (before and after swapped).
  MeshPatch reversed() const;
  // Turns a mesh in the `before` state into the `after` state (forward) or the reverse; all or nothing (above).
  void apply(HalfedgeMesh& mesh, bool forward) const;
  // Makes the forward change on `mesh` as an edit would, through its setters, new_* and delete_element, so a journal
  // attached to it logs the change slot by slot (apply() writes the arrays directly, which makes a journal fall back
  // to a copy of the mesh). Afterwards the mesh is in the `after` state (contents and live counts; its version moves
  // on as with any edit). Returns false, having changed nothing, when the patch cannot be made that way: `mesh` is
  // not in the `before` state where the patch says anything (shape, listed slots), a capacity shrinks, or a dead slot
  // comes back to life (no setter revives one). Patches that make_patch takes from setter edits always pass. Out of
  // memory, throws std::bad_alloc part-way, like any edit (an attached journal can revert it).
  bool apply_as_edit(HalfedgeMesh& mesh) const;
};

// The patch from the state the journal saw when it was attached to `mesh` as it is now. The journal must not have
// fallen back (to a snapshot, or to nothing: state_before_lost). O(log length * log(log length)) plus the appended
// slots.
MeshPatch make_patch(const ChangeJournal& journal, const HalfedgeMesh& mesh);

// diff(before, after) of the patch's two states (history.h), computed from the patch alone.
std::vector<FieldChange> patch_diff(const MeshPatch& patch);
// diff(...).size() of the patch, or some number above `limit` once the count passes it.
size_t patch_change_count(const MeshPatch& patch, size_t limit);

}  // namespace meshedit
