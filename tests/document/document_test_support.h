// What the document tests share (and the panel tests, through ui/ui_test_support.h): short id helpers and the grid
// fixture whose ids the tests name. No ImGui.
#pragma once

#include <cstdint>

#include <gtest/gtest.h>

#include "core/halfedge_mesh.h"
#include "core/ids.h"
#include "core/mesh_build.h"
#include "core/primitives.h"

namespace meshedit::document_testing {

inline VertexId V(uint32_t i) { return VertexId(i); }
inline HalfedgeId H(uint32_t i) { return HalfedgeId(i); }
inline EdgeId E(uint32_t i) { return EdgeId(i); }
inline FaceId F(uint32_t i) { return FaceId::face(i); }
inline FaceId B(uint32_t i) { return FaceId::boundary(i); }

// Compares elements by their printed form, so failures read "h13 vs h14".
#define EXPECT_REF(actual, expected)                               \
  EXPECT_EQ(::meshedit::format_id(::meshedit::ElementRef(actual)), \
            ::meshedit::format_id(::meshedit::ElementRef(expected)))

// make_grid(1, 1): v0 (0,0) v1 (1,0) v2 (0,1) v3 (1,1); f0 = h0 h1 h2 (v0 v1 v3), f1 = h3 h4 h5 (v0 v3 v2);
// e0 = v0-v1 (h0/h6), e1 = v1-v3 (h1/h9), e2 = v3-v0, the diagonal (h2/h3), e3 = v3-v2 (h4/h8),
// e4 = v2-v0 (h5/h7); boundary loop b0 = h6 h7 h8 h9; v0.halfedge h7, v1 h6, v2 h8, v3 h9.
inline HalfedgeMesh grid_1x1() { return build_halfedge_mesh(make_grid(1, 1)); }

}  // namespace meshedit::document_testing
