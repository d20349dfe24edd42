// Checks a PolygonMesh before a writer turns it into a file, so that every file MeshEdit writes is one
// its own readers accept: well-formed face offsets, faces of at least 3 corners, indices in range,
// finite positions, and sizes within io_limits.h.
#pragma once

#include <string>

#include "core/polygon_mesh.h"

namespace meshedit {

// Throws FileError(file, "face 3", "refers to vertex 9, but the mesh has 8 vertices") and the like.
void require_writable(const PolygonMesh& mesh, const std::string& file);

}  // namespace meshedit
