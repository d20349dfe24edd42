// Opening files as half-edge meshes (see mesh_loading.h).
#include "app/mesh_loading.h"

#include "core/data_folders.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "io/file_error.h"

namespace meshedit {

PolygonMesh polygons_of(const LoadedFile& file, const std::filesystem::path& path, int patch_resolution) {
  switch (file.kind) {
    case FileKind::Mesh: return file.mesh;
    case FileKind::Patches: return tessellate_patches(file.patches, patch_resolution);
    case FileKind::Curve: break;
  }
  throw FileError(path.string(), "", "holds a Bézier curve, not a mesh");
}

LoadedMesh build_from_file(const PolygonMesh& polygons, const std::filesystem::path& path) {
  LoadedMesh loaded;
  BuildReport report;
  try {
    loaded.mesh = build_halfedge_mesh(polygons, &report);
  } catch (const MeshError& e) {
    throw MeshError(path.string() + ": " + e.what(), e.element());
  }
  loaded.unused_vertices = report.unused_vertices;
  return loaded;
}

LoadedMesh load_halfedge_mesh(const std::filesystem::path& path, int patch_resolution) {
  return build_from_file(polygons_of(load_file(path), path, patch_resolution), path);
}

std::filesystem::path assets_dir() { return data_folder("assets"); }
std::filesystem::path lessons_dir() { return data_folder("lessons"); }

}  // namespace meshedit
