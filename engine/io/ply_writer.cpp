// PLY writing (see ply_io.h): binary little endian, float coordinates when that loses nothing.
#include "io/binary_bytes.h"
#include "io/file_access.h"
#include "io/ply_io.h"
#include "io/polygon_checks.h"

namespace meshedit {
namespace {

bool all_exact_floats(const PolygonMesh& mesh) {
  for (const glm::dvec3& p : mesh.positions) {
    for (int a = 0; a < 3; ++a) {
      if (double(static_cast<float>(p[a])) != p[a]) return false;
    }
  }
  return true;
}

}  // namespace

std::string format_ply(const PolygonMesh& mesh, const std::string& name) {
  require_writable(mesh, name);
  const bool floats = all_exact_floats(mesh);
  size_t most_corners = 0;
  for (size_t f = 0; f < mesh.num_faces(); ++f) most_corners = std::max(most_corners, mesh.face(f).size());
  const bool byte_counts = most_corners <= 255;
  const char* coordinate = floats ? "float" : "double";

  std::string out = "ply\nformat binary_little_endian 1.0\ncomment MeshEdit\n";
  out += "element vertex " + std::to_string(mesh.num_vertices()) + "\n";
  for (const char* axis : {"x", "y", "z"}) out += std::string("property ") + coordinate + " " + axis + "\n";
  out += "element face " + std::to_string(mesh.num_faces()) + "\n";
  out += std::string("property list ") + (byte_counts ? "uchar" : "uint") + " int vertex_indices\nend_header\n";
  for (const glm::dvec3& p : mesh.positions) {
    for (int a = 0; a < 3; ++a) floats ? append_float_le(out, static_cast<float>(p[a])) : append_double_le(out, p[a]);
  }
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const auto corners = mesh.face(f);
    append_unsigned_le(out, corners.size(), byte_counts ? 1 : 4);
    for (uint32_t v : corners) append_unsigned_le(out, v, 4);
  }
  return out;
}

void write_ply(const std::filesystem::path& path, const PolygonMesh& mesh) {
  write_file(path, format_ply(mesh, path.string()));
}

}  // namespace meshedit
