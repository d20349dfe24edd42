// Pre-write checks of a PolygonMesh (see polygon_checks.h).
#include "io/polygon_checks.h"

#include <cmath>

#include "io/file_error.h"
#include "io/io_limits.h"

namespace meshedit {

void require_writable(const PolygonMesh& mesh, const std::string& file) {
  if (mesh.positions.size() > kMaxVertices || mesh.indices.size() > kMaxCorners) {
    throw FileError(file, "",
                    "mesh is too large to write (" + std::to_string(mesh.positions.size()) + " vertices, " +
                        std::to_string(mesh.indices.size()) + " corners)");
  }
  if (mesh.face_offsets.empty() || mesh.face_offsets.front() != 0 || mesh.face_offsets.back() != mesh.indices.size()) {
    throw FileError(file, "", "mesh face offsets do not cover its indices");
  }
  if (mesh.num_faces() == 0) throw FileError(file, "", "mesh has no faces");
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.face_offsets[f + 1] < mesh.face_offsets[f]) {
      throw FileError(file, "face " + std::to_string(f), "face offsets decrease");
    }
    const auto corners = mesh.face(f);
    if (corners.size() < 3) {
      throw FileError(file, "face " + std::to_string(f),
                      "has " + std::to_string(corners.size()) + " corners; at least 3 are needed");
    }
    for (uint32_t v : corners) {
      if (v >= mesh.positions.size()) {
        throw FileError(file, "face " + std::to_string(f),
                        "refers to vertex " + std::to_string(v) + ", but the mesh has " +
                            std::to_string(mesh.positions.size()) + " vertices");
      }
    }
  }
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3& p = mesh.positions[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw FileError(file, "vertex " + std::to_string(v), "position is not finite");
    }
  }
}

}  // namespace meshedit
