// Wavefront .obj: polygon meshes, read and written.
//
// Read: `v x y z [w] [r g b]` (x y z finite; w and the vertex colours MeshLab, MeshMixer and Blender write are checked
// as numbers, nan and inf allowed, and dropped); `f` (and the obsolete `fo`) with corners `i`, `i/t`, `i//n` or
// `i/t/n`, 1-based, negative indices counting back from the last vertex defined so far, where an empty texture or
// normal part stands for none (`i/`, `i//` as Wings3D writes, `i/t/`). Comments (`#` to the end of a line), `\`
// line continuations, a UTF-8 byte order mark before the first statement, and every other statement (`o g s usemtl
// mtllib vt vn l p`, unknown ones) are skipped. Texture and normal indices are checked as whole numbers but not used.
// Every face is kept as the file has it, whatever its number of corners (an `f 1 2` line, a repeated corner): the
// half-edge builder refuses such a face by its number and mesh repair drops it with a report.
// Errors name the line: "teapot.obj:88: face refers to vertex 1300, but only 1232 are defined".
// A positive index may refer to a vertex defined later in the file (the format allows it); it is
// checked against the final vertex count and reported at the first line that uses it.
// Files with no faces are refused.
//
// Write: a header comment, `v` lines with the shortest text that reads back to the same double, and
// `f` lines, 1-based. parse_obj(format_obj(m)) == m for any mesh require_writable accepts.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/polygon_mesh.h"

namespace meshedit {

// `name` is the file name used in error messages.
PolygonMesh parse_obj(std::string_view text, const std::string& name);
PolygonMesh read_obj(const std::filesystem::path& path);

std::string format_obj(const PolygonMesh& mesh, const std::string& name);
void write_obj(const std::filesystem::path& path, const PolygonMesh& mesh);

}  // namespace meshedit
