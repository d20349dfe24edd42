// A torus of quads, for the render tests that need polygons (the core's primitives are triangles but for the cube).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/polygon_mesh.h"

namespace meshedit {

// A torus of rings x sides quads.
inline PolygonMesh quad_torus(uint32_t rings, uint32_t sides) {
  PolygonMesh out;
  for (uint32_t i = 0; i < rings; ++i) {
    for (uint32_t j = 0; j < sides; ++j) {
      const double u = 6.283185307179586 * i / rings, v = 6.283185307179586 * j / sides;
      out.positions.push_back(
          {(1.0 + 0.35 * std::cos(v)) * std::cos(u), (1.0 + 0.35 * std::cos(v)) * std::sin(u), 0.35 * std::sin(v)});
    }
  }
  for (uint32_t i = 0; i < rings; ++i) {
    for (uint32_t j = 0; j < sides; ++j) {
      const uint32_t i1 = (i + 1) % rings, j1 = (j + 1) % sides;
      out.indices.insert(out.indices.end(), {i * sides + j, i1 * sides + j, i1 * sides + j1, i * sides + j1});
      out.face_offsets.push_back(uint32_t(out.indices.size()));
    }
  }
  return out;
}

}  // namespace meshedit
