// MeshStorage: direct access to HalfedgeMesh's arrays for whole-mesh passes that would only pay for per-call
// bookkeeping through the element API: Loop subdivision and the builders write through it (View, Arrays).
//
// Invariants: a mesh with a ChangeJournal attached is told before view(), grow(), arrays() or set_slots() hands out
// or changes its arrays (the journal takes a full snapshot then, since it cannot follow such writes slot by slot).
// Each of those, and set_versions(), drops the mesh's triangle rows (triangle_rows.h): they cannot follow such
// writes either. A caller that makes rows for what it wrote sets them last, with set_triangle_rows().
// grow() appends live elements (alive flags set, live counts and version() updated) and leaves their fields for the
// caller to write, all of them; a View's pointers stay valid until the next change of any array's size. Code that
// writes through a View must leave a mesh the element API could have produced, and calls touch() when done.
// vouch_valid_triangles() is called only by code that has established what it vouches for.
#pragma once

#include <algorithm>
#include <cstdint>

#include "core/halfedge_mesh.h"

namespace meshedit {

struct MeshStorage {
  struct View {
    HalfedgeRecord* h;
    HalfedgeId* vertex_halfedge;
    glm::dvec3* position;
    HalfedgeId* edge_halfedge;
    HalfedgeId* face_halfedge;
    const AliveFlags* vertex_alive;  // the mesh's own flags: they follow grow()
    const AliveFlags* edge_alive;
    const AliveFlags* face_alive;
  };

  static View view(HalfedgeMesh& m) {
    m.journal_.before_bulk_write();
    m.rows_.reset();
    return {m.h_.data(),          m.v_halfedge_.data(), m.v_position_.data(), m.e_halfedge_.data(),
            m.f_halfedge_.data(), &m.v_alive_,          &m.e_alive_,          &m.f_alive_};
  }

  // Grows each kind to the given capacity with new live elements whose fields are NOT set: the caller must write
  // every pointer of every new element (and every new position) before the mesh is used. Capacities never shrink.
  // Every array gets its room before any size or count changes, so the resizes below allocate nothing. That room is
  // exact: a caller that grows in steps calls reserve_total for the last step first, as Loop does, so the steps do not
  // copy the arrays again each time.
  static void grow(HalfedgeMesh& m, uint32_t vertices, uint32_t halfedges, uint32_t edges, uint32_t faces) {
    m.journal_.before_bulk_write();
    reserve_total(m, vertices, halfedges, edges, faces);
    m.live_vertices_ += vertices - m.vertex_capacity();
    m.live_halfedges_ += halfedges - m.halfedge_capacity();
    m.live_edges_ += edges - m.edge_capacity();
    m.live_faces_ += faces - m.face_capacity();
    m.v_alive_.resize(vertices, true);
    m.h_alive_.resize(halfedges, true);
    m.e_alive_.resize(edges, true);
    m.f_alive_.resize(faces, true);
    m.v_halfedge_.resize_for_overwrite(vertices);
    m.v_position_.resize_for_overwrite(vertices);
    m.h_.resize_for_overwrite(halfedges);
    m.e_halfedge_.resize_for_overwrite(edges);
    m.f_halfedge_.resize_for_overwrite(faces);
    m.touch();
  }

  // Makes room for this many elements of each kind in all, so later grow() calls up to it do not copy.
  static void reserve_total(HalfedgeMesh& m, size_t vertices, size_t halfedges, size_t edges, size_t faces) {
    m.reserve(vertices - std::min<size_t>(vertices, m.vertex_capacity()),
              halfedges - std::min<size_t>(halfedges, m.halfedge_capacity()),
              edges - std::min<size_t>(edges, m.edge_capacity()), faces - std::min<size_t>(faces, m.face_capacity()));
  }

  static void touch(HalfedgeMesh& m) { m.touch(); }

  // Declares the mesh, as it is now, valid with triangle faces only (HalfedgeMesh::proven_valid_triangles). Only
  // for code that has established it: the builder's fast path, Loop subdivision of an accepted mesh.
  static void vouch_valid_triangles(HalfedgeMesh& m) { m.proven_version_ = m.version_; }

  // Rows made for the connectivity as it is now, set after the last write that would drop them. Only for code that
  // made them so (Loop subdivision).
  static void set_triangle_rows(HalfedgeMesh& m, std::shared_ptr<const TriangleRows> rows) {
    m.rows_ = std::move(rows);
  }

