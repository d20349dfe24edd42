// Which axis is up in a file: the rule the window follows to show a file upright (the user can still override
// it, View > Up axis). Only the view uses it; positions are never rotated.
//
// The rule:
// - A format that does not say (every one but COLLADA) has the up axis of the files people make in it, from
//   one data table, kFormatUpAxes: Y for .obj (Blender's and most tools' default export), .gltf/.glb (Y-up by
//   the glTF spec) and .ply (the Stanford scans, the bunny, the dragon and the Buddha, stand on Y, and
//   MeshLab keeps a scan's axes); Z for .stl (made for 3D printing and CAD, whose build plate is the XY
//   plane: slicers and CAD tools are Z-up), .off (ModelNet's aligned shapes stand on Z) and .bez (the Utah
//   teapot's patches, Z-up since Newell). A format not in the table has none (format_up_axis gives
//   nullopt): a new reader gets an entry there, nowhere else.
// - A COLLADA file says, in <asset>/<up_axis> (Y_UP when absent, COLLADA's default); the rule trusts it,
//   except for the exporters in kMistaggedExporters, whose files are Z-up whatever their tag says.
//   The one there, "modo 801 [Build 77509], Mac OS X 10.9.3 (10.9.3)", wrote every CS184 course .dae that is
//   not Blender's (bean, beetle, cow, peter, quadball, teapot): they are tagged Y_UP, modo's own convention,
//   but their geometry is Z-up, as the course viewer (a Z-up orbit for every file) shows them. Rendered with
//   Y up the cow stands on its nose and the teapot and the beetle show their bottoms; with Z up all stand on
//   their feet (the bean and the quadball look right either way). The course's Blender files (cube, weird)
//   are tagged Z_UP, which is right. The match is on the whole authoring-tool string, one modo build on one
//   machine's system, so a file modelled upright in modo and exported by any other build or system keeps its
//   Y_UP; modo in general is not distrusted.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string_view>

#include "core/up_axis.h"
#include "io/dae_reader.h"

namespace meshedit {

struct FormatUpAxis {
  std::string_view extension;  // lower case, with its dot
  UpAxis up_axis;
};

inline constexpr std::array<FormatUpAxis, 8> kFormatUpAxes = {{
    {".obj", UpAxis::Y},
    {".gltf", UpAxis::Y},
    {".glb", UpAxis::Y},
    {".ply", UpAxis::Y},
    {".stl", UpAxis::Z},
    {".off", UpAxis::Z},
    {".dae", UpAxis::Y},  // COLLADA's default, for a file without <up_axis>; collada_up_axis reads the tag
    {".bez", UpAxis::Z},
}};

// <authoring_tool> strings (whole) of exporters that tag Z-up geometry Y_UP.
inline constexpr std::array<std::string_view, 1> kMistaggedExporters = {
    "modo 801 [Build 77509], Mac OS X 10.9.3 (10.9.3)",
};

// Where a file's up axis came from (the window's status bar says it).
enum class UpAxisSource {
  Format,          // the format's entry in kFormatUpAxes
  FileTag,         // the COLLADA file's <up_axis>
  CourseExporter,  // the file's exporter is in kMistaggedExporters: Z whatever the tag says
  Lesson           // a lesson's show(mesh, {up = ...}), for a mesh it read from a file
};

struct FileUpAxis {
  UpAxis up_axis = UpAxis::Z;
  UpAxisSource source = UpAxisSource::Format;
};

// The table's up axis for the path's extension (compared case-insensitively), or nullopt when it has none.
std::optional<UpAxis> format_up_axis(const std::filesystem::path& path);
// A COLLADA file's up axis from its <asset>, by the rule above.
FileUpAxis collada_up_axis(const DaeAsset& asset);

}  // namespace meshedit
