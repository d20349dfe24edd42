// peer_bench's CGAL contender (compiled only when CMake finds CGAL): Surface_mesh<Point_3> of
// Simple_cartesian<double>, built with add_vertex/add_face after reserve(), subdivided by
// CGAL::Subdivision_method_3::Loop_subdivision, normals by the same face loop as OpenMesh's.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version_macros.h>

#include <stdexcept>

#include "bench/peer_contender.h"

namespace meshedit::bench {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

class CgalContender final : public Contender {
 public:
  std::string name() const override { return "CGAL"; }
  std::string library() const override {
    return std::string("CGAL ") + CGAL_VERSION_STR + " (Surface_mesh<Simple_cartesian<double>::Point_3>)";
  }
  // Loop_mask_3::border_node: boundary vertex (v_-1 + 6 v + v_1) / 8, boundary edge point the midpoint.
  std::string boundary_rule() const override { return "(v_-1 + 6 v + v_1) / 8, edge midpoint (Loop_mask_3)"; }
  bool boundary_rule_like_ours() const override { return true; }

  void build(const PolygonMesh& triangles) override {
    mesh_ = std::make_unique<Mesh>();  // a fresh mesh: assigning to the old one would keep its capacity
    Mesh& mesh = *mesh_;
    const size_t faces = triangles.num_faces();
    mesh.reserve(Mesh::size_type(triangles.num_vertices()), Mesh::size_type(triangles.num_vertices() + faces),
                 Mesh::size_type(faces));
    for (const glm::dvec3& p : triangles.positions) mesh.add_vertex(Point(p.x, p.y, p.z));
    for (size_t f = 0; f < faces; ++f) {
      const auto c = triangles.face(f);
      if (c.size() != 3) throw std::runtime_error("CGAL contender: face is not a triangle");
      const auto added = mesh.add_face(Mesh::Vertex_index(c[0]), Mesh::Vertex_index(c[1]), Mesh::Vertex_index(c[2]));
      if (added == Mesh::null_face()) throw std::runtime_error("CGAL refused face " + std::to_string(f));
    }
  }

  void subdivide(int levels, int /*threads*/) override {
    CGAL::Subdivision_method_3::Loop_subdivision(*mesh_, CGAL::parameters::number_of_iterations(levels));
  }

  void compute_normals(int /*threads*/) override {
    normals_.assign(mesh_->number_of_vertices(), glm::dvec3(0.0));
    for (const auto f : mesh_->faces()) {
      const auto h0 = mesh_->halfedge(f);
      const auto h1 = mesh_->next(h0);
      const auto h2 = mesh_->next(h1);
      const auto a = mesh_->target(h0), b = mesh_->target(h1), c = mesh_->target(h2);
      const Point& pa = mesh_->point(a);
      const Kernel::Vector_3 n = CGAL::cross_product(mesh_->point(b) - pa, mesh_->point(c) - pa);
      const glm::dvec3 term(n.x(), n.y(), n.z());
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

  MeshCounts counts() const override {
    return {mesh_->number_of_vertices(), mesh_->number_of_edges(), mesh_->number_of_faces()};
  }

  VertexData vertex_data() const override {
    VertexData data;
    for (const auto v : mesh_->vertices()) {
      const Point& p = mesh_->point(v);
      data.position.emplace_back(p.x(), p.y(), p.z());
      data.normal.push_back(v.idx() < normals_.size() ? normals_[v.idx()] : glm::dvec3(0.0));
      data.on_boundary.push_back(mesh_->is_border(v) ? 1 : 0);
    }
    return data;
  }

 private:
  std::unique_ptr<Mesh> mesh_ = std::make_unique<Mesh>();  // replaced, never reassigned (see build)
  std::vector<glm::dvec3> normals_;
};

}  // namespace

std::unique_ptr<Contender> make_cgal() { return std::make_unique<CgalContender>(); }

}  // namespace meshedit::bench