  // The arrays themselves, for a builder that sizes and fills them from nothing (mesh_build_fast.cpp).
  struct Arrays {
    MeshArray<HalfedgeRecord>& h;
    AliveFlags& h_alive;
    MeshArray<HalfedgeId>& v_halfedge;
    MeshArray<glm::dvec3>& v_position;
    AliveFlags& v_alive;
    MeshArray<HalfedgeId>& e_halfedge;
    AliveFlags& e_alive;
    MeshArray<HalfedgeId>& f_halfedge;
    AliveFlags& f_alive;
    MeshArray<HalfedgeId>& b_halfedge;
    AliveFlags& b_alive;
  };
  static Arrays arrays(HalfedgeMesh& m) {
    m.journal_.before_bulk_write();
    m.rows_.reset();
    return {m.h_,       m.h_alive_,    m.v_halfedge_, m.v_position_, m.v_alive_, m.e_halfedge_,
            m.e_alive_, m.f_halfedge_, m.f_alive_,    m.b_halfedge_, m.b_alive_};
  }
  // Sets the live counts from the alive flags' sizes after a builder filled the arrays (every element live but
  // `dead_vertices` unused input vertices).
  static void count_live(HalfedgeMesh& m, size_t dead_vertices) {
    m.live_vertices_ = m.v_alive_.size() - dead_vertices;
    m.live_halfedges_ = m.h_alive_.size();
    m.live_edges_ = m.e_alive_.size();
    m.live_faces_ = m.f_alive_.size();
    m.live_boundaries_ = m.b_alive_.size();
  }

  // ---- for undo and the change journal (mesh_patch.h, change_journal.h), which restore exact states ----
  // The journal a mesh reports to (JournalLink); attach only a journal that detaches before it dies.
  static ChangeJournal* journal(const HalfedgeMesh& m) { return m.journal_.journal_; }
  static void set_journal(HalfedgeMesh& m, ChangeJournal* journal) { m.journal_.journal_ = journal; }
  // Sets every array of each kind to these slot counts (kinds in ElementKind order): new slots are dead with
  // invalid pointers and position (0,0,0); slots past the count are dropped. Live counts are set as given.
  static void set_slots(HalfedgeMesh& m, const uint32_t (&capacity)[kElementKindCount],
                        const size_t (&live)[kElementKindCount]) {
    m.journal_.before_bulk_write();
    m.rows_.reset();
    m.v_halfedge_.resize(capacity[0]);
    m.v_position_.resize(capacity[0]);
    m.v_alive_.resize(capacity[0], false);
    m.h_.resize(capacity[1]);
    m.h_alive_.resize(capacity[1], false);
    m.e_halfedge_.resize(capacity[2]);
    m.e_alive_.resize(capacity[2], false);
    m.f_halfedge_.resize(capacity[3]);
    m.f_alive_.resize(capacity[3], false);
    m.b_halfedge_.resize(capacity[4]);
    m.b_alive_.resize(capacity[4], false);
    m.live_vertices_ = live[0];
    m.live_halfedges_ = live[1];
    m.live_edges_ = live[2];
    m.live_faces_ = live[3];
    m.live_boundaries_ = live[4];
  }
  // Makes room for set_slots(m, capacity, live) and for then writing any values into those slots (dead flags
  // included), so that neither allocates. Changes no value, so a journal is not told.
  static void reserve_slots(HalfedgeMesh& m, const uint32_t (&capacity)[kElementKindCount],
                            const size_t (&live)[kElementKindCount]) {
    m.v_halfedge_.reserve(capacity[0]);
    m.v_position_.reserve(capacity[0]);
    m.h_.reserve(capacity[1]);
    m.e_halfedge_.reserve(capacity[2]);
    m.f_halfedge_.reserve(capacity[3]);
    m.b_halfedge_.reserve(capacity[4]);
    AliveFlags* alive[kElementKindCount] = {&m.v_alive_, &m.h_alive_, &m.e_alive_, &m.f_alive_, &m.b_alive_};
    for (int k = 0; k < kElementKindCount; ++k) {
      // Dead bits are needed when the kind grows (new slots start dead) or when the new state has dead slots.
      if (capacity[k] > alive[k]->size() || live[k] < capacity[k]) alive[k]->reserve_bits(capacity[k]);
    }
  }
  // The version at the last vouch_valid_triangles, and a way to put back both counters exactly (a refused
  // operation leaves the mesh with the version it had).
  static uint64_t proven_version(const HalfedgeMesh& m) { return m.proven_version_; }
  static void set_versions(HalfedgeMesh& m, uint64_t version, uint64_t proven_version) {
    m.version_ = version;
    m.proven_version_ = proven_version;
    m.rows_.reset();
  }
};

}  // namespace meshedit
