// Reading and writing one slot's stored values, and a mesh's shape (see slot_state.h for the invariants).
#include "core/slot_values.h"

#include <cstring>

#include "core/mesh_storage.h"

namespace meshedit {

bool same_state(const SlotValues& a, const SlotValues& b) {
  return a.record == b.record && std::memcmp(&a.position, &b.position, sizeof(glm::dvec3)) == 0 &&
         a.halfedge == b.halfedge && a.alive == b.alive;
}

SlotValues read_slot(const HalfedgeMesh& mesh, ElementKind kind, uint32_t slot) {
  SlotValues state;
  switch (kind) {
    case ElementKind::Vertex:
      state.halfedge = mesh.halfedge(VertexId(slot));
      state.position = mesh.position(VertexId(slot));
      state.alive = mesh.alive(VertexId(slot));
      break;
    case ElementKind::Halfedge:
      state.record = mesh.record(HalfedgeId(slot));
      state.alive = mesh.alive(HalfedgeId(slot));
      break;
    case ElementKind::Edge:
      state.halfedge = mesh.halfedge(EdgeId(slot));
      state.alive = mesh.alive(EdgeId(slot));
      break;
    case ElementKind::Face:
    case ElementKind::Boundary: {
      const FaceId f = kind == ElementKind::Boundary ? FaceId::boundary(slot) : FaceId::face(slot);
      state.halfedge = mesh.halfedge(f);
      state.alive = mesh.alive(f);
      break;
    }
  }
  return state;
}

void write_slot(HalfedgeMesh& mesh, ElementKind kind, uint32_t slot, const SlotValues& state) {
  const MeshStorage::Arrays a = MeshStorage::arrays(mesh);
  const bool alive = state.alive;
  switch (kind) {
    case ElementKind::Vertex:
      a.v_halfedge[slot] = state.halfedge;
      a.v_position[slot] = state.position;
      a.v_alive.set(slot, alive);
      break;
    case ElementKind::Halfedge:
      a.h[slot] = state.record;
      a.h_alive.set(slot, alive);
      break;
    case ElementKind::Edge:
      a.e_halfedge[slot] = state.halfedge;
      a.e_alive.set(slot, alive);
      break;
    case ElementKind::Face:
      a.f_halfedge[slot] = state.halfedge;
      a.f_alive.set(slot, alive);
      break;
    case ElementKind::Boundary:
      a.b_halfedge[slot] = state.halfedge;
      a.b_alive.set(slot, alive);
      break;
  }
}

MeshShape shape_of(const HalfedgeMesh& mesh) {
  MeshShape shape;
  for (int k = 0; k < kElementKindCount; ++k) shape.capacity[k] = mesh.capacity(static_cast<ElementKind>(k));
  shape.live[0] = mesh.num_vertices();
  shape.live[1] = mesh.num_halfedges();
  shape.live[2] = mesh.num_edges();
  shape.live[3] = mesh.num_faces();
  shape.live[4] = mesh.num_boundaries();
  return shape;
}

void set_shape(HalfedgeMesh& mesh, const MeshShape& shape) { MeshStorage::set_slots(mesh, shape.capacity, shape.live); }

void reserve_shape(HalfedgeMesh& mesh, const MeshShape& shape) {
  MeshStorage::reserve_slots(mesh, shape.capacity, shape.live);
}

}  // namespace meshedit
