// Object File Format (.off, Geomview's, used by the Princeton Shape Benchmark and ModelNet): polygon
// meshes, read.
//
// Read: an optional keyword OFF with the prefixes C (vertex colours), N (vertex normals) and ST (texture
// coordinates) in any combination ("COFF", "NOFF", "STCNOFF"); then the vertex, face and edge counts
// (the edge count may be missing; it is never used); then one vertex per line ("x y z", anything after
// the three coordinates, such as colours or normals, dropped); then one face per line ("n i1 ... in",
// 0-based, anything after the indices, such as a colour, dropped). Comments run from '#' to the end of
// the line; blank lines are skipped. The counts may follow the keyword on its line, even without a
// space ("OFF490 518 0", as many ModelNet files have it). Binary OFF and the 4D and n-dimensional
// variants (4OFF, nOFF) are refused, as are indices out of range. Every face is kept as the file has it, whatever its
// number of corners: the half-edge builder refuses a face of fewer than 3 corners or a repeated corner by its number
// and mesh repair drops it with a report.
// Errors name the line: "chair.off:12: face 3: index 8 is not below the vertex count 8".
// Declared counts are checked against io_limits.h and the numbers the file really holds before
// anything is allocated.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/polygon_mesh.h"

namespace meshedit {

// `name` is the file name used in error messages.
PolygonMesh parse_off(std::string_view text, const std::string& name);
PolygonMesh read_off(const std::filesystem::path& path);

}  // namespace meshedit
