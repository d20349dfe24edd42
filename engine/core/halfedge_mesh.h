// HalfedgeMesh: the teaching half-edge structure, stored as flat arrays indexed by typed ids.
//
// Every pointer a student reasons about is stored explicitly (no implicit twin = h^1), so the pointer
// tables show exactly what is in memory and a script can break any of them.
//
// Invariants of the storage (kept by this class, whatever the connectivity says):
// - Ids are indices into the arrays below and are never reused: new elements are appended, deletion
//   only clears the element's `alive` flag (a tombstone; alive_flags.h: no bytes while nothing of a kind has
//   died). `alive(id)` is false for ids past the end, so ids from "the future" (after an undo) read as dead
//   rather than crashing.
// - Faces and boundary loops live in separate arrays; a FaceId's boundary bit says which (ids.h).
// - `h.vertex` is the vertex the halfedge LEAVES (its tail), as in the course code. Seen from outside (the side
//   the faces' normals point to; primitives.h makes every face outward), `next` goes counter-clockwise around a
//   face, and the step h -> twin(h).next, from one halfedge leaving a vertex to the next, turns clockwise around
//   that vertex.
// - A boundary vertex's `halfedge` is its outgoing halfedge on the boundary loop, when the mesh was built
//   here or edited by the core's operations.
// - The class never follows pointers on its own except in the bounded walks below, which stop after
//   `halfedge_capacity()` steps, so a broken mesh can be inspected without hanging.
// - Every mutation bumps `version()`, so caches (GPU buffers, tables) know when to refresh. Every mutation but
//   set_position also drops the triangle rows (triangle_rows.h) a Loop subdivision left, which describe the
//   connectivity they were made from.
// - While a ChangeJournal is attached (change_journal.h; off by default), every mutating member first reports the
//   slot it is about to write, and every wholesale replacement (assignment, being moved from, MeshStorage's direct
//   array access) makes the journal take a full snapshot first (out of memory, the journal gives up the state before
//   instead of throwing: moves stay noexcept). Without a journal that costs one branch per write.
//   The journal is not part of the value: a copy of a mesh has none.
//
// Connectivity invariants (twin of twin, closed face cycles, ...) are NOT enforced here: check them with
// validate() (validate.h). The mesh is a plain copyable value; history.h keeps copies or patches for undo.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/alive_flags.h"
#include "core/ids.h"
#include "core/mesh_array.h"
#include "core/triangle_rows.h"

namespace meshedit {

// Resizes `a` to `n` leaving the new elements' bytes unset (MeshArray::resize_for_overwrite): for a caller that
// writes every one of them before reading any.
template <class T>
void resize_for_overwrite(MeshArray<T>& a, size_t n) {
  a.resize_for_overwrite(n);
}

// Iterates the live ids of one kind; the end is fixed when the range is made, so elements appended
// during the loop are not visited (the "only split the original edges" rule of Loop subdivision).
template <class IdT>
class AliveRange {
 public:
  class Iterator {
   public:
    Iterator(const AliveFlags* alive, uint32_t i, uint32_t end, uint32_t tag)
        : alive_(alive), i_(i), end_(end), tag_(tag) {
      skip();
    }
    IdT operator*() const { return IdT(i_ | tag_); }
    Iterator& operator++() {
      ++i_;
      skip();
      return *this;
    }
    bool operator!=(const Iterator& o) const { return i_ != o.i_; }
    bool operator==(const Iterator& o) const { return i_ == o.i_; }

   private:
    void skip() {
      while (i_ < end_ && !(*alive_)[i_]) ++i_;
    }
    const AliveFlags* alive_;
    uint32_t i_, end_, tag_;
  };
  AliveRange(const AliveFlags* alive, uint32_t tag = 0)
      : alive_(alive), end_(static_cast<uint32_t>(alive->size())), tag_(tag) {}
  Iterator begin() const { return Iterator(alive_, 0, end_, tag_); }
  Iterator end() const { return Iterator(alive_, end_, end_, tag_); }

 private:
  const AliveFlags* alive_;
  uint32_t end_, tag_;
};

struct MeshStorage;
class ChangeJournal;

// The journal a mesh reports its writes to, or none (change_journal.h). Not part of the mesh's value: a copy starts
// without one. Declared as the mesh's first member, so in the mesh's assignment it runs before any array is
// replaced: a journaled mesh whose contents are about to be replaced (assigned to) or emptied (moved from) tells its
// journal first, which takes a full snapshot of the state before the change and detaches (or, when the snapshot
// cannot be allocated, detaches and reports the state before lost: nothing throws here).
class JournalLink {
 public:
  JournalLink() = default;
  JournalLink(const JournalLink&) noexcept {}
  JournalLink(JournalLink&& from) noexcept { from.before_bulk_write(); }
  JournalLink& operator=(const JournalLink&) {
    before_bulk_write();
    return *this;
  }
  JournalLink& operator=(JournalLink&& from) noexcept {
    before_bulk_write();
    from.before_bulk_write();
    return *this;
  }

