// Counts and topology of a half-edge mesh, as `meshedit info` prints them.
//
// Euler characteristic chi = V - E + F counts real faces only (boundary loops are holes, not faces).
// For a mesh whose components are all closed, genus = (2 * components - chi) / 2; with boundaries the
// genus is still defined per surface as (2C - chi - B) / 2, and that is what we report.
#pragma once

#include <cstddef>
#include <optional>

#include "core/halfedge_mesh.h"

namespace meshedit {

struct MeshStats {
  size_t vertices = 0, edges = 0, faces = 0, halfedges = 0, boundary_loops = 0;
  size_t components = 0;  // connected pieces (through edges)
  long euler_characteristic = 0;
  std::optional<long> genus;  // absent when the count does not come out whole (a broken mesh)
  bool closed() const { return boundary_loops == 0; }
  bool triangles_only = true;  // every real face has 3 sides
};

// Bounded like validate(): safe on any mesh. Components are found through each live halfedge's vertex
// and its twin's vertex, so a broken mesh gives a number, not a crash.
MeshStats compute_stats(const HalfedgeMesh& mesh);

}  // namespace meshedit
