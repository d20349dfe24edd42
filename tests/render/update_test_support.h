// What the renderer-update tests share: byte equality of two arrays and of every slot array of two SlotGeometry
// values, and the elements a diff touches (each once, in diff()'s order: kind, then id), which is what the document
// hands the renderer after an edit.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <type_traits>
#include <vector>

#include "core/history.h"
#include "render/slot_geometry.h"

namespace meshedit::testing {

// Two arrays (std::vector or MeshArray) of the same element type, byte for byte.
template <class A, class B>
bool same_bytes(const A& a, const B& b) {
  using T = typename A::value_type;
  static_assert(std::is_same_v<T, typename B::value_type>);
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Every per-slot array, the boundary list and the counts, byte for byte (bounds and arrows are each test's own).
inline void expect_same_slots(const SlotGeometry& got, const SlotGeometry& want) {
  EXPECT_TRUE(same_bytes(got.positions, want.positions));
  EXPECT_TRUE(same_bytes(got.smooth_normals, want.smooth_normals));
  EXPECT_TRUE(same_bytes(got.points, want.points));
  EXPECT_TRUE(same_bytes(got.triangles, want.triangles));
  EXPECT_TRUE(same_bytes(got.face_normals, want.face_normals));
  EXPECT_TRUE(same_bytes(got.extra_triangles, want.extra_triangles));
  EXPECT_TRUE(same_bytes(got.extra_faces, want.extra_faces));
  EXPECT_TRUE(same_bytes(got.edges, want.edges));
  EXPECT_EQ(got.boundary_edges, want.boundary_edges);
  EXPECT_TRUE(got.counts == want.counts);
}

inline std::vector<ElementRef> changed_elements(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  std::vector<ElementRef> out;
  for (const FieldChange& c : diff(before, after)) {
    if (out.empty() || !(out.back() == c.element)) out.push_back(c.element);
  }
  return out;
}

}  // namespace meshedit::testing
