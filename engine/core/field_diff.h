// The comparison and text of one field in a diff (history.h FieldChange), shared by diff() of two meshes
// (history.cpp) and the diff of an undo patch (mesh_patch.cpp), so both list a change in the same words.
//
// Invariants: values compare raw (positions bit for bit, so -0 vs 0 and NaN payloads count as changes); ids print
// with the id formatter, positions with format_position, liveness as "alive"/"dead", and a side without the slot
// as "-".
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include "core/field_change.h"
#include "core/halfedge_mesh.h"
#include "core/value_format.h"

namespace meshedit::field_diff {

template <class T>
bool same(const T& a, const T& b) {
  return a == b;
}
inline bool same(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof(glm::dvec3)) == 0; }

template <ElementKind K>
std::string show(Id<K> id) {
  return format_id(id);
}
inline std::string show(FaceId f) { return format_id(f); }
inline std::string show(const glm::dvec3& p) { return format_position(p); }
inline std::string show(bool alive) { return alive ? "alive" : "dead"; }

// Appends the change of one field of one slot; `before` / `after` are null when the slot does not exist in that
// state.
template <class T>
void compare(std::vector<FieldChange>& out, ElementRef element, const char* field, const T* before, const T* after) {
  if (before && after) {
    if (!same(*before, *after)) out.push_back({element, field, show(*before), show(*after)});
  } else if (after) {
    out.push_back({element, field, "-", show(*after)});
  } else if (before) {
    out.push_back({element, field, show(*before), "-"});
  }
}

}  // namespace meshedit::field_diff
