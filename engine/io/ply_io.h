// Stanford PLY (.ply): polygon meshes, read and written.
//
// Read: ASCII, binary_little_endian and binary_big_endian bodies. The "vertex" element must have scalar
// properties x, y and z of any PLY number type (float and double in practice). Faces come from the "face" element, a
// list named vertex_indices (or vertex_index, as some scanners write) with any integer count and index types, and
// from a "tristrips" element (how some of the old Stanford scans store their triangles): one list of vertex indices
// per item, strips separated by -1, each strip read as its triangles with every other one flipped so that all keep
// the strip's first winding, skipping the degenerate triangles (two corners the same vertex) that join strips. A
// file needs one of the two elements; with both, the polygons are added in the order the elements come in the file.
// Every other property (normals, colours, confidence, texture coordinates) and every other element
// (edge, material, ...) is read past and dropped. Indices must be below the vertex count and positions finite; every
// face is kept as the file has it, whatever its number of corners (a face of one corner, a repeated corner): the
// half-edge builder refuses such a face by its number and mesh repair drops it with a report. Files with no faces are
// refused.
// Errors name the file and the place: the line for the header and ASCII bodies
// ("bunny.ply:14: face 3: index 36000 is not below the vertex count 35947"), and the element and byte
// offset for binary bodies ("bunny.ply: face 3, byte 1044: ..."). Declared counts are checked against
// io_limits.h and against the bytes (or tokens) the file really holds before anything is allocated.
//
// Write: binary_little_endian with `element vertex` (x y z as float when every coordinate is exactly a
// float, else as double, so nothing is rounded) and `element face` with `property list uchar int
// vertex_indices` (uint count type if a face has more than 255 corners), the layout Blender and MeshLab
// write. parse_ply(format_ply(m)) == m for any mesh require_writable accepts.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/polygon_mesh.h"

namespace meshedit {

// `name` is the file name used in error messages.
PolygonMesh parse_ply(std::string_view bytes, const std::string& name);
PolygonMesh read_ply(const std::filesystem::path& path);

std::string format_ply(const PolygonMesh& mesh, const std::string& name);
void write_ply(const std::filesystem::path& path, const PolygonMesh& mesh);

}  // namespace meshedit
