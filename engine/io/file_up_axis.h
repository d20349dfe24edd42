// Which axis is up in a file: the rule the window follows to show a file upright (the user can still override
// it, View > Up axis). Only the view uses it; positions are never rotated.
//
// The rule:
// - A format that does not say (every one but COLLADA) has the up axis of the files people make in it, from
//   the one table of formats (mesh_file.cpp, kFormats; format_up_axis in mesh_file.h): Y for .obj (Blender's and most
//   tools' default export), .gltf/.glb (Y-up by the glTF spec) and .ply (the Stanford scans, the bunny, the dragon and
//   the Buddha, stand on Y, and MeshLab keeps a scan's axes); Z for .stl (made for 3D printing and CAD, whose build
//   plate is the XY plane: slicers and CAD tools are Z-up), .off (ModelNet's aligned shapes stand on Z) and .bez (the
//   Utah teapot's patches, Z-up since Newell). A curve (.bzc) has none: it is drawn in its plane.
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
#include <string_view>

#include "core/up_axis.h"
#include "io/dae_reader.h"

namespace meshedit {

// <authoring_tool> strings (whole) of exporters that tag Z-up geometry Y_UP.
inline constexpr std::array<std::string_view, 1> kMistaggedExporters = {
    "modo 801 [Build 77509], Mac OS X 10.9.3 (10.9.3)",
};

// Where a file's up axis came from (the window's status bar says it).
enum class UpAxisSource {
  Format,          // the format's entry in the table of formats
  FileTag,         // the COLLADA file's <up_axis>
  CourseExporter,  // the file's exporter is in kMistaggedExporters: Z whatever the tag says
  Lesson           // a lesson's show(mesh, {up = ...}), for a mesh it read from a file
};

struct FileUpAxis {
  UpAxis up_axis = UpAxis::Z;
  UpAxisSource source = UpAxisSource::Format;
};

// A COLLADA file's up axis from its <asset>, by the rule above.
FileUpAxis collada_up_axis(const DaeAsset& asset);

}  // namespace meshedit
