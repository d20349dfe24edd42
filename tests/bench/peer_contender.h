// The interface peer_bench times: one half-edge library ("contender") behind the same calls, so
// MeshEdit, OpenMesh and CGAL get the same input and the same treatment. Each contender lives in its own
// file (peer_ours.cpp, peer_openmesh.cpp, peer_cgal.cpp); the peers are compiled only when CMake finds
// the library, which then defines MESHEDIT_HAVE_OPENMESH / MESHEDIT_HAVE_CGAL.
#pragma once

#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/polygon_mesh.h"

namespace meshedit::bench {

struct MeshCounts {
  size_t vertices = 0, edges = 0, faces = 0;
  bool operator==(const MeshCounts&) const = default;
};

// Live vertices in the contender's own order: position, the last computed normal (zero if none), and
// 1 for a vertex on a boundary.
// The last step of the peers' area-weighted normals (the same code in each): every summed vector to unit length,
// zero sums left as they are.
inline void normalise_sums(std::vector<glm::dvec3>& sums) {
  for (glm::dvec3& n : sums) {
    const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (length > 0.0) n /= length;
  }
}

struct VertexData {
  std::vector<glm::dvec3> position;
  std::vector<glm::dvec3> normal;
  std::vector<unsigned char> on_boundary;
};

class Contender {
 public:
  virtual ~Contender() = default;
  virtual std::string name() const = 0;
  // The library, its version and the mesh type used, for the header of the output.
  virtual std::string library() const = 0;
  // The boundary rule of its Loop subdivision, in words, and whether it is ours
  // (boundary vertex 3/4 p + 1/8 of its two boundary neighbours, boundary edge point at the midpoint).
  virtual std::string boundary_rule() const = 0;
  virtual bool boundary_rule_like_ours() const = 0;
  // Whether its subdivision / normals use the `threads` argument (false: single thread only).
  virtual bool takes_threads_for_subdivision() const { return false; }
  virtual bool takes_threads_for_normals() const { return false; }

  // Builds a half-edge mesh from the indexed triangles, replacing the one held. Throws on refusal.
  virtual void build(const PolygonMesh& triangles) = 0;
  // `levels` Loop subdivision steps with Loop's original weights. Throws on refusal.
  virtual void subdivide(int levels, int threads) = 0;
  // Area-weighted vertex normals of the mesh held (sum of the faces' edge cross products, normalised),
  // kept for vertex_data().
  virtual void compute_normals(int threads) = 0;
  virtual void drop_normals() = 0;
  // Releases the mesh and the normals.
  virtual void clear() = 0;

  virtual MeshCounts counts() const = 0;
  virtual VertexData vertex_data() const = 0;
  // The bytes the mesh says it holds (its own capacity accounting), or -1 if the library has none.
  virtual long long self_reported_bytes() const { return -1; }
};

std::unique_ptr<Contender> make_ours();
#ifdef MESHEDIT_HAVE_OPENMESH
std::unique_ptr<Contender> make_openmesh();
#endif
#ifdef MESHEDIT_HAVE_CGAL
std::unique_ptr<Contender> make_cgal();
#endif

}  // namespace meshedit::bench
