// Dispatch by extension (see mesh_file.h). Readers are added format by format.
#include "io/mesh_file.h"

#include "io/file_error.h"

namespace meshedit {

FileKind file_kind(const std::filesystem::path& path) {
  throw FileError(path.string(), "", "unsupported file type '" + path.extension().string() + "'");
}

LoadedFile load_file(const std::filesystem::path& path) {
  file_kind(path);
  return {};
}

PolygonMesh load_mesh(const std::filesystem::path& path) { return load_file(path).mesh; }

void save_mesh(const std::filesystem::path& path, const PolygonMesh&) {
  throw FileError(path.string(), "", "unsupported file type '" + path.extension().string() + "'");
}

}  // namespace meshedit
