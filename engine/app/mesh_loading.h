// Opening any supported file as a half-edge mesh, for the command-line tools and the demo.
// Patches (.bez) are tessellated at `patch_resolution` and welded; a curve (.bzc) is not a mesh and is
// refused with a FileError.
#pragma once

#include <filesystem>

#include "core/halfedge_mesh.h"
#include "core/patch_tessellation.h"
#include "io/mesh_file.h"

namespace meshedit {

struct LoadedMesh {
  HalfedgeMesh mesh;
  size_t unused_vertices = 0;  // input vertices no face used (kept as dead ids)
};

// build_halfedge_mesh, with the file's name put in front of a refusal ("cow.obj: the edge between ...").
LoadedMesh build_from_file(const PolygonMesh& polygons, const std::filesystem::path& path);

// Throws FileError (unreadable file) or MeshError (not a manifold), both naming the file.
LoadedMesh load_halfedge_mesh(const std::filesystem::path& path, int patch_resolution = kDefaultPatchResolution);

// The polygons of an already-loaded file: a mesh as is, patches tessellated; throws for a curve.
PolygonMesh polygons_of(const LoadedFile& file, const std::filesystem::path& path, int patch_resolution);

// The assets/ folder: beside the binary, in the installed layout or in the source tree (core/data_folders.h).
std::filesystem::path assets_dir();
// The lessons/ folder, found the same way.
std::filesystem::path lessons_dir();

}  // namespace meshedit
