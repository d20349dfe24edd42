// EdgeOperation: which of the three local operations on one edge (mesh_ops.h: flip, split, collapse) is meant, for
// code that must name the one that ran: the document's labels ("flip e5") and the window's animation of an edit.
// Plain names, no behaviour: the operations themselves are in mesh_ops.h.
#pragma once

namespace meshedit {

enum class EdgeOperation { Flip, Split, Collapse };

// The operation's verb as the labels and messages write it: "flip", "split", "collapse".
constexpr const char* edge_operation_verb(EdgeOperation operation) {
  switch (operation) {
    case EdgeOperation::Flip: return "flip";
    case EdgeOperation::Split: return "split";
    case EdgeOperation::Collapse: return "collapse";
  }
  return "flip";
}

}  // namespace meshedit
