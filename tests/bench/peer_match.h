// Checks that two contenders' meshes are the same point set: every compared vertex of ours has exactly
// one vertex of theirs within tolerance (found through a grid hash, since the libraries number vertices
// differently), with the same boundary flag and the same normal. Used by peer_bench before any time is
// printed; a checksum alone could hide a permutation of errors.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "bench/peer_contender.h"

namespace meshedit::bench {

struct MatchOptions {
  double position_tolerance = 1e-9;  // relative to the largest |p| of our mesh
  double normal_tolerance = 1e-9;    // absolute, on unit normals
  // Ours' vertices to leave out (1 = skip); empty = compare all and require equal vertex counts.
  const std::vector<unsigned char>* skip = nullptr;
};

struct MatchReport {
  bool ok = false;
  size_t compared = 0;
  double max_position_error = 0.0;  // relative, as the tolerance
  double max_normal_error = 0.0;
  std::string problem;  // the first failure, empty when ok
};

MatchReport match_vertices(const VertexData& ours, const VertexData& theirs, const MatchOptions& options);

// 1 for ours' vertices within `radius` of one of ours' boundary vertices (those a different boundary
// rule can move), else 0.
std::vector<unsigned char> near_boundary(const VertexData& ours, double radius);

// The longest edge of the triangles (the unit `near_boundary` radii are measured in).
double longest_edge(const PolygonMesh& triangles);

}  // namespace meshedit::bench
