// Turning bicubic Bézier patches into one triangle mesh: sample each patch on a (u,v) grid, weld the
// samples that coincide (shared patch edges, collapsed rows), drop what welding made degenerate, and
// split the vertices where welding joined surfaces that only touch.
//
// Invariants of the result:
// - Each triangle has three distinct vertex indices.
// - Every vertex has a single fan: its triangles are joined, around it, through edges that exactly two
//   triangles use in opposite directions. Vertices where this failed after welding were split (below).
// - Orientation follows each patch's (u,v) order: the triangles of a grid cell turn from +u to +v, so a
//   face's normal points along dP/du x dP/dv (u along a row of control points, v down the rows). On the
//   published Utah teapot data that normal points outwards on every patch.
// - When the patches are consistently oriented and meet edge to edge (the teapot, the course's
//   wavy_cube), the result builds with build_halfedge_mesh. A patch oriented against its neighbour is not
//   flipped: the split rule cuts it free along the shared edge, which then shows as a boundary.
#pragma once

#include <cstddef>
#include <functional>
#include <span>

#include "core/bezier.h"
#include "core/polygon_mesh.h"

namespace meshedit {

// What welding did, for the console and for tests.
struct TessellationReport {
  size_t samples = 0;               // patches * (resolution + 1)^2 evaluated points
  size_t welded_vertices = 0;       // distinct vertices after welding (before vertex splits)
  size_t degenerate_triangles = 0;  // triangles dropped because welding merged two of their corners
  size_t vertex_splits = 0;         // extra vertex copies made so that every vertex has one fan
};

inline constexpr int kDefaultPatchResolution = 16;  // CS184 samples each patch on a 16x16 grid
inline constexpr int kMaxPatchResolution = 1024;

// Tessellates `patches` into triangles.
//
// Each patch p is sampled at (u, v) = (i/n, j/n), i, j = 0..n (n = resolution), and each grid cell
// with corners a = (i,j), b = (i+1,j), c = (i+1,j+1), d = (i,j+1) becomes triangles (a b c) and (a c d).
// A sample becomes the lowest-numbered earlier vertex within tol = 1e-9 * (diagonal of the finite
// samples' bounding box), found through a grid hash (expected O(samples)), or a new vertex; non-finite
// samples are never welded.
//
// Numbering (tests rely on it): output vertices appear in the order their first sample is met, going
// patch by patch, j (v) outer, i (u) inner; triangles come patch by patch, cell (i,j) in the same
// order, (a b c) before (a c d), minus the dropped degenerate ones. A vertex whose remaining triangles
// form several fans keeps its id for the fan of its lowest triangle; each further fan gets a copy of
// it, appended after all welded vertices in vertex order. That happens where two surfaces touch at a
// point (the teapot's handle ends on a corner of the body's patches), where welding stacked more than
// two triangles on one edge (the teapot's thin tubes sampled at resolution 1 flatten into sheets), and
// along edges two triangles use in the same direction (inconsistently oriented patches).
// Consequently one flat patch gives (n+1)^2 vertices, vertex j*(n+1)+i at (i/n, j/n), and 2n^2
// triangles, cell (i,j) giving triangles 2(j*n+i) and 2(j*n+i)+1.
//
// Samples that no triangle keeps (a patch collapsed to a curve or a point) stay as unused vertices.
// NaN or infinite control points do not throw: their samples stay unwelded and the positions carry the
// NaN. Throws MeshError if resolution is outside [1, kMaxPatchResolution] or the triangles would not fit
// 32-bit indices; no patches give an empty mesh.
PolygonMesh tessellate_patches(std::span<const BezierPatch> patches, int resolution = kDefaultPatchResolution,
                               TessellationReport* report = nullptr);

// The point of patch `index` at (u, v), for a tessellation whose samples come from elsewhere than evaluate_patch.
using PatchSampler = std::function<glm::dvec3(size_t index, double u, double v)>;
// The same tessellation, welding and numbering of `patches`, with every sample `sample(p, i / n, j / n)` in the order
// above (patch by patch, j outer, i inner) instead of evaluate_patch: a student's evaluate drawn as the reference's.
PolygonMesh tessellate_patches(std::span<const BezierPatch> patches, int resolution, const PatchSampler& sample,
                               TessellationReport* report = nullptr);

}  // namespace meshedit
