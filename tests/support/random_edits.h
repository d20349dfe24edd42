// random_local_edits: flips, splits and collapses on random live edges (the core's checked operations, so the
// mesh stays valid), leaving dead slots among the ids and irregular valences. Seeded mt19937, raw output only,
// so a seed gives the same mesh on every platform. random_edit_or_write: one such operation or a few raw writes
// through the setters (broken pointers, new and deleted elements, a slot written twice), as a script would.
// break_randomly: one to three random pointer writes, deletions or non-finite positions (no new elements).
// edited_torus: a small torus after 60 such edits.
#pragma once

#include <cstdint>
#include <limits>
#include <random>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"

namespace meshedit::testing {

inline void random_local_edits(HalfedgeMesh& m, uint32_t seed, int steps) {
  std::mt19937 random(seed);
  for (int step = 0; step < steps; ++step) {
    const EdgeId e(random() % m.edge_capacity());
    if (!m.alive(e)) continue;
    switch (random() % 3) {
      case 0: (void)flip(m, e); break;
      case 1: (void)split(m, e); break;
      default: (void)collapse(m, e); break;
    }
  }
}

// One random edit of `m` (which must have at least one face): a core operation on a random edge, or raw writes.
inline void random_edit_or_write(HalfedgeMesh& m, std::mt19937& random) {
  const EdgeId e(random() % m.edge_capacity());
  switch (random() % 5) {
    case 0: (void)flip(m, e); break;
    case 1: (void)split(m, e); break;
    case 2: (void)collapse(m, e); break;
    case 3:
      for (int i = 0; i < 4; ++i) {
        const HalfedgeId h(random() % m.halfedge_capacity());
        m.set_next(h, HalfedgeId(random() % m.halfedge_capacity()));
        m.set_face(h, FaceId::boundary(0));
        m.set_position(VertexId(random() % m.vertex_capacity()), {double(random() % 7), -0.0, 0.5});
      }
      break;
    default: {
      const VertexId v = m.new_vertex({1, 2, 3});
      m.set_halfedge(v, HalfedgeId(random() % m.halfedge_capacity()));
      m.delete_element(EdgeId(random() % m.edge_capacity()));
      m.delete_element(FaceId::face(random() % m.face_capacity()));
      const HalfedgeId h = m.new_halfedge();
      m.set_neighbors(h, h, h, v, e, FaceId::face(0));
      m.set_halfedge(FaceId::face(0), h);
      m.set_position(v, {4, 5, 6});  // a slot written twice
      break;
    }
  }
}

// One to three random pointer writes, deletions or non-finite positions.
inline void break_randomly(HalfedgeMesh& m, std::mt19937& random) {
  const int writes = 1 + int(random() % 3);
  for (int i = 0; i < writes; ++i) {
    const uint32_t hc = m.halfedge_capacity();
    const HalfedgeId h(random() % hc);
    switch (random() % 10) {
      case 0: m.set_next(h, HalfedgeId(random() % (hc + 2))); break;
      case 1: m.set_twin(h, HalfedgeId(random() % hc)); break;
      case 2: m.set_vertex(h, VertexId(random() % (m.vertex_capacity() + 1))); break;
      case 3: m.set_edge(h, EdgeId(random() % m.edge_capacity())); break;
      case 4: m.set_face(h, random() % 4 ? FaceId::face(random() % m.face_capacity()) : FaceId::boundary(0)); break;
      case 5: m.set_halfedge(VertexId(random() % m.vertex_capacity()), HalfedgeId(random() % hc)); break;
      case 6: m.set_halfedge(EdgeId(random() % m.edge_capacity()), HalfedgeId(random() % hc)); break;
      case 7: m.set_halfedge(FaceId::face(random() % m.face_capacity()), HalfedgeId(random() % hc)); break;
      case 8:
        m.set_position(VertexId(random() % m.vertex_capacity()), glm::dvec3(std::numeric_limits<double>::quiet_NaN()));
        break;
      default: m.delete_element(EdgeId(random() % m.edge_capacity())); break;
    }
  }
}

// A torus after random local edits: dead slots among the ids, irregular valences.
inline HalfedgeMesh edited_torus(uint32_t seed) {
  HalfedgeMesh m = build_halfedge_mesh(make_torus(6, 8));
  random_local_edits(m, seed, 60);
  return m;
}

}  // namespace meshedit::testing
