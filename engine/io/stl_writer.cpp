// STL writing (see stl_io.h): binary, polygons split into triangles by ear clipping (core/triangulate.h, so a
// non-convex face is cut inside itself), a unit normal per triangle.
#include <cfloat>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/triangulate.h"
#include "io/binary_bytes.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/polygon_checks.h"
#include "io/stl_io.h"

namespace meshedit {

std::string format_stl(const PolygonMesh& mesh, const std::string& name) {
  require_writable(mesh, name);
  for (size_t v = 0; v < mesh.num_vertices(); ++v) {
    const glm::dvec3& p = mesh.positions[v];
    if (std::abs(p.x) > FLT_MAX || std::abs(p.y) > FLT_MAX || std::abs(p.z) > FLT_MAX) {
      throw FileError(name, "vertex " + std::to_string(v), "position does not fit STL's float coordinates");
    }
  }
  size_t triangles = 0;
  for (size_t f = 0; f < mesh.num_faces(); ++f) triangles += mesh.face(f).size() - 2;

  // The header must not start with "solid", or readers could take the file for ASCII.
  std::string out = "MeshEdit binary STL";
  out.resize(80, ' ');
  append_unsigned_le(out, triangles, 4);
  out.reserve(out.size() + triangles * 50);
  auto append_vector = [&out](const glm::dvec3& v) {
    for (int a = 0; a < 3; ++a) append_float_le(out, static_cast<float>(v[a]));
  };
  std::vector<glm::dvec3> points;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const auto corners = mesh.face(f);
    points.clear();
    for (const uint32_t corner : corners) points.push_back(mesh.positions[corner]);
    const std::vector<uint32_t> triangles_of_face = triangulate_polygon(points);
    for (size_t t = 0; t + 2 < triangles_of_face.size(); t += 3) {
      const glm::dvec3& a = points[triangles_of_face[t]];
      const glm::dvec3& b = points[triangles_of_face[t + 1]];
      const glm::dvec3& c = points[triangles_of_face[t + 2]];
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double length = glm::length(n);
      append_vector(length > 0 && std::isfinite(length) ? n / length : glm::dvec3(0));
      append_vector(a);
      append_vector(b);
      append_vector(c);
      append_unsigned_le(out, 0, 2);
    }
  }
  return out;
}

void write_stl(const std::filesystem::path& path, const PolygonMesh& mesh) {
  write_file(path, format_stl(mesh, path.string()));
}

}  // namespace meshedit
