// What area-weighted vertex normals could cost on a mesh with no half-edge chase at all: a bare index buffer (three
// corner ids per face, made outside the timing) scattered into per-vertex sums, once with the mesh's own vertex ids
// and once with the vertices renumbered in first-touch order (what a cache-ordered, renumbered Loop output would
// give). mesh_bench prints both beside the core's vertex_normals, as the floor peer_bench's normals row runs into:
// the first needs a derived 12 B/face buffer, the second also new ids, which the stable-id design rules out.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "bench/bench_support.h"
#include "core/halfedge_mesh.h"

namespace meshedit::bench {

inline void print_normals_floor(const HalfedgeMesh& mesh, int reps) {
  // A valid triangle mesh (just built or subdivided): every face slot live, three halfedges each.
  std::vector<uint32_t> corners;
  corners.reserve(size_t(mesh.face_capacity()) * 3);
  for (FaceId f : mesh.faces()) {
    HalfedgeId h = mesh.halfedge(f);
    for (int k = 0; k < 3; ++k, h = mesh.next(h)) corners.push_back(mesh.vertex(h).index);
  }
  std::vector<glm::dvec3> positions(mesh.vertex_capacity()), sums(mesh.vertex_capacity());
  for (VertexId v : mesh.vertices()) positions[v.index] = mesh.position(v);
  const auto scatter = [&](const std::vector<uint32_t>& ids, const std::vector<glm::dvec3>& at) {
    std::fill(sums.begin(), sums.end(), glm::dvec3(0.0));
    for (size_t i = 0; i + 2 < ids.size(); i += 3) {
      const glm::dvec3 a = at[ids[i]], b = at[ids[i + 1]], c = at[ids[i + 2]];
      const glm::dvec3 term = glm::cross(b - a, c - a);
      sums[ids[i]] += term;
      sums[ids[i + 1]] += term;
      sums[ids[i + 2]] += term;
    }
    for (glm::dvec3& n : sums) {
      const double length = glm::length(n);
      if (length > 0.0) n /= length;
    }
  };
  std::printf("%-34s %9.2f ms\n", "normals floor, buffer, our ids",
              min_ms(
                  reps, [] {}, [&] { scatter(corners, positions); }));
  std::vector<uint32_t> renumbered(corners.size()), new_id(positions.size(), UINT32_MAX);
  uint32_t next = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (new_id[corners[i]] == UINT32_MAX) new_id[corners[i]] = next++;
    renumbered[i] = new_id[corners[i]];
  }
  std::vector<glm::dvec3> moved(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    if (new_id[v] != UINT32_MAX) moved[new_id[v]] = positions[v];
  }
  std::printf("%-34s %9.2f ms\n", "normals floor, buffer, new ids",
              min_ms(
                  reps, [] {}, [&] { scatter(renumbered, moved); }));
}

}  // namespace meshedit::bench
