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
// - Output order: geometries in library order, each once per instance in scene order; a geometry's
//   vertices keep their order in its POSITION source, so vertex i of a one-geometry file is the file's
//   index i. Polygons keep the file's corner order.
// Errors name the file, the XML line and the element:
//   cow.dae:120: <p> of <polylist> has 17 indices, expected a multiple of 2
// Numbers are strict (text_scanner.h): NaN, inf and malformed numbers are refused with their line.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/polygon_mesh.h"

namespace meshedit {

// `name` is the file name used in error messages.
PolygonMesh parse_dae(std::string_view text, const std::string& name);
PolygonMesh read_dae(const std::filesystem::path& path);

}  // namespace meshedit
