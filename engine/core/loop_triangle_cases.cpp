// The 64 cases of loop_triangle_cases.h, each replayed once from mesh_ops.h's writes on slot numbers.
#include "core/loop_triangle_cases.h"

#include <algorithm>
#include <vector>

namespace meshedit::loop_cases {
namespace {

// Replays split() on T's three sides in `order`, then flip() of the first split's crossing edge, on slot numbers:
// the writes of mesh_ops.h restricted to T, so the table below is the teaching path's result by construction.
TriangleCase replay_case(const uint8_t order[3], const bool side_h0[3]) {
  TriangleCase t{};
  for (uint8_t i = 0; i < 3; ++i) {
    t.next[i] = uint8_t((i + 1) % 3);
    t.face[i] = 0;
    t.vertex[i] = i;
  }
  t.face_halfedge[0] = 0;
  for (int k = 0; k < 3; ++k) {
    // split(): the current triangle prev -> x -> nx becomes (F, p, prev) and (S, nx, q), F running from x's tail
    // to the midpoint and S from the midpoint on; x keeps its face, the other triangle is the new face.
    const uint8_t i = order[k];
    const uint8_t x = i, o = uint8_t(3 + i), p = uint8_t(6 + i), q = uint8_t(9 + i), mid = uint8_t(3 + i);
    const uint8_t nx = t.next[x], prev = t.next[nx];
    const uint8_t corner = t.vertex[prev];
    const uint8_t old_face = t.face[x], new_face = uint8_t(1 + i);
    uint8_t first, second, first_face, second_face;
    if (side_h0[i]) {  // x is h0: it becomes the second half; o = n0 is the first, from x's old tail
      first = o, second = x, first_face = new_face, second_face = old_face;
      t.vertex[o] = t.vertex[x];
      t.vertex[x] = mid;
    } else {  // x is h1: it stays the first half; o = n1 leaves the midpoint
      first = x, second = o, first_face = old_face, second_face = new_face;
      t.vertex[o] = mid;
    }
    t.vertex[p] = mid;
    t.vertex[q] = corner;
    t.next[first] = p, t.next[p] = prev, t.next[prev] = first;
    t.next[second] = nx, t.next[nx] = q, t.next[q] = second;
    t.face[first] = t.face[p] = t.face[prev] = first_face;
    t.face[second] = t.face[nx] = t.face[q] = second_face;
    t.face_halfedge[old_face] = x;
    t.face_halfedge[new_face] = o;
  }
  // flip() of the first split's crossing edge (its halfedge is p, leaving the midpoint).
  const uint8_t h0 = uint8_t(6 + order[0]), h1 = uint8_t(9 + order[0]);
  const uint8_t h2 = t.next[h0], h3 = t.next[h2], h4 = t.next[h1], h5 = t.next[h4];
  const uint8_t c = t.vertex[h3], d = t.vertex[h5];
  const uint8_t f0 = t.face[h0], f1 = t.face[h1];
  t.vertex[h0] = d;
  t.next[h0] = h3, t.next[h3] = h4, t.next[h4] = h0;
  t.face[h4] = f0;
  t.face_halfedge[f0] = h0;
  t.vertex[h1] = c;
  t.next[h1] = h5, t.next[h5] = h2, t.next[h2] = h1;
  t.face[h2] = f1;
  t.face_halfedge[f1] = h1;
  for (uint8_t g = 0; g < 4; ++g) {
    uint8_t h = t.face_halfedge[g];
    for (uint8_t k = 0; k < 3; ++k, h = t.next[h]) t.corner[g][k] = t.vertex[h];
  }
  return t;
}

}  // namespace

const TriangleCase* triangle_cases() {
  static const std::vector<TriangleCase> kTable = [] {
    std::vector<TriangleCase> cases(64);
    for (unsigned code = 0; code < 8; ++code) {
      uint8_t order_of[3] = {0, 1, 2};
      // Find a permutation whose comparisons give this code; impossible codes keep the identity.
      const uint8_t perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
      for (const auto& perm : perms) {
        uint32_t r[3];
        for (uint32_t k = 0; k < 3; ++k) r[perm[k]] = k;  // perm[k] is split k-th
        if (order_code(r[0], r[1], r[2]) == code) std::copy(perm, perm + 3, order_of);
      }
      for (unsigned bits = 0; bits < 8; ++bits) {
        const bool side_h0[3] = {(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0};
        cases[case_index(code, bits)] = replay_case(order_of, side_h0);
      }
    }
    return cases;
  }();
  return kTable.data();
}

}  // namespace meshedit::loop_cases
