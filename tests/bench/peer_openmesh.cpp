// peer_bench's OpenMesh contender (compiled only when CMake finds OpenMesh): TriMesh_ArrayKernelT with
// double points (so its output can be compared with ours to 1e-9), built with add_vertex/add_face after
// reserve(), subdivided by OpenMesh::Subdivider::Uniform::LoopT, normals by the same face loop as CGAL's.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <stdexcept>

#include "bench/peer_contender.h"

namespace meshedit::bench {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

glm::dvec3 to_glm(const Mesh::Point& p) { return {p[0], p[1], p[2]}; }

class OpenMeshContender final : public Contender {
 public:
  std::string name() const override { return "OpenMesh"; }
  std::string library() const override {
    return "OpenMesh " + std::to_string(OM_GET_VER) + "." + std::to_string(OM_GET_MAJ) +
           " (TriMesh_ArrayKernelT, Vec3d points)";
  }
  // LoopT::smooth: boundary vertex (v_l + 6 v + v_r) / 8; compute_midpoint: boundary edge midpoint.
  std::string boundary_rule() const override { return "(v_l + 6 v + v_r) / 8, edge midpoint (LoopT)"; }
  bool boundary_rule_like_ours() const override { return true; }

  void build(const PolygonMesh& triangles) override {
    mesh_ = std::make_unique<Mesh>();  // a fresh mesh: assigning to the old one would keep its capacity
    Mesh& mesh = *mesh_;
    const size_t faces = triangles.num_faces();
    mesh.reserve(triangles.num_vertices(), triangles.num_vertices() + faces, faces);
    for (const glm::dvec3& p : triangles.positions) mesh.add_vertex(Mesh::Point(p.x, p.y, p.z));
    for (size_t f = 0; f < faces; ++f) {
      const auto c = triangles.face(f);
      if (c.size() != 3) throw std::runtime_error("OpenMesh contender: face is not a triangle");
      const auto added = mesh.add_face(OpenMesh::VertexHandle(int(c[0])), OpenMesh::VertexHandle(int(c[1])),
                                       OpenMesh::VertexHandle(int(c[2])));
      if (!added.is_valid()) throw std::runtime_error("OpenMesh refused face " + std::to_string(f));
    }
  }

  void subdivide(int levels, int /*threads*/) override {
    OpenMesh::Subdivider::Uniform::LoopT<Mesh> loop;
    if (!loop.attach(*mesh_) || !loop(size_t(levels))) throw std::runtime_error("OpenMesh LoopT failed");
    loop.detach();
  }

  void compute_normals(int /*threads*/) override {
    normals_.assign(mesh_->n_vertices(), glm::dvec3(0.0));
    for (const auto f : mesh_->faces()) {
      const auto h0 = mesh_->halfedge_handle(f);
      const auto h1 = mesh_->next_halfedge_handle(h0);
      const auto h2 = mesh_->next_halfedge_handle(h1);
      const auto a = mesh_->to_vertex_handle(h0), b = mesh_->to_vertex_handle(h1), c = mesh_->to_vertex_handle(h2);
      const Mesh::Point& pa = mesh_->point(a);
      const Mesh::Point n = (mesh_->point(b) - pa) % (mesh_->point(c) - pa);  // % is the cross product
      const glm::dvec3 term(n[0], n[1], n[2]);
      normals_[a.idx()] += term;
      normals_[b.idx()] += term;
      normals_[c.idx()] += term;
    }
    normalise_sums(normals_);
  }
  void drop_normals() override { normals_ = {}; }
  void clear() override {
    mesh_ = std::make_unique<Mesh>();
    normals_ = {};
  }

  MeshCounts counts() const override { return {mesh_->n_vertices(), mesh_->n_edges(), mesh_->n_faces()}; }

  VertexData vertex_data() const override {
    VertexData data;
    for (const auto v : mesh_->vertices()) {
      data.position.push_back(to_glm(mesh_->point(v)));
      data.normal.push_back(size_t(v.idx()) < normals_.size() ? normals_[v.idx()] : glm::dvec3(0.0));
      data.on_boundary.push_back(mesh_->is_boundary(v) ? 1 : 0);
    }
    return data;
  }

 private:
  std::unique_ptr<Mesh> mesh_ = std::make_unique<Mesh>();  // replaced, never reassigned (see build)
  std::vector<glm::dvec3> normals_;
};

}  // namespace

std::unique_ptr<Contender> make_openmesh() { return std::make_unique<OpenMeshContender>(); }

}  // namespace meshedit::bench