  // Before a write of one slot (kind, slot): the journal logs the slot's old values.
  void before_write(ElementKind kind, uint32_t slot) {
    if (journal_) [[unlikely]]
      note_write(kind, slot);
  }
  // Before a write the journal cannot follow slot by slot.
  void before_bulk_write() noexcept {
    if (journal_) [[unlikely]]
      fall_back();
  }

 private:
  friend struct MeshStorage;
  void note_write(ElementKind kind, uint32_t slot);  // change_journal.cpp
  void fall_back() noexcept;                         // change_journal.cpp
  ChangeJournal* journal_ = nullptr;
};

// The five pointers of one halfedge, stored together: a walk reads one cache line per halfedge, not five.
struct HalfedgeRecord {
  HalfedgeId next;  // h.next
  HalfedgeId twin;  // h.twin
  VertexId vertex;  // h.vertex (tail)
  EdgeId edge;      // h.edge
  FaceId face;      // h.face (a face or a boundary loop)
  friend bool operator==(const HalfedgeRecord&, const HalfedgeRecord&) = default;
};

class HalfedgeMesh {
 public:
  // ---- counts -------------------------------------------------------------------------------------
  // Live elements.
  size_t num_vertices() const { return live_vertices_; }
  size_t num_halfedges() const { return live_halfedges_; }
  size_t num_edges() const { return live_edges_; }
  size_t num_faces() const { return live_faces_; }  // real faces, boundary loops excluded
  size_t num_boundaries() const { return live_boundaries_; }
  // Slots ever allocated (live + dead): the id range of each kind.
  uint32_t vertex_capacity() const { return static_cast<uint32_t>(v_alive_.size()); }
  uint32_t halfedge_capacity() const { return static_cast<uint32_t>(h_alive_.size()); }
  uint32_t edge_capacity() const { return static_cast<uint32_t>(e_alive_.size()); }
  uint32_t face_capacity() const { return static_cast<uint32_t>(f_alive_.size()); }
  uint32_t boundary_capacity() const { return static_cast<uint32_t>(b_alive_.size()); }
  uint32_t capacity(ElementKind kind) const;

  // ---- liveness -----------------------------------------------------------------------------------
  bool alive(VertexId v) const { return v.index < v_alive_.size() && v_alive_[v.index]; }
  bool alive(HalfedgeId h) const { return h.index < h_alive_.size() && h_alive_[h.index]; }
  bool alive(EdgeId e) const { return e.index < e_alive_.size() && e_alive_[e.index]; }
  bool alive(FaceId f) const {
    if (!f.valid()) return false;
    const auto& flags = f.is_boundary() ? b_alive_ : f_alive_;
    return f.slot() < flags.size() && flags[f.slot()];
  }
  bool alive(ElementRef r) const;

  // ---- the pointers (precondition: the element is live or at least allocated) ---------------------
  HalfedgeId next(HalfedgeId h) const { return h_[h.index].next; }
  HalfedgeId twin(HalfedgeId h) const { return h_[h.index].twin; }
  VertexId vertex(HalfedgeId h) const { return h_[h.index].vertex; }  // the vertex h leaves
  EdgeId edge(HalfedgeId h) const { return h_[h.index].edge; }
  FaceId face(HalfedgeId h) const { return h_[h.index].face; }
  HalfedgeId halfedge(VertexId v) const { return v_halfedge_[v.index]; }  // some outgoing halfedge
  HalfedgeId halfedge(EdgeId e) const { return e_halfedge_[e.index]; }
  HalfedgeId halfedge(FaceId f) const { return f.is_boundary() ? b_halfedge_[f.slot()] : f_halfedge_[f.slot()]; }
  const glm::dvec3& position(VertexId v) const { return v_position_[v.index]; }
  // All five pointers of h at once (whole-mesh passes prefetch it).
  const HalfedgeRecord& record(HalfedgeId h) const { return h_[h.index]; }

