// Dispatch by extension (see mesh_file.h): kFormats is the only list of the formats, which reader and writer serve
// each and which axis is up in its files; the messages, the extension lists and the dispatch all read it. Extensions
// compare case-insensitively (".OBJ" is ".obj").
#include "io/mesh_file.h"

#include <optional>
#include <string_view>
#include <utility>

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

// ---- the formats -----------------------------------------------------------------------------------

// Each format's reader fills its kind's part of a LoadedFile (and what else the format tells).
void read_obj_file(const std::filesystem::path& path, LoadedFile& loaded) { loaded.mesh = read_obj(path); }
void read_dae_file_with_axis(const std::filesystem::path& path, LoadedFile& loaded) {
  DaeFile dae = read_dae_file(path);
  loaded.mesh = std::move(dae.mesh);
  loaded.up_axis = collada_up_axis(dae.asset);
}
void read_gltf_welded(const std::filesystem::path& path, LoadedFile& loaded) {
  loaded.mesh = read_gltf(path);
  loaded.joined_vertices = weld_repeated_positions(loaded.mesh);
}
void read_ply_welded(const std::filesystem::path& path, LoadedFile& loaded) {
  loaded.mesh = read_ply(path);
  loaded.joined_vertices = weld_repeated_positions(loaded.mesh);
}
void read_stl_file(const std::filesystem::path& path, LoadedFile& loaded) { loaded.mesh = read_stl(path); }
void read_off_file(const std::filesystem::path& path, LoadedFile& loaded) { loaded.mesh = read_off(path); }
void read_bez_file(const std::filesystem::path& path, LoadedFile& loaded) { loaded.patches = read_bez(path); }
void read_bzc_file(const std::filesystem::path& path, LoadedFile& loaded) { loaded.curve = read_bzc(path); }

struct Format {
  std::string_view extension;  // lower case, with its dot
  FileKind kind;
  std::optional<UpAxis> up_axis;  // when the file does not say (file_up_axis.h gives each reason); none for a curve
  void (*read)(const std::filesystem::path&, LoadedFile&);
  void (*write)(const std::filesystem::path&, const PolygonMesh&);  // nullptr: MeshEdit does not write it
};

// Every format MeshEdit reads or writes, in the order messages and help list them.
constexpr Format kFormats[] = {
    {".obj", FileKind::Mesh, UpAxis::Y, read_obj_file, write_obj},
    {".dae", FileKind::Mesh, UpAxis::Y, read_dae_file_with_axis, nullptr},  // Y: COLLADA's default without <up_axis>
    {".gltf", FileKind::Mesh, UpAxis::Y, read_gltf_welded, write_gltf},
    {".glb", FileKind::Mesh, UpAxis::Y, read_gltf_welded, write_glb},
    {".ply", FileKind::Mesh, UpAxis::Y, read_ply_welded, write_ply},
    {".stl", FileKind::Mesh, UpAxis::Z, read_stl_file, write_stl},
    {".off", FileKind::Mesh, UpAxis::Z, read_off_file, nullptr},
    {".bez", FileKind::Patches, UpAxis::Z, read_bez_file, nullptr},
    {".bzc", FileKind::Curve, std::nullopt, read_bzc_file, nullptr},
};

const Format* find_format(const std::filesystem::path& path) {
  const std::string ext = lowercase_extension(path);
  for (const Format& format : kFormats) {
    if (format.extension == ext) return &format;
  }
  return nullptr;
}

// ---- messages --------------------------------------------------------------------------------------

std::string describe_extension(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  return ext.empty() ? "file has no extension" : "unsupported file type '" + ext + "'";
}

// "MeshEdit reads .obj, ... and .off (meshes), .bez (Bézier patches) and .bzc (Bézier curves)"
std::string readable_text() {
  const auto group = [](FileKind kind, const char* what) {
    return list_extensions(readable_extensions(kind), ", ", " and ") + " (" + what + ")";
  };
  return "MeshEdit reads " + group(FileKind::Mesh, "meshes") + ", " + group(FileKind::Patches, "Bézier patches") +
         " and " + group(FileKind::Curve, "Bézier curves");
}

// The format of a file MeshEdit reads, or a FileError naming the path and listing what it reads.
const Format& readable_format(const std::filesystem::path& path) {
  if (const Format* format = find_format(path)) return *format;
  throw FileError(path.string(), "", describe_extension(path) + "; " + readable_text());
}

}  // namespace

// ---- public functions ------------------------------------------------------------------------------

std::vector<std::string> readable_extensions(FileKind kind) {
  std::vector<std::string> extensions;
  for (const Format& format : kFormats) {
    if (format.kind == kind) extensions.emplace_back(format.extension);
  }
  return extensions;
}

std::vector<std::string> writable_extensions() {
  std::vector<std::string> extensions;
  for (const Format& format : kFormats) {
    if (format.write) extensions.emplace_back(format.extension);
  }
  return extensions;
}

std::string list_extensions(const std::vector<std::string>& extensions, std::string_view separator,
                            std::string_view last_separator) {
  std::string text;
  for (size_t i = 0; i < extensions.size(); ++i) {
    if (i > 0) text += i + 1 == extensions.size() ? last_separator : separator;
    text += extensions[i];
  }
  return text;
}

std::optional<UpAxis> format_up_axis(const std::filesystem::path& path) {
  const Format* format = find_format(path);
  return format ? format->up_axis : std::nullopt;
}

FileKind file_kind(const std::filesystem::path& path) { return readable_format(path).kind; }

bool is_readable(const std::filesystem::path& path) { return find_format(path) != nullptr; }

LoadedFile load_file(const std::filesystem::path& path) {
  const Format& format = readable_format(path);
  LoadedFile loaded;
  loaded.kind = format.kind;
  loaded.up_axis = {format.up_axis.value_or(UpAxis::Z), UpAxisSource::Format};
  format.read(path, loaded);
  return loaded;
}

PolygonMesh load_mesh(const std::filesystem::path& path) {
  const FileKind kind = file_kind(path);
  if (kind == FileKind::Patches) throw FileError(path.string(), "", "holds Bézier patches, not a mesh");
  if (kind == FileKind::Curve) throw FileError(path.string(), "", "holds a Bézier curve, not a mesh");
  return load_file(path).mesh;
}

void save_mesh(const std::filesystem::path& path, const PolygonMesh& mesh) {
  const Format* format = find_format(path);
  if (!format || !format->write) {
    throw FileError(path.string(), "",
                    describe_extension(path) + " for saving; MeshEdit writes meshes as " +
                        list_extensions(writable_extensions(), ", ", " or "));
  }
  format->write(path, mesh);
}

}  // namespace meshedit
