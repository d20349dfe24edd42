// StateBefore: the mesh as it was before an edit, read through the edit's patch (mesh_patch.h) and the mesh after it,
// with HalfedgeMesh's read functions. Code that must look at both states of a local edit (the patch check, the
// renderer's in-place update) reads the state before here instead of from a copy of the whole mesh.
//
// Invariants:
// - A slot the patch lists reads its `before` values, any other slot its values in `after` (the two states agree
//   there). So the view is exact when `after` is the state the patch ends in (patch_check.h's patch_ends_in checks
//   that; the document's patches always are).
// - Capacities and live counts are the patch's shape_before. alive() is false past them, for invalid ids and for any
//   id of a kind the state before has fewer of; the other functions expect an id below the capacity of its kind, as
//   HalfedgeMesh's do.
// - A lookup costs a binary search in the patch's slots (sorted by kind, then slot); nothing is copied.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"
#include "core/mesh_patch.h"

namespace meshedit {

class StateBefore {
 public:
  StateBefore(const HalfedgeMesh& after, const MeshPatch& patch) : after_(after), patch_(patch) {}

  uint32_t capacity(ElementKind kind) const { return patch_.shape_before.capacity[int(kind)]; }
  uint32_t vertex_capacity() const { return capacity(ElementKind::Vertex); }
  uint32_t halfedge_capacity() const { return capacity(ElementKind::Halfedge); }
  uint32_t edge_capacity() const { return capacity(ElementKind::Edge); }
  uint32_t face_capacity() const { return capacity(ElementKind::Face); }
  uint32_t boundary_capacity() const { return capacity(ElementKind::Boundary); }
  size_t live(ElementKind kind) const { return patch_.shape_before.live[int(kind)]; }
  size_t num_vertices() const { return live(ElementKind::Vertex); }
  size_t num_halfedges() const { return live(ElementKind::Halfedge); }
  size_t num_edges() const { return live(ElementKind::Edge); }
  size_t num_faces() const { return live(ElementKind::Face); }

  bool alive(ElementRef element) const {
    if (!element.valid() || element.index >= capacity(element.kind)) return false;
    if (const SlotChange* change = find(element.kind, element.index)) return change->before.alive;
    return after_.alive(element);  // an unlisted slot below the capacity before is below the one after too
  }
  bool alive(VertexId v) const { return alive(ElementRef(v)); }
  bool alive(HalfedgeId h) const { return alive(ElementRef(h)); }
  bool alive(EdgeId e) const { return alive(ElementRef(e)); }
  bool alive(FaceId f) const { return alive(ElementRef(f)); }

  HalfedgeRecord record(HalfedgeId h) const {
    const SlotChange* change = find(ElementKind::Halfedge, h.index);
    return change ? change->before.record : after_.record(h);
  }
  HalfedgeId next(HalfedgeId h) const { return record(h).next; }
  HalfedgeId twin(HalfedgeId h) const { return record(h).twin; }
  VertexId vertex(HalfedgeId h) const { return record(h).vertex; }
  EdgeId edge(HalfedgeId h) const { return record(h).edge; }
  FaceId face(HalfedgeId h) const { return record(h).face; }

  HalfedgeId halfedge(ElementRef element) const {
    if (const SlotChange* change = find(element.kind, element.index)) return change->before.halfedge;
    switch (element.kind) {
      case ElementKind::Vertex: return after_.halfedge(VertexId(element.index));
      case ElementKind::Edge: return after_.halfedge(EdgeId(element.index));
      default: return after_.halfedge(element.face_id());
    }
  }
  HalfedgeId halfedge(VertexId v) const { return halfedge(ElementRef(v)); }
  HalfedgeId halfedge(EdgeId e) const { return halfedge(ElementRef(e)); }
  HalfedgeId halfedge(FaceId f) const { return halfedge(ElementRef(f)); }

  const glm::dvec3& position(VertexId v) const {
    const SlotChange* change = find(ElementKind::Vertex, v.index);
    return change ? change->before.position : after_.position(v);
  }

 private:
  const SlotChange* find(ElementKind kind, uint32_t slot) const {
    const auto less = [](const SlotChange& c, uint64_t key) { return slot_key(c) < key; };
    const auto it = std::lower_bound(patch_.slots.begin(), patch_.slots.end(), slot_key(kind, slot), less);
    return it != patch_.slots.end() && it->kind == kind && it->slot == slot ? &*it : nullptr;
  }

  const HalfedgeMesh& after_;
  const MeshPatch& patch_;
};

}  // namespace meshedit
