// Wavefront .obj: polygon meshes, read and written.
//
// Read: `v x y z [w]` (w and trailing vertex colours are checked as numbers and dropped); `f` (and the
// obsolete `fo`) with corners `i`, `i/t`, `i//n` or `i/t/n`, 1-based, negative indices counting back
// from the last vertex defined so far; polygons of any size (at least 3 corners). Comments (`#` to the
// end of a line), `\` line continuations, and every other statement (`o g s usemtl mtllib vt vn l p`,
// unknown ones) are skipped. Texture and normal indices are checked as whole numbers but not used.
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
