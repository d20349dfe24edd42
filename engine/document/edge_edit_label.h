// The labels the document keeps for a flip, split or collapse of one edge ("flip e5": document_actions.h makes them
// with edge_edit_label) and for their undo and redo ("undo flip e5", "redo flip e5": mesh_document.h puts the word in
// front), read back into the operation and the edge they name. The window reads `doc.last.label` this way to know
// which operation its last change was (to animate it) without keeping a second record of the edits.
//
// Invariants:
// - read_edge_edit_label(edge_edit_label(op, e)) names op and e, played forward; with "redo " in front, the same;
//   with "undo " in front, the same undone. Anything else (a console line, Loop subdivision, an exercise's run, a
//   label with more or less text) reads as nullopt.
// - Neither function looks at a mesh: the edge may be dead or out of range; whoever uses it checks.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/edge_operation.h"
#include "core/ids.h"

namespace meshedit {

struct EdgeEditLabel {
  EdgeOperation operation = EdgeOperation::Flip;
  EdgeId edge;
  bool undone = false;  // the label is an undo's: the change went from the operation's result back to its start
};

// "flip e5", "split e5", "collapse e5". Allocates (std::bad_alloc when memory runs out).
std::string edge_edit_label(EdgeOperation operation, EdgeId edge);
// What the label names, or nullopt when it is not one of the forms above. Allocates nothing.
std::optional<EdgeEditLabel> read_edge_edit_label(std::string_view label);

}  // namespace meshedit
