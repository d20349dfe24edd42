// Opening and saving any supported file, chosen by extension from one table of formats (mesh_file.cpp, kFormats):
//   read:  .obj .dae .gltf .glb .ply .stl .off (meshes), .bez (Bézier patches), .bzc (a Bézier curve)
//   write: .obj .gltf .glb .ply .stl (meshes)
// Everything else that lists formats (messages, the Open and Save panels, the command-line help, the web page's file
// picker, the docs) takes the lists from readable_extensions and writable_extensions or is held to them by a test.
// Every failure is a FileError naming the file and the place; nothing here exits or aborts, whatever
// the bytes are. Readers for one format are in their own headers (obj_io.h, dae_reader.h, ply_io.h, ...),
// each with a parse_* function over the bytes in memory that the fuzz tests call. A loaded file carries the axis to
// show up (file_up_axis.h): COLLADA's from the file, every other format's from the table. glTF and PLY vertices
// that share a position are joined (LoadedFile::joined_vertices says how many), as STL's corners are.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
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

// The extensions load_file reads as `kind`, and those save_mesh writes: lower case with their dots, in the table's
// order (".obj", ".dae", ...).
std::vector<std::string> readable_extensions(FileKind kind);
std::vector<std::string> writable_extensions();
// The extensions one after another: ".obj .gltf .glb" (" ", " "), ".obj, .gltf or .glb" (", ", " or ").
std::string list_extensions(const std::vector<std::string>& extensions, std::string_view separator,
                            std::string_view last_separator);

// The up axis of files with the path's extension when the file does not say (compared case-insensitively;
// file_up_axis.h gives the reasons), or nullopt for a curve or an extension MeshEdit does not read.
std::optional<UpAxis> format_up_axis(const std::filesystem::path& path);

// The kind a path's extension promises, or a FileError for an extension we do not read.
FileKind file_kind(const std::filesystem::path& path);
// True when load_file reads files with the path's extension (what the Open dialog lists).
bool is_readable(const std::filesystem::path& path);
LoadedFile load_file(const std::filesystem::path& path);
// Loads a mesh file; throws FileError if the file holds patches or a curve instead.
PolygonMesh load_mesh(const std::filesystem::path& path);
void save_mesh(const std::filesystem::path& path, const PolygonMesh& mesh);

}  // namespace meshedit
