// MeshStorage::grow out of memory (FailingAllocations fails each of its allocations in turn): it throws
// std::bad_alloc with the mesh exactly as it was (every slot, flag, count and capacity), or grows every kind; never
// a mesh whose alive flags or live counts run past its arrays.
#include <new>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_storage.h"
#include "core/primitives.h"
#include "support/failing_allocations.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;

// A small torus (its arrays come from operator new, so every allocation counts) with a dead slot of every kind, so
// each kind's alive flags hold bits that must grow too.
HalfedgeMesh torus_with_dead_slots() {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(6, 5));
  m.delete_element(VertexId(1));
  m.delete_element(HalfedgeId(2));
  m.delete_element(EdgeId(3));
  m.delete_element(FaceId::face(4));
  return m;
}

TEST(MeshStorageOutOfMemory, GrowChangesNothingOrEverything) {
  const HalfedgeMesh before = torus_with_dead_slots();
  const uint32_t vertices = uint32_t(before.vertex_capacity()) + 100;
  const uint32_t halfedges = uint32_t(before.halfedge_capacity()) + 600;
  const uint32_t edges = uint32_t(before.edge_capacity()) + 300, faces = uint32_t(before.face_capacity()) + 200;
  for (size_t n = 1;; ++n) {
    SCOPED_TRACE(n);
    HalfedgeMesh m = before;
    bool threw = false, failed = false;
    {
      const FailingAllocations failing(n, FailingAllocations::Later::Fail);
      try {
        MeshStorage::grow(m, vertices, halfedges, edges, faces);
      } catch (const std::bad_alloc&) {
        threw = true;
      }
      failed = failing.failed();
    }
    if (threw) {
      EXPECT_TRUE(m.same_as(before));
      EXPECT_EQ(m.vertex_capacity(), before.vertex_capacity());
      EXPECT_EQ(m.halfedge_capacity(), before.halfedge_capacity());
      EXPECT_EQ(m.edge_capacity(), before.edge_capacity());
      EXPECT_EQ(m.face_capacity(), before.face_capacity());
      EXPECT_EQ(m.num_vertices(), before.num_vertices());
      EXPECT_EQ(m.num_halfedges(), before.num_halfedges());
      EXPECT_EQ(m.num_edges(), before.num_edges());
      EXPECT_EQ(m.num_faces(), before.num_faces());
    } else {
      EXPECT_EQ(m.vertex_capacity(), vertices);
      EXPECT_EQ(m.halfedge_capacity(), halfedges);
      EXPECT_EQ(m.edge_capacity(), edges);
      EXPECT_EQ(m.face_capacity(), faces);
      EXPECT_EQ(m.num_faces(), before.num_faces() + (faces - before.face_capacity()));
      EXPECT_TRUE(m.alive(FaceId::face(faces - 1)));
      EXPECT_FALSE(m.alive(FaceId::face(4)));
    }
    if (!failed) break;
  }
}

}  // namespace
}  // namespace meshedit