  void set_next(HalfedgeId h, HalfedgeId next) {
    log_write(h);
    h_[h.index].next = next;
    touch();
  }
  void set_twin(HalfedgeId h, HalfedgeId twin) {
    log_write(h);
    h_[h.index].twin = twin;
    touch();
  }
  void set_vertex(HalfedgeId h, VertexId v) {
    log_write(h);
    h_[h.index].vertex = v;
    touch();
  }
  void set_edge(HalfedgeId h, EdgeId e) {
    log_write(h);
    h_[h.index].edge = e;
    touch();
  }
  void set_face(HalfedgeId h, FaceId f) {
    log_write(h);
    h_[h.index].face = f;
    touch();
  }
  // The course's Halfedge::setNeighbors, with its argument order.
  void set_neighbors(HalfedgeId h, HalfedgeId next, HalfedgeId twin, VertexId vertex, EdgeId edge, FaceId face);
  void set_halfedge(VertexId v, HalfedgeId h) {
    log_write(v);
    v_halfedge_[v.index] = h;
    touch();
  }
  void set_halfedge(EdgeId e, HalfedgeId h) {
    log_write(e);
    e_halfedge_[e.index] = h;
    touch();
  }
  void set_halfedge(FaceId f, HalfedgeId h) {
    log_write(f);
    (f.is_boundary() ? b_halfedge_[f.slot()] : f_halfedge_[f.slot()]) = h;
    touch();
  }
  void set_position(VertexId v, const glm::dvec3& p) {
    log_write(v);
    v_position_[v.index] = p;
    ++version_;  // the connectivity, and so the triangle rows, stay as they are
  }

  // ---- allocation and deletion --------------------------------------------------------------------
  // New elements are live, appended at the end, with every pointer invalid and position (0,0,0).
  VertexId new_vertex(const glm::dvec3& position = glm::dvec3(0.0));
  HalfedgeId new_halfedge();
  EdgeId new_edge();
  FaceId new_face();
  FaceId new_boundary();
  // Marks the element dead; its slot and stored pointers stay (so tables can still show them).
  void delete_element(VertexId v);
  void delete_element(HalfedgeId h);
  void delete_element(EdgeId e);
  void delete_element(FaceId f);
  // Reserves room for at least this many more elements of each kind (no effect on ids).
  void reserve(size_t vertices, size_t halfedges, size_t edges, size_t faces);

  // ---- iteration over live elements (end fixed at creation) ---------------------------------------
  AliveRange<VertexId> vertices() const { return AliveRange<VertexId>(&v_alive_); }
  AliveRange<HalfedgeId> halfedges() const { return AliveRange<HalfedgeId>(&h_alive_); }
  AliveRange<EdgeId> edges() const { return AliveRange<EdgeId>(&e_alive_); }
  AliveRange<FaceId> faces() const { return AliveRange<FaceId>(&f_alive_); }
  AliveRange<FaceId> boundaries() const { return AliveRange<FaceId>(&b_alive_, FaceId::kBoundaryBit); }

  // ---- derived navigation, bounded so a broken mesh cannot hang the caller --------------------------
  // Walks: each returns false (and stops) after halfedge_capacity() steps or on an invalid/dead pointer.
  // The halfedge whose next is h, found by walking h's face cycle; invalid if the cycle is broken.
  HalfedgeId prev(HalfedgeId h) const;
  // Number of halfedges in f's next-cycle; 0 if the cycle does not close.
  uint32_t degree(FaceId f) const;
  // Number of outgoing halfedges around v (walking twin->next, clockwise seen from outside); 0 if the fan does not
  // close.
  uint32_t degree(VertexId v) const;
  // True if v has an outgoing halfedge whose face is a boundary loop.
  bool is_boundary(VertexId v) const;
  bool is_boundary(EdgeId e) const;
  bool is_boundary(HalfedgeId h) const { return face(h).is_boundary(); }

  // Calls fn(h) for each halfedge of f's cycle, starting at halfedge(f). Returns false if the walk
  // met an invalid or dead halfedge or did not close within the bound.
  template <class Fn>
  bool for_each_face_halfedge(FaceId f, Fn&& fn) const;
  // Calls fn(h) for each outgoing halfedge of v (h = twin(h).next, clockwise seen from outside), starting at
  // halfedge(v).
  template <class Fn>
  bool for_each_outgoing(VertexId v, Fn&& fn) const;

