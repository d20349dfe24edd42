// HalfedgeMesh storage, allocation and bounded walks (see halfedge_mesh.h for the invariants).
#include "core/halfedge_mesh.h"

#include <cstring>
#include <type_traits>

namespace meshedit {

// Containers of meshes (the history's redo list) relocate them by moving only while moving cannot throw; a journal
// link must not change that (JournalLink's move is noexcept).
static_assert(std::is_nothrow_move_constructible_v<HalfedgeMesh>);

uint32_t HalfedgeMesh::capacity(ElementKind kind) const {
  switch (kind) {
    case ElementKind::Vertex: return vertex_capacity();
    case ElementKind::Halfedge: return halfedge_capacity();
    case ElementKind::Edge: return edge_capacity();
    case ElementKind::Face: return face_capacity();
    case ElementKind::Boundary: return boundary_capacity();
  }
  return 0;
}

bool HalfedgeMesh::alive(ElementRef r) const {
  switch (r.kind) {
    case ElementKind::Vertex: return alive(VertexId(r.index));
    case ElementKind::Halfedge: return alive(HalfedgeId(r.index));
    case ElementKind::Edge: return alive(EdgeId(r.index));
    case ElementKind::Face:
    case ElementKind::Boundary: return r.valid() && alive(r.face_id());
  }
  return false;
}

void HalfedgeMesh::set_neighbors(HalfedgeId h, HalfedgeId next, HalfedgeId twin, VertexId vertex, EdgeId edge,
                                 FaceId face) {
  log_write(h);
  h_[h.index] = HalfedgeRecord{next, twin, vertex, edge, face};
  touch();
}

VertexId HalfedgeMesh::new_vertex(const glm::dvec3& position) {
  v_halfedge_.emplace_back();
  v_position_.push_back(position);
  v_alive_.push_back(true);
  ++live_vertices_;
  touch();
  return VertexId(vertex_capacity() - 1);
}

HalfedgeId HalfedgeMesh::new_halfedge() {
  h_.emplace_back();
  h_alive_.push_back(true);
  ++live_halfedges_;
  touch();
  return HalfedgeId(halfedge_capacity() - 1);
}

EdgeId HalfedgeMesh::new_edge() {
  e_halfedge_.emplace_back();
  e_alive_.push_back(true);
  ++live_edges_;
  touch();
  return EdgeId(edge_capacity() - 1);
}

FaceId HalfedgeMesh::new_face() {
  f_halfedge_.emplace_back();
  f_alive_.push_back(true);
  ++live_faces_;
  touch();
  return FaceId::face(face_capacity() - 1);
}

FaceId HalfedgeMesh::new_boundary() {
  b_halfedge_.emplace_back();
  b_alive_.push_back(true);
  ++live_boundaries_;
  touch();
  return FaceId::boundary(boundary_capacity() - 1);
}

void HalfedgeMesh::delete_element(VertexId v) {
  if (!alive(v)) return;
  log_write(v);
  v_alive_.set(v.index, false);
  --live_vertices_;
  touch();
}

void HalfedgeMesh::delete_element(HalfedgeId h) {
  if (!alive(h)) return;
  log_write(h);
  h_alive_.set(h.index, false);
  --live_halfedges_;
  touch();
}

void HalfedgeMesh::delete_element(EdgeId e) {
  if (!alive(e)) return;
  log_write(e);
  e_alive_.set(e.index, false);
  --live_edges_;
  touch();
}

void HalfedgeMesh::delete_element(FaceId f) {
  if (!alive(f)) return;
  log_write(f);
  if (f.is_boundary()) {
    b_alive_.set(f.slot(), false);
    --live_boundaries_;
  } else {
    f_alive_.set(f.slot(), false);
    --live_faces_;
  }
  touch();
}

void HalfedgeMesh::reserve(size_t vertices, size_t halfedges, size_t edges, size_t faces) {
  v_halfedge_.reserve(v_halfedge_.size() + vertices);
  v_position_.reserve(v_position_.size() + vertices);
  v_alive_.reserve(v_alive_.size() + vertices);
  h_.reserve(h_.size() + halfedges);
  h_alive_.reserve(h_alive_.size() + halfedges);
  e_halfedge_.reserve(e_halfedge_.size() + edges);
  e_alive_.reserve(e_alive_.size() + edges);
  f_halfedge_.reserve(f_halfedge_.size() + faces);
  f_alive_.reserve(f_alive_.size() + faces);
}

HalfedgeId HalfedgeMesh::prev(HalfedgeId h) const {
  if (!alive(h)) return HalfedgeId();
  HalfedgeId p = h;
  for (uint32_t steps = 0; steps <= halfedge_capacity(); ++steps) {
    const HalfedgeId n = next(p);
    if (!alive(n)) return HalfedgeId();
    if (n == h) return p;
    p = n;
  }
  return HalfedgeId();
}

uint32_t HalfedgeMesh::degree(FaceId f) const {
  uint32_t count = 0;
  return for_each_face_halfedge(f, [&](HalfedgeId) { ++count; }) ? count : 0;
}

uint32_t HalfedgeMesh::degree(VertexId v) const {
  uint32_t count = 0;
  return for_each_outgoing(v, [&](HalfedgeId) { ++count; }) ? count : 0;
}

bool HalfedgeMesh::is_boundary(VertexId v) const {
  bool boundary = false;
  for_each_outgoing(v, [&](HalfedgeId h) { boundary = boundary || face(h).is_boundary(); });
  return boundary;
}

bool HalfedgeMesh::is_boundary(EdgeId e) const {
  if (!alive(e)) return false;
  const HalfedgeId h = halfedge(e);
  if (!alive(h)) return false;
  const HalfedgeId t = twin(h);
  return face(h).is_boundary() || (alive(t) && face(t).is_boundary());
}

size_t HalfedgeMesh::memory_bytes() const {
  return h_.capacity() * sizeof(HalfedgeRecord) + h_alive_.memory_bytes() +
         v_halfedge_.capacity() * sizeof(HalfedgeId) + v_position_.capacity() * sizeof(glm::dvec3) +
         v_alive_.memory_bytes() + e_halfedge_.capacity() * sizeof(HalfedgeId) + e_alive_.memory_bytes() +
         f_halfedge_.capacity() * sizeof(HalfedgeId) + f_alive_.memory_bytes() +
         b_halfedge_.capacity() * sizeof(HalfedgeId) + b_alive_.memory_bytes() + (rows_ ? rows_->memory_bytes() : 0);
}

namespace {
// Positions compare bit for bit, so a NaN equals itself and a mesh is always same_as its copy.
bool same_bits(const MeshArray<glm::dvec3>& a, const MeshArray<glm::dvec3>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::dvec3)) == 0);
}
}  // namespace

bool HalfedgeMesh::same_as(const HalfedgeMesh& o) const {
  return h_ == o.h_ && h_alive_ == o.h_alive_ && v_halfedge_ == o.v_halfedge_ &&
         same_bits(v_position_, o.v_position_) && v_alive_ == o.v_alive_ && e_halfedge_ == o.e_halfedge_ &&
         e_alive_ == o.e_alive_ && f_halfedge_ == o.f_halfedge_ && f_alive_ == o.f_alive_ &&
         b_halfedge_ == o.b_halfedge_ && b_alive_ == o.b_alive_;
}

}  // namespace meshedit
