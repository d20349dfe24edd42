// Dispatch by extension (see mesh_file.h): the only place that knows which reader or writer serves
// which extension. Extensions compare case-insensitively (".OBJ" is ".obj").
#include "io/mesh_file.h"

#include <optional>

#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "io/dae_reader.h"
#include "io/file_access.h"
#include "io/file_error.h"
#include "io/file_up_axis.h"
#include "io/gltf_io.h"
#include "io/obj_io.h"
#include "io/off_io.h"
#include "io/ply_io.h"
#include "io/position_welder.h"
#include "io/stl_io.h"

namespace meshedit {
namespace {

constexpr const char* kReadable =
    "MeshEdit reads .obj, .dae, .gltf, .glb, .ply, .stl and .off (meshes), .bez (Bézier patches) and .bzc "
    "(Bézier curves)";
constexpr const char* kWritable = "MeshEdit writes meshes as .obj, .gltf, .glb, .ply or .stl";

std::string describe_extension(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  return ext.empty() ? "file has no extension" : "unsupported file type '" + ext + "'";
}

std::optional<FileKind> kind_of_extension(const std::string& ext) {
  for (const char* mesh_ext : {".obj", ".dae", ".gltf", ".glb", ".ply", ".stl", ".off"}) {
    if (ext == mesh_ext) return FileKind::Mesh;
  }
  if (ext == ".bez") return FileKind::Patches;
  if (ext == ".bzc") return FileKind::Curve;
  return std::nullopt;
}

}  // namespace

FileKind file_kind(const std::filesystem::path& path) {
  if (const auto kind = kind_of_extension(lowercase_extension(path))) return *kind;
  throw FileError(path.string(), "", describe_extension(path) + "; " + kReadable);
}

bool is_readable(const std::filesystem::path& path) { return kind_of_extension(lowercase_extension(path)).has_value(); }

LoadedFile load_file(const std::filesystem::path& path) {
  LoadedFile loaded;
  loaded.kind = file_kind(path);
  loaded.up_axis = {format_up_axis(path).value_or(UpAxis::Z), UpAxisSource::Format};
  const std::string ext = lowercase_extension(path);
  if (ext == ".obj") {
    loaded.mesh = read_obj(path);
  } else if (ext == ".dae") {
    DaeFile dae = read_dae_file(path);
    loaded.mesh = std::move(dae.mesh);
    loaded.up_axis = collada_up_axis(dae.asset);
  } else if (ext == ".gltf" || ext == ".glb") {
    loaded.mesh = read_gltf(path);
    loaded.joined_vertices = weld_repeated_positions(loaded.mesh);
  } else if (ext == ".ply") {
    loaded.mesh = read_ply(path);
    loaded.joined_vertices = weld_repeated_positions(loaded.mesh);
  } else if (ext == ".stl") {
    loaded.mesh = read_stl(path);
  } else if (ext == ".off") {
    loaded.mesh = read_off(path);
  } else if (ext == ".bez") {
    loaded.patches = read_bez(path);
  } else {
    loaded.curve = read_bzc(path);
  }
  return loaded;
}

PolygonMesh load_mesh(const std::filesystem::path& path) {
  const FileKind kind = file_kind(path);
  if (kind == FileKind::Patches) throw FileError(path.string(), "", "holds Bézier patches, not a mesh");
  if (kind == FileKind::Curve) throw FileError(path.string(), "", "holds a Bézier curve, not a mesh");
  return load_file(path).mesh;
}

void save_mesh(const std::filesystem::path& path, const PolygonMesh& mesh) {
  const std::string ext = lowercase_extension(path);
  if (ext == ".obj") {
    write_obj(path, mesh);
  } else if (ext == ".gltf") {
    write_gltf(path, mesh);
  } else if (ext == ".glb") {
    write_glb(path, mesh);
  } else if (ext == ".ply") {
    write_ply(path, mesh);
  } else if (ext == ".stl") {
    write_stl(path, mesh);
  } else {
    throw FileError(path.string(), "", describe_extension(path) + " for saving; " + kWritable);
  }
}

}  // namespace meshedit
