// STL (.stl): triangle soups, read into an indexed polygon mesh and written.
//
// Read: binary (an 80-byte header, a uint32 triangle count, then 50 bytes per triangle: a normal, three
// float corners and a 16-bit attribute) and ASCII ("solid NAME / facet normal ... / outer loop /
// vertex x y z (three times) / endloop / endfacet / endsolid NAME", several solids allowed). A file is
// binary when its size is exactly 84 + 50 * count, or when it does not start with "solid" (some binary
// exporters start their header with "solid", so the size decides first); trailing bytes after a binary
// file's triangles are ignored. Stored normals and attributes are ignored.
// Corners are merged by exact position (+0 and -0 are one position), in order of first appearance, so
// the result is an indexed mesh whose shared edges connect. A triangle whose corners merge into fewer
// than three vertices is kept as the file has it (nothing is dropped silently: the builder refuses it by its
// number and mesh repair drops it with a report); a file with no triangles is refused.
// Errors name the file and the place: the line for ASCII ("part.stl:9: expected \"vertex\", found
// \"endloop\""), the triangle and byte offset for binary ("part.stl: triangle 3, byte 234: ...").
//
// Write: binary, with a normal per triangle; polygons of more than three corners are split into triangles
// by ear clipping in their plane (core/triangulate.h), so a non-convex face stays inside itself. Coordinates are
// stored as float, as the format requires, so a round trip keeps positions exactly only when they are
// floats; a position beyond the float range is refused.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/polygon_mesh.h"

namespace meshedit {

// `name` is the file name used in error messages.
PolygonMesh parse_stl(std::string_view bytes, const std::string& name);
PolygonMesh read_stl(const std::filesystem::path& path);

std::string format_stl(const PolygonMesh& mesh, const std::string& name);
void write_stl(const std::filesystem::path& path, const PolygonMesh& mesh);

}  // namespace meshedit
