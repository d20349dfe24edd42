// FieldChange: one line of a mesh diff, the unit the diff of two meshes (history.h diff()) and the diff of an undo
// patch (mesh_patch.h patch_diff()) both produce.
//
// Invariant: `before` / `after` are the field's values as text, "-" on the side where the slot does not exist.
#pragma once

#include <string>

#include "core/ids.h"

namespace meshedit {

// One changed field: (element, field, old, new), values printed with the id formatter ("h12", "b0", "-"
// for an invalid id), positions as "(0.5, 0, 1)" with each coordinate in the shortest form that reads back
// to the same double (value_format.h), liveness as "alive"/"dead".
struct FieldChange {
  ElementRef element;
  std::string field;  // "next" "twin" "vertex" "edge" "face" "halfedge" "position" "alive"
  std::string before;
  std::string after;
};

}  // namespace meshedit
