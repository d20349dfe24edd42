// COLLADA (.dae) reading: the subset the CS184 course files use (Blender 2.7x and modo exports), through
// tinyxml2, into one PolygonMesh.
//
// Read:
// - root <COLLADA>; every <library_geometries>/<geometry>/<mesh>: <source> with <float_array count=..>
//   and an optional <technique_common>/<accessor count stride offset>; <vertices id> with
//   <input semantic="POSITION" source="#...">;
// - primitives <triangles>, <polylist> (with <vcount>), <polygons>, <trifans> and <tristrips>, each with
//   <input semantic offset> (index stride = largest offset + 1; only VERTEX is used) and <p>. <lines>,
//   <linestrips> and other primitives are skipped; polygons with holes (<ph>) are refused.
// - transforms: the scene named by <scene>/<instance_visual_scene> (else the first <visual_scene>); its
//   nodes nest, each composing <matrix> (row-major 4x4), <translate>, <rotate> (axis, degrees) and
//   <scale> in document order. Each <instance_geometry url="#id"> adds a copy of that geometry with the
//   node's world transform applied to its positions. A geometry never instanced is added once,
//   untransformed. A transform with a negative determinant reverses every face so normals stay outward.
//   The course code (CS184) parsed transforms but ignored them; MeshEdit applies them, so cube.dae
//   (a 2x scale matrix) loads as the cube [-2, 2]^3. <instance_node> is not followed.
// - <asset>: <up_axis> (X_UP, Y_UP or Z_UP, spaces around it allowed; anything else is refused with its line)
//   and the first <contributor>/<authoring_tool>, as the file says them; which up axis the window uses is
//   decided from them in file_up_axis.h. No <asset> or no <up_axis> means COLLADA's default, Y_UP.
// - Output order: geometries in library order, each once per instance in scene order; a geometry's
//   vertices keep their order in its POSITION source, so vertex i of a one-geometry file is the file's
//   index i. Polygons keep the file's corner order. A <polylist> or <polygons> polygon of fewer than 3 corners is
//   kept as the file has it (the half-edge builder refuses it by its number and mesh repair drops it with a report);
//   a fan or a strip of fewer than 3 corners, which holds no triangle, is refused.
// Errors name the file, the XML line and the element:
//   cow.dae:120: <p> of <polylist> has 17 indices, expected a multiple of 2
// Numbers are strict (text_scanner.h): NaN, inf and malformed numbers are refused with their line.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/polygon_mesh.h"
#include "core/up_axis.h"

namespace meshedit {

// What the file's <asset> says that showing it needs.
struct DaeAsset {
  UpAxis up_axis = UpAxis::Y;   // <up_axis>, or COLLADA's default when the file has none
  bool up_axis_tagged = false;  // the file has an <up_axis>
  std::string authoring_tool;   // the first <contributor>/<authoring_tool>, trimmed; "" when absent
};

struct DaeFile {
  PolygonMesh mesh;
  DaeAsset asset;
};

// `name` is the file name used in error messages.
DaeFile parse_dae_file(std::string_view text, const std::string& name);
DaeFile read_dae_file(const std::filesystem::path& path);
// The mesh alone.
PolygonMesh parse_dae(std::string_view text, const std::string& name);
PolygonMesh read_dae(const std::filesystem::path& path);

}  // namespace meshedit
