// peer_bench's MeshEdit contender: the public core API only (build_halfedge_mesh, loop_subdivide with
// LoopWeights::Loop once per level, vertex_normals), so it measures whatever the core is at the time.
// A thread count is passed only when the core's functions take one (detected at compile time below).
#include <stdexcept>

#include "bench/peer_contender.h"
#include "core/halfedge_mesh.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/normals.h"

namespace meshedit::bench {
namespace {

// True when the core offers loop_subdivide(mesh, weights, levels, threads) / vertex_normals(mesh, threads).
// Templates so that the call is only looked at, never compiled, while the core does not have it.
template <class Mesh>
constexpr bool kLoopTakesThreads = requires(Mesh& m) { loop_subdivide(m, LoopWeights::Loop, 1, 2); };
template <class Mesh>
constexpr bool kNormalsTakeThreads = requires(const Mesh& m) { vertex_normals(m, 2); };

template <class Mesh>
Check subdivide_once(Mesh& mesh, int threads) {
  if constexpr (kLoopTakesThreads<Mesh>) {
    return loop_subdivide(mesh, LoopWeights::Loop, 1, threads);
  } else {
    (void)threads;
    return loop_subdivide(mesh, LoopWeights::Loop);
  }
}

template <class Mesh>
std::vector<glm::dvec3> normals_of(const Mesh& mesh, int threads) {
  if constexpr (kNormalsTakeThreads<Mesh>) {
    return vertex_normals(mesh, threads);
  } else {
    (void)threads;
    return vertex_normals(mesh);
  }
}

class Ours final : public Contender {
 public:
  std::string name() const override { return "ours"; }
  std::string library() const override { return "MeshEdit core (HalfedgeMesh, double positions)"; }
  std::string boundary_rule() const override { return "3/4 p + 1/8 boundary neighbours, edge midpoint"; }
  bool boundary_rule_like_ours() const override { return true; }
  bool takes_threads_for_subdivision() const override { return kLoopTakesThreads<HalfedgeMesh>; }
  bool takes_threads_for_normals() const override { return kNormalsTakeThreads<HalfedgeMesh>; }

  void build(const PolygonMesh& triangles) override { mesh_ = build_halfedge_mesh(triangles); }

  void subdivide(int levels, int threads) override {
    for (int i = 0; i < levels; ++i) {
      const Check done = subdivide_once(mesh_, threads);
      if (!done) throw std::runtime_error("loop_subdivide refused: " + done.reason);
    }
  }

  void compute_normals(int threads) override { normals_ = normals_of(mesh_, threads); }
  void drop_normals() override { normals_ = {}; }
  void clear() override {
    mesh_ = HalfedgeMesh();
    normals_ = {};
  }

  MeshCounts counts() const override { return {mesh_.num_vertices(), mesh_.num_edges(), mesh_.num_faces()}; }

  VertexData vertex_data() const override {
    VertexData data;
    data.position.reserve(mesh_.num_vertices());
    data.normal.reserve(mesh_.num_vertices());
    data.on_boundary.reserve(mesh_.num_vertices());
    for (VertexId v : mesh_.vertices()) {
      data.position.push_back(mesh_.position(v));
      data.normal.push_back(v.index < normals_.size() ? normals_[v.index] : glm::dvec3(0.0));
      data.on_boundary.push_back(mesh_.is_boundary(v) ? 1 : 0);
    }
    return data;
  }

  long long self_reported_bytes() const override { return static_cast<long long>(mesh_.memory_bytes()); }

 private:
  HalfedgeMesh mesh_;
  std::vector<glm::dvec3> normals_;
};

}  // namespace

std::unique_ptr<Contender> make_ours() { return std::make_unique<Ours>(); }

}  // namespace meshedit::bench
