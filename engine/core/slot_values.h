// SlotValues and MeshShape: the stored values of one slot of a mesh, and the slot and live counts of every kind; what
// the change journal logs and what an undo patch stores (change_journal.h, mesh_patch.h).
//
// Invariants: read_slot/write_slot touch exactly the fields diff() compares for that kind (history.h) and nothing
// else, so writing a read state back restores the slot bit for bit; the fields of other kinds stay default. Both
// expect slot < the mesh's capacity of that kind (callers check). write_slot goes through MeshStorage, so on a
// journaled mesh it makes the journal fall back to a snapshot: write only to meshes without a journal.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit {

struct SlotValues {
  HalfedgeRecord record;     // halfedges: next, twin, vertex, edge, face
  glm::dvec3 position{0.0};  // vertices
  HalfedgeId halfedge;       // vertices, edges, faces, boundary loops
  bool alive = false;
};
// Field by field; positions bit for bit (as diff() compares them).
bool same_state(const SlotValues& a, const SlotValues& b);

SlotValues read_slot(const HalfedgeMesh& mesh, ElementKind kind, uint32_t slot);
void write_slot(HalfedgeMesh& mesh, ElementKind kind, uint32_t slot, const SlotValues& state);

// Slots ever allocated and live elements of each kind, indexed by ElementKind.
struct MeshShape {
  uint32_t capacity[kElementKindCount] = {};
  size_t live[kElementKindCount] = {};
};
MeshShape shape_of(const HalfedgeMesh& mesh);
// Resizes every array to the shape's capacities (new slots dead and empty, extra slots dropped) and sets the live
// counts; the slots' values are the caller's to write.
void set_shape(HalfedgeMesh& mesh, const MeshShape& shape);
// Makes room for set_shape(mesh, shape) and for writing any state into its slots, so that neither allocates
// (MeshStorage::reserve_slots). Changes no value.
void reserve_shape(HalfedgeMesh& mesh, const MeshShape& shape);

}  // namespace meshedit
