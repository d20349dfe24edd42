// Mesh counts, components, Euler characteristic and genus (see mesh_stats.h).
#include "core/mesh_stats.h"

#include <numeric>
#include <vector>

namespace meshedit {
namespace {

// Union-find over vertex ids, with path halving.
struct Components {
  std::vector<uint32_t> parent;
  explicit Components(uint32_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace

MeshStats compute_stats(const HalfedgeMesh& mesh) {
  MeshStats s;
  s.vertices = mesh.num_vertices();
  s.edges = mesh.num_edges();
  s.faces = mesh.num_faces();
  s.halfedges = mesh.num_halfedges();
  s.boundary_loops = mesh.num_boundaries();
  s.euler_characteristic = long(s.vertices) - long(s.edges) + long(s.faces);

  Components components(mesh.vertex_capacity());
  for (HalfedgeId h : mesh.halfedges()) {
    const VertexId a = mesh.vertex(h);
    const HalfedgeId t = mesh.twin(h);
    if (!mesh.alive(a) || !mesh.alive(t) || !mesh.alive(mesh.vertex(t))) continue;
    components.join(a.index, mesh.vertex(t).index);
  }
  for (VertexId v : mesh.vertices()) s.components += components.find(v.index) == v.index ? 1 : 0;

  for (FaceId f : mesh.faces()) {
    if (mesh.degree(f) != 3) {
      s.triangles_only = false;
      break;
    }
  }
  const long twice_genus = 2 * long(s.components) - s.euler_characteristic - long(s.boundary_loops);
  if (twice_genus >= 0 && twice_genus % 2 == 0) s.genus = twice_genus / 2;
  return s;
}

}  // namespace meshedit
