// The inputs peer_bench gives every contender: the core's benchmark torus (make_torus_with_faces) and the
// same torus with square holes, one quad (two triangles) cut out every 8 rings and 8 sides. The holes share
// no vertex and every vertex keeps some faces, so all three libraries accept the mesh and it has one
// boundary loop per hole.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/primitives.h"

namespace meshedit::bench {

struct HoledTorus {
  PolygonMesh mesh;
  size_t holes = 0;
};

inline HoledTorus make_torus_with_holes(uint32_t faces) {
  // make_torus_with_faces makes make_torus(2 * sides, sides), whose vertex (ring i, side j) is i * sides + j.
  const auto sides = static_cast<uint32_t>(std::max(3.0, std::round(std::sqrt(faces / 4.0))));
  const uint32_t rings = 2 * sides;
  const PolygonMesh torus = make_torus(rings, sides);
  std::vector<uint32_t> hole_of(torus.num_vertices(), 0);  // 1 + the hole the vertex is a corner of
  HoledTorus out;
  for (uint32_t i = 4; i + 2 < rings; i += 8) {
    for (uint32_t j = 4; j + 2 < sides; j += 8) {
      ++out.holes;
      for (uint32_t k : {i * sides + j, (i + 1) * sides + j, i * sides + j + 1, (i + 1) * sides + j + 1})
        hole_of[k] = static_cast<uint32_t>(out.holes);
    }
  }
  out.mesh.positions = torus.positions;
  size_t removed = 0;
  for (size_t f = 0; f < torus.num_faces(); ++f) {
    const auto c = torus.face(f);
    if (hole_of[c[0]] != 0 && hole_of[c[0]] == hole_of[c[1]] && hole_of[c[0]] == hole_of[c[2]]) {
      ++removed;
      continue;
    }
    out.mesh.add_face(c);
  }
  if (out.holes == 0 || removed != 2 * out.holes)
    throw std::logic_error("make_torus_with_holes: the torus is not numbered as expected");
  return out;
}

}  // namespace meshedit::bench
