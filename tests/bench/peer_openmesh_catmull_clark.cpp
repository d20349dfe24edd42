// peer_bench's OpenMesh Catmull-Clark contender (compiled only when CMake finds OpenMesh): PolyMesh_ArrayKernelT
// with double points, built with add_vertex/add_face after reserve(), subdivided by
// OpenMesh::Subdivider::Uniform::CatmullClarkT.
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include <stdexcept>
#include <vector>

#include "bench/peer_catmull_clark.h"

namespace meshedit::bench {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

class OpenMeshCatmullClark final : public CatmullClarkContender {
 public:
  std::string name() const override { return "OpenMesh"; }
  // CatmullClarkT::update_vertex: a boundary vertex goes to (p + its two boundary edges' midpoints) / 3.
  std::string boundary_rule() const override { return "2/3 p + 1/6 boundary neighbours (CatmullClarkT)"; }
  bool boundary_rule_like_ours() const override { return false; }

  void build(const PolygonMesh& polygons) override {
    mesh_ = std::make_unique<Mesh>();
    Mesh& mesh = *mesh_;
    mesh.reserve(polygons.num_vertices(), polygons.num_vertices() + polygons.num_faces(), polygons.num_faces());
    for (const glm::dvec3& p : polygons.positions) mesh.add_vertex(Mesh::Point(p.x, p.y, p.z));
    std::vector<OpenMesh::VertexHandle> corners;
    for (size_t f = 0; f < polygons.num_faces(); ++f) {
      corners.clear();
      for (uint32_t i : polygons.face(f)) corners.emplace_back(int(i));
      if (!mesh.add_face(corners).is_valid()) throw std::runtime_error("OpenMesh refused face " + std::to_string(f));
    }
  }

  void subdivide(int levels) override {
    OpenMesh::Subdivider::Uniform::CatmullClarkT<Mesh> catmull_clark;
    if (!catmull_clark.attach(*mesh_) || !catmull_clark(size_t(levels)))
      throw std::runtime_error("OpenMesh CatmullClarkT failed");
    catmull_clark.detach();
  }

  void clear() override { mesh_ = std::make_unique<Mesh>(); }

  MeshCounts counts() const override { return {mesh_->n_vertices(), mesh_->n_edges(), mesh_->n_faces()}; }

  VertexData vertex_data() const override {
    VertexData data;
    for (const auto v : mesh_->vertices()) {
      const Mesh::Point& p = mesh_->point(v);
      data.position.emplace_back(p[0], p[1], p[2]);
      data.normal.emplace_back(0.0);
      data.on_boundary.push_back(mesh_->is_boundary(v) ? 1 : 0);
    }
    return data;
  }

 private:
  std::unique_ptr<Mesh> mesh_ = std::make_unique<Mesh>();
};

}  // namespace

std::unique_ptr<CatmullClarkContender> make_openmesh_catmull_clark() {
  return std::make_unique<OpenMeshCatmullClark>();
}

}  // namespace meshedit::bench
