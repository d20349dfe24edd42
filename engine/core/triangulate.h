// Triangulation of polygons: every face with more than three corners becomes triangles, convex or not, planar or
// nearly so.
//
// Invariants:
// - A polygon is ear-clipped in its best-fit plane (the Newell normal), so a triangle's corners keep the polygon's
//   order: each triangle's normal points the way the polygon's does, and the triangles cover the polygon exactly
//   (their areas sum to its area) with no triangle outside it.
// - An ear is a convex corner (positive area, never zero) whose triangle holds no other corner of what is left.
//   Only when no corner is an ear (a self-intersecting or fully degenerate polygon) is the rest cut as a fan.
// - Triangles and untouched faces stay in the input's face order; a polygon's triangles replace it in place.
//   No vertex is added, moved or renumbered.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/check.h"
#include "core/halfedge_mesh.h"
#include "core/polygon_mesh.h"

namespace meshedit {

struct TriangulationReport {
  size_t polygons_split = 0;  // faces with more than three corners
  size_t triangles_made = 0;  // the triangles those faces became
  size_t fan_fallbacks = 0;   // polygons where no ear was found and the rest was cut as a fan
};

// The triangles of one polygon given its corner positions in order: 3 corner numbers (0..n-1) per triangle,
// n - 2 triangles. A polygon of fewer than 3 corners gives none. `used_fan` (optional) says whether the fan
// fallback was needed.
std::vector<uint32_t> triangulate_polygon(std::span<const glm::dvec3> corners, bool* used_fan = nullptr);
// The same, cutting along a diagonal from corner a to corner c only where allowed(a, c) says so, as long as some ear
// allows it (when none does, the best-shaped ear is cut all the same).
using DiagonalAllowed = std::function<bool(uint32_t a, uint32_t c)>;
std::vector<uint32_t> triangulate_polygon(std::span<const glm::dvec3> corners, const DiagonalAllowed& allowed,
                                          bool* used_fan = nullptr);

// The Newell normal of a polygon (not normalized; its length is twice the polygon's area when planar).
glm::dvec3 newell_normal(std::span<const glm::dvec3> corners);

// `polygons` with every face of more than three corners replaced by its triangles (faces of fewer than three
// corners, which are not polygons, are kept as they are for the builder to report). No diagonal runs along an edge
// the mesh already has or another polygon's diagonal, where some ear allows it: two quads that share three corners
// are cut along different diagonals, so no triangle is made twice.
PolygonMesh triangulate(const PolygonMesh& polygons, TriangulationReport* report = nullptr);

// Triangulates every face of `mesh`: the mesh becomes the triangles of to_polygon_mesh(mesh) rebuilt (live vertices
// renumbered densely in id order, faces in id order). Refused, changing nothing, when the mesh is not valid enough
// to list its faces; a mesh of triangles only is left as it is (value = report with polygons_split 0).
OpResult<TriangulationReport> triangulate_mesh(HalfedgeMesh& mesh);

// How to triangulate, for refusals that need triangles ("f0 has 4 sides; Loop subdivision needs triangles; ...").
inline constexpr const char* kHowToTriangulate =
    "triangulate first: Edit > Triangulate, mesh:triangulate() in Lua, or meshedit triangulate IN -o OUT";

}  // namespace meshedit
