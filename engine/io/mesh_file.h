// Opening and saving any supported file, chosen by extension:
//   read:  .obj .dae .gltf .glb .ply .stl .off (meshes), .bez (Bézier patches), .bzc (a Bézier curve)
//   write: .obj .gltf .glb .ply .stl (meshes)
// Every failure is a FileError naming the file and the place; nothing here exits or aborts, whatever
// the bytes are. Readers for one format are in their own headers (obj_io.h, dae_reader.h, ply_io.h, ...),
// each with a parse_* function over the bytes in memory that the fuzz tests call. A loaded file carries the axis to
// show up (file_up_axis.h): COLLADA's from the file, every other format's from kFormatUpAxes. glTF and PLY vertices
// that share a position are joined (LoadedFile::joined_vertices says how many), as STL's corners are.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/bezier.h"
#include "core/polygon_mesh.h"
#include "io/file_up_axis.h"

namespace meshedit {

enum class FileKind { Mesh, Patches, Curve };

struct LoadedFile {
  FileKind kind = FileKind::Mesh;
  PolygonMesh mesh;                  // kind == Mesh
  std::vector<BezierPatch> patches;  // kind == Patches
  BezierCurve curve;                 // kind == Curve
  FileUpAxis up_axis;                // the axis to show up; Z for a curve, which is drawn in its plane
  // glTF and PLY: the vertices the file repeats at one position (a modeller splits them where a normal, a texture
  // coordinate or a colour changes) that were joined into one (position_welder.h); 0 for the other formats.
  size_t joined_vertices = 0;
};

// The kind a path's extension promises, or a FileError for an extension we do not read.
FileKind file_kind(const std::filesystem::path& path);
// True when load_file reads files with the path's extension (what the Open dialog lists).
bool is_readable(const std::filesystem::path& path);
LoadedFile load_file(const std::filesystem::path& path);
// Loads a mesh file; throws FileError if the file holds patches or a curve instead.
PolygonMesh load_mesh(const std::filesystem::path& path);
void save_mesh(const std::filesystem::path& path, const PolygonMesh& mesh);

}  // namespace meshedit
