// Making and reading the labels of flip, split and collapse (see edge_edit_label.h).
#include "document/edge_edit_label.h"

namespace meshedit {
namespace {

// Removes `prefix` from the front of `text`; false (text unchanged) when it is not there.
bool take_prefix(std::string_view& text, std::string_view prefix) {
  if (text.substr(0, prefix.size()) != prefix) return false;
  text.remove_prefix(prefix.size());
  return true;
}

}  // namespace

std::string edge_edit_label(EdgeOperation operation, EdgeId edge) {
  return std::string(edge_operation_verb(operation)) + " " + format_id(edge);
}

std::optional<EdgeEditLabel> read_edge_edit_label(std::string_view label) {
  EdgeEditLabel read;
  if (take_prefix(label, "undo ")) read.undone = true;
  else take_prefix(label, "redo ");
  bool named = false;
  for (const EdgeOperation operation : {EdgeOperation::Flip, EdgeOperation::Split, EdgeOperation::Collapse}) {
    std::string_view rest = label;
    if (take_prefix(rest, edge_operation_verb(operation)) && take_prefix(rest, " ")) {
      read.operation = operation;
      label = rest;
      named = true;
      break;
    }
  }
  if (!named) return std::nullopt;
  const std::optional<ElementRef> edge = parse_element(label);
  if (!edge || edge->kind != ElementKind::Edge) return std::nullopt;
  read.edge = EdgeId(edge->index);
  return read;
}

}  // namespace meshedit
