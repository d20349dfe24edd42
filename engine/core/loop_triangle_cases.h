// The cases of Loop subdivision's fast path (loop_subdivision_fast.cpp): what one original triangle T becomes when
// its three edges are split in some order and the first split's crossing edge is flipped, as a function of that
// order and of which side of each split T was on. Each case is the teaching path's writes (mesh_ops.h: split, then
// flip) replayed once on slot numbers, so the fast path's result is the teaching path's by construction.
//
// Slots: 0-2 the original halfedges x0 x1 x2 (x0 = T.halfedge, x1 = x0.next); per side i the new halfedges on T's
// side: o_i (the other half of the split edge) at 3 + i, p_i (from the midpoint to the opposite corner) at 6 + i,
// q_i (its twin) at 9 + i. Faces: 0 = T, 1 + i = the face split i made on T's side. Vertices: 0-2 the corners
// (x_i leaves corner i), 3 + i the midpoint of side i.
#pragma once

#include <cstdint>

namespace meshedit::loop_cases {

struct TriangleCase {
  uint8_t next[12];
  uint8_t face[12];
  uint8_t vertex[12];
  uint8_t face_halfedge[4];
  uint8_t corner[4][3];  // each face's corners (vertex slots), from its halfedge in next order
};

// The order of three ranks as an index: bit 0 = r0 < r1, bit 1 = r1 < r2, bit 2 = r0 < r2 (codes 2 and 5 cannot
// happen for distinct ranks).
inline unsigned order_code(uint32_t r0, uint32_t r1, uint32_t r2) {
  return unsigned(r0 < r1) | unsigned(r1 < r2) << 1 | unsigned(r0 < r2) << 2;
}

// The 64 cases, the one for an order code and side bits (bit i: T's halfedge on side i was split()'s h0) at
// case_index(order, sides). Replayed on the first call (thread-safe: a function-local static).
const TriangleCase* triangle_cases();
inline unsigned case_index(unsigned order, unsigned sides) { return order * 8 + sides; }

}  // namespace meshedit::loop_cases
