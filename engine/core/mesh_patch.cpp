// MeshPatch: made from a change journal, applied both ways, diffed (see mesh_patch.h for the invariants).
#include "core/mesh_patch.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include "core/field_diff.h"

namespace meshedit {
namespace {

int index_of(ElementKind kind) { return static_cast<int>(kind); }

bool exists(const MeshShape& shape, const SlotChange& s) { return s.slot < shape.capacity[index_of(s.kind)]; }

// for_each_field over one changed slot, with the states where the slot exists.
template <class Add>
void for_each_field(const MeshPatch& patch, const SlotChange& s, Add&& add) {
  field_diff::for_each_field(s.kind, s.slot, exists(patch.shape_before, s) ? &s.before : nullptr,
                             exists(patch.shape_after, s) ? &s.after : nullptr, add);
}

}  // namespace

MeshPatch MeshPatch::reversed() const {
  MeshPatch r;
  r.shape_before = shape_after;
  r.shape_after = shape_before;
  r.slots.reserve(slots.size());
  for (const SlotChange& s : slots) r.slots.push_back({s.kind, s.slot, s.after, s.before});
  return r;
}

void MeshPatch::apply(HalfedgeMesh& mesh, bool forward) const {
  const MeshShape& target = forward ? shape_after : shape_before;
  reserve_shape(mesh, target);  // the only step that allocates, and it changes no value
  set_shape(mesh, target);
  for (const SlotChange& s : slots) {
    if (exists(target, s)) write_slot(mesh, s.kind, s.slot, forward ? s.after : s.before);
  }
}

bool MeshPatch::apply_as_edit(HalfedgeMesh& mesh) const {
  const MeshShape shape = shape_of(mesh);
  size_t appended[kElementKindCount] = {};
  for (int k = 0; k < kElementKindCount; ++k) {
    if (shape.capacity[k] != shape_before.capacity[k] || shape.live[k] != shape_before.live[k] ||
        shape_after.capacity[k] < shape_before.capacity[k]) {
      return false;
    }
  }
  for (size_t i = 0; i < slots.size(); ++i) {
    const SlotChange& s = slots[i];
    if (i > 0 && !(slot_key(slots[i - 1]) < slot_key(s)))
      return false;  // sorted, each slot once: appends come in order
    if (!exists(shape_after, s)) return false;
    if (!exists(shape_before, s)) {
      ++appended[index_of(s.kind)];
    } else if (!same_state(read_slot(mesh, s.kind, s.slot), s.before) || (!s.before.alive && s.after.alive)) {
      return false;
    }
  }
  for (int k = 0; k < kElementKindCount; ++k) {
    if (appended[k] != shape_after.capacity[k] - shape_before.capacity[k]) return false;
  }

  for (const SlotChange& s : slots) {
    const SlotValues& v = s.after;
    switch (s.kind) {
      case ElementKind::Vertex: {
        const VertexId id = exists(shape_before, s) ? VertexId(s.slot) : mesh.new_vertex(v.position);
        mesh.set_position(id, v.position);
        mesh.set_halfedge(id, v.halfedge);
        if (!v.alive) mesh.delete_element(id);
        break;
      }
      case ElementKind::Halfedge: {
        const HalfedgeId id = exists(shape_before, s) ? HalfedgeId(s.slot) : mesh.new_halfedge();
        mesh.set_neighbors(id, v.record.next, v.record.twin, v.record.vertex, v.record.edge, v.record.face);
        if (!v.alive) mesh.delete_element(id);
        break;
      }
      case ElementKind::Edge: {
        const EdgeId id = exists(shape_before, s) ? EdgeId(s.slot) : mesh.new_edge();
        mesh.set_halfedge(id, v.halfedge);
        if (!v.alive) mesh.delete_element(id);
        break;
      }
      case ElementKind::Face:
      case ElementKind::Boundary: {
        const bool boundary = s.kind == ElementKind::Boundary;
        const FaceId id = exists(shape_before, s) ? (boundary ? FaceId::boundary(s.slot) : FaceId::face(s.slot))
                                                  : (boundary ? mesh.new_boundary() : mesh.new_face());
        mesh.set_halfedge(id, v.halfedge);
        if (!v.alive) mesh.delete_element(id);
        break;
      }
    }
  }
  return true;
}

MeshPatch make_patch(const ChangeJournal& journal, const HalfedgeMesh& mesh) {
  MeshPatch patch;
  patch.shape_before = journal.shape_before();
  patch.shape_after = shape_of(mesh);
  // The first log entry of each slot holds its value before the edit: a stable sort by slot puts it first.
  const std::vector<ChangeJournal::Entry>& log = journal.log();
  auto key = [&](uint32_t i) { return slot_key(log[i].kind, log[i].slot); };
  std::vector<uint32_t> order(log.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
  size_t next = 0;
  for (int k = 0; k < kElementKindCount; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    // Touched slots that existed before (all below the old capacity), then the appended ones, keeps slot order.
    for (; next < order.size() && log[order[next]].kind == kind; ++next) {
      const ChangeJournal::Entry& first = log[order[next]];
      while (next + 1 < order.size() && key(order[next + 1]) == key(order[next])) ++next;
      const SlotValues after = read_slot(mesh, kind, first.slot);
      if (!same_state(first.old, after)) patch.slots.push_back({kind, first.slot, first.old, after});
    }
    const uint32_t old_capacity = patch.shape_before.capacity[k], new_capacity = patch.shape_after.capacity[k];
    for (uint32_t slot = old_capacity; slot < new_capacity; ++slot) {
      patch.slots.push_back({kind, slot, SlotValues{}, read_slot(mesh, kind, slot)});
    }
  }
  return patch;
}

std::vector<FieldChange> patch_diff(const MeshPatch& patch) {
  std::vector<FieldChange> out;
  for (const SlotChange& s : patch.slots) {
    for_each_field(patch, s, [&](ElementRef element, const char* name, const auto* before, const auto* after) {
      field_diff::compare(out, element, name, before, after);
    });
  }
  return out;
}

size_t patch_change_count(const MeshPatch& patch, size_t limit) {
  size_t count = 0;
  for (const SlotChange& s : patch.slots) {
    for_each_field(patch, s, [&](ElementRef, const char*, const auto* before, const auto* after) {
      if (before && after) count += !field_diff::same(*before, *after);
      else count += before || after;
    });
    if (count > limit) return count;
  }
  return count;
}

}  // namespace meshedit
