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
#include "core/slot_values.h"
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

// Calls add(element, field, before, after) for each field of one slot, in diff()'s order (history.h); `before` /
// `after` point to the field's value in that state, or are null where the slot does not exist. The one list of the
// fields a diff shows, for the diff of two meshes and of an undo patch alike.
template <class Add>
void for_each_field(ElementKind kind, uint32_t slot, const SlotValues* a, const SlotValues* b, Add&& add) {
  auto field = [&](ElementRef element, const char* name, auto member) {
    add(element, name, a ? &(a->*member) : nullptr, b ? &(b->*member) : nullptr);
  };
  auto record_field = [&](ElementRef element, const char* name, auto member) {
    add(element, name, a ? &(a->record.*member) : nullptr, b ? &(b->record.*member) : nullptr);
  };
  switch (kind) {
    case ElementKind::Vertex: {
      const ElementRef v(VertexId{slot});
      field(v, "halfedge", &SlotValues::halfedge);
      field(v, "position", &SlotValues::position);
      field(v, "alive", &SlotValues::alive);
      break;
    }
    case ElementKind::Halfedge: {
      const ElementRef h(HalfedgeId{slot});
      record_field(h, "next", &HalfedgeRecord::next);
      record_field(h, "twin", &HalfedgeRecord::twin);
      record_field(h, "vertex", &HalfedgeRecord::vertex);
      record_field(h, "edge", &HalfedgeRecord::edge);
      record_field(h, "face", &HalfedgeRecord::face);
      field(h, "alive", &SlotValues::alive);
      break;
    }
    case ElementKind::Edge: {
      const ElementRef e(EdgeId{slot});
      field(e, "halfedge", &SlotValues::halfedge);
      field(e, "alive", &SlotValues::alive);
      break;
    }
    case ElementKind::Face:
    case ElementKind::Boundary: {
      const ElementRef f(kind == ElementKind::Boundary ? FaceId::boundary(slot) : FaceId::face(slot));
      field(f, "halfedge", &SlotValues::halfedge);
      field(f, "alive", &SlotValues::alive);
      break;
    }
  }
}

}  // namespace meshedit::field_diff