  // ---- bookkeeping --------------------------------------------------------------------------------
  // Bumped by every mutation; equal versions of the same mesh object mean equal contents.
  uint64_t version() const { return version_; }
  // After restoring a snapshot (undo), makes version() larger than `seen`, so no cache mistakes the
  // restored state for one it saw before.
  void bump_version_above(uint64_t seen) { version_ = std::max(version_, seen) + 1; }
  // Becomes `replacement` as one mutation: version() ends above the one before, as after any other (a plain
  // assignment brings the replacement's own count, which may equal a version seen before).
  void replace_with(HalfedgeMesh&& replacement) {
    const uint64_t seen = version_;
    *this = std::move(replacement);
    bump_version_above(seen);
  }
  // Memory held by the arrays and the triangle rows (with the seam they keep), in bytes (capacity, not size).
  size_t memory_bytes() const;

  // True while the mesh is unchanged since a builder or an operation that checks its result declared it a valid
  // mesh whose faces are all triangles (build_halfedge_mesh, loop_subdivide); any mutation ends it. Whole-mesh
  // passes (vertex_normals) may then skip per-step checks. Never true for a mesh nobody vouched for.
  bool proven_valid_triangles() const { return proven_version_ == version_; }
  // Every face as a row of its corners, in an order that keeps neighbours close (triangle_rows.h): left by Loop
  // subdivision and kept until the connectivity changes; nullptr otherwise.
  const TriangleRows* triangle_rows() const { return rows_.get(); }

  // Exact equality of every array (ids, pointers, liveness, positions bit for bit); version is ignored.
  bool same_as(const HalfedgeMesh& other) const;

 private:
  // The builder and the whole-mesh fast paths (Loop subdivision) fill the arrays directly through it, one pass
  // per array instead of one call per element (mesh_storage.h).
  friend struct MeshStorage;
  void touch() {
    ++version_;
    if (rows_) rows_.reset();
  }
  void log_write(VertexId v) { journal_.before_write(ElementKind::Vertex, v.index); }
  void log_write(HalfedgeId h) { journal_.before_write(ElementKind::Halfedge, h.index); }
  void log_write(EdgeId e) { journal_.before_write(ElementKind::Edge, e.index); }
  void log_write(FaceId f) {
    journal_.before_write(f.is_boundary() ? ElementKind::Boundary : ElementKind::Face, f.slot());
  }

  JournalLink journal_;  // first member: see JournalLink

  // Halfedge arrays, indexed by HalfedgeId.
  MeshArray<HalfedgeRecord> h_;  // next, twin, vertex, edge, face
  AliveFlags h_alive_;
  // Vertex arrays, indexed by VertexId.
  MeshArray<HalfedgeId> v_halfedge_;  // v.halfedge (outgoing)
  MeshArray<glm::dvec3> v_position_;  // v.position
  AliveFlags v_alive_;
  // Edge arrays, indexed by EdgeId.
  MeshArray<HalfedgeId> e_halfedge_;  // e.halfedge
  AliveFlags e_alive_;
  // Face arrays, indexed by FaceId::slot() of real faces.
  MeshArray<HalfedgeId> f_halfedge_;  // f.halfedge
  AliveFlags f_alive_;
  // Boundary-loop arrays, indexed by FaceId::slot() of boundary loops.
  MeshArray<HalfedgeId> b_halfedge_;  // b.halfedge
  AliveFlags b_alive_;

  size_t live_vertices_ = 0, live_halfedges_ = 0, live_edges_ = 0, live_faces_ = 0, live_boundaries_ = 0;
  uint64_t version_ = 0;
  uint64_t proven_version_ = ~uint64_t(0);    // version_ at the last MeshStorage::vouch_valid_triangles
  std::shared_ptr<const TriangleRows> rows_;  // what Loop left, while the connectivity is unchanged
};

template <class Fn>
bool HalfedgeMesh::for_each_face_halfedge(FaceId f, Fn&& fn) const {
  if (!alive(f)) return false;
  const HalfedgeId start = halfedge(f);
  HalfedgeId h = start;
  for (uint32_t steps = 0; steps <= halfedge_capacity(); ++steps) {
    if (!alive(h)) return false;
    fn(h);
    h = next(h);
    if (h == start) return true;
  }
  return false;
}

template <class Fn>
bool HalfedgeMesh::for_each_outgoing(VertexId v, Fn&& fn) const {
  if (!alive(v)) return false;
  const HalfedgeId start = halfedge(v);
  HalfedgeId h = start;
  for (uint32_t steps = 0; steps <= halfedge_capacity(); ++steps) {
    if (!alive(h)) return false;
    fn(h);
    const HalfedgeId t = twin(h);
    if (!alive(t)) return false;
    h = next(t);
    if (h == start) return true;
  }
  return false;
}

}  // namespace meshedit
