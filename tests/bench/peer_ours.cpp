// peer_bench's MeshEdit contender: the public core API only (build_halfedge_mesh, loop_subdivide with
// LoopWeights::Loop for all levels in one call, vertex_normals into the contender's vector, as the peers fill
// theirs), so it measures whatever the core is at the time.
#include <stdexcept>

#include "bench/peer_contender.h"
#include "core/halfedge_mesh.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/normals.h"

namespace meshedit::bench {
namespace {

class Ours final : public Contender {
 public:
  std::string name() const override { return "ours"; }
  std::string library() const override { return "MeshEdit core (HalfedgeMesh, double positions)"; }
  std::string boundary_rule() const override { return "3/4 p + 1/8 boundary neighbours, edge midpoint"; }
  bool boundary_rule_like_ours() const override { return true; }
  bool takes_threads_for_subdivision() const override { return true; }
  bool takes_threads_for_normals() const override { return true; }

  void build(const PolygonMesh& triangles) override { mesh_ = build_halfedge_mesh(triangles); }

  // All levels in one call: the input is checked once and the arrays are sized once for the last level.
  void subdivide(int levels, int threads) override {
    const Check done = loop_subdivide(mesh_, LoopWeights::Loop, levels, threads);
    if (!done) throw std::runtime_error("loop_subdivide refused: " + done.reason);
  }

  void compute_normals(int threads) override { vertex_normals(mesh_, normals_, threads); }
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
