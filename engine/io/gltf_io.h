// glTF 2.0 (.gltf JSON and .glb binary): polygon meshes, read and written through tinygltf.
//
// Read:
// - every mesh primitive of mode TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN (strips and fans become
//   triangles; a strip's degenerate stitching triangles are dropped); POINTS and LINES primitives are
//   skipped without error. Indexed (uint8/16/32) or not. POSITION must be a float VEC3 accessor; byte
//   strides and sparse accessors are honoured. Primitives of one mesh instance that share a POSITION
//   accessor share its vertices; otherwise every primitive has vertices of its own (glTF does not
//   weld, and neither do we: seams stay open).
// - the default scene's node trees, or, without a default scene, every root node; each mesh a node
//   refers to is added with the node's world transform (matrix, or translation * rotation * scale)
//   applied. A transform with a negative determinant reverses the triangles so normals stay outward.
//   A file without nodes gets each mesh once, untransformed. Nodes must form a tree (no node reached
//   twice), as the specification requires.
// - every accessor, buffer view and index is checked against the bytes that really exist before it is
//   read, so hostile files give a FileError, never an out-of-bounds read. Images are never decoded.
//   External buffers (.bin) are read only beside a file on disk (read_gltf), never when parsing from
//   memory, and only from regular files.
// Errors name the file and the glTF object: "scene.gltf: accessor 3: count 4000000000 exceeds the
// buffer view".
//
// Write: one mesh, one primitive (TRIANGLES), POSITION (float32, with min/max) and uint32 indices; faces
// are fan-triangulated. .gltf embeds its buffer as a base64 data URI, so a written .gltf is a single
// self-contained file; .glb stores it in the binary chunk. Positions are rounded to float32, which is
// all glTF stores.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/polygon_mesh.h"

namespace meshedit {

// `name` is the file name used in error messages. External buffers are resolved in `base_dir`; with an
// empty base_dir, a file that needs one is refused.
PolygonMesh parse_gltf(std::string_view json, const std::string& name, const std::filesystem::path& base_dir = {});
PolygonMesh parse_glb(std::string_view bytes, const std::string& name, const std::filesystem::path& base_dir = {});
// Reads .gltf or .glb, told apart by the file's first four bytes ("glTF" starts a .glb).
PolygonMesh read_gltf(const std::filesystem::path& path);

// require_writable() holds for `mesh`, and every coordinate fits a float; FileError otherwise.
std::string format_gltf(const PolygonMesh& mesh, const std::string& name);
std::string format_glb(const PolygonMesh& mesh, const std::string& name);
void write_gltf(const std::filesystem::path& path, const PolygonMesh& mesh);
void write_glb(const std::filesystem::path& path, const PolygonMesh& mesh);

}  // namespace meshedit
