// Linear (midpoint) subdivision: the connectivity refines, the shape stays exactly as it was. Two phases a lesson
// can step through, plus one call for any number of levels:
//   1. linear_compute_points: every original edge's midpoint and every centre vertex's centroid (nothing changes);
//   2. linear_refine: the mesh becomes its refinement, each new vertex at the point phase 1 computed.
//
// Rule (RefineRule::TrianglesInFour, subdivision_refine.h):
//   a triangle becomes 4 triangles: its three corners and the middle one, joining its edges' midpoints;
//   a face of n >= 4 corners becomes n quads around its centroid (Catmull-Clark's topology with linear positions:
//   each quad joins a corner, the midpoints of its two edges and the centroid), so the result of a quad mesh is
//   the mesh Catmull-Clark's phase 2 shows before any vertex moves.
// Positions: original vertices keep theirs bit for bit; an edge's new vertex is its midpoint (a + b) / 2, a centre
// vertex the mean of its face's corners. A mixed mesh is refined face by face; neighbouring faces share the
// midpoint of the edge between them, so triangles and quads stay joined.
// Counts after a level: V' = V + E + (faces of 4 or more sides), F' = 4 T + (sum of the other faces' sides),
// where T counts the triangles. Ids as subdivision_refine.h lays out.
// Refused, changing nothing: what can_refine refuses.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "core/check.h"
#include "core/halfedge_mesh.h"
#include "core/subdivision_refine.h"

namespace meshedit {

// What phase 1 computes and phase 2 reads.
struct LinearState {
  RefineLayout layout;               // the ids phase 2 gives the new vertices
  std::vector<glm::dvec3> position;  // by refined vertex id: original vertices where they are, then the new points
};

Check can_linear_subdivide(const HalfedgeMesh& mesh);
// Phase 2 assumes phase 1 ran on the same mesh; phase 1 refuses what can_linear_subdivide refuses.
OpResult<LinearState> linear_compute_points(const HalfedgeMesh& mesh);
void linear_refine(HalfedgeMesh& mesh, const LinearState& state);

// `levels` levels. The input is checked once (each level's result passes the check); a refused mesh is unchanged.
Check linear_subdivide(HalfedgeMesh& mesh, int levels = 1);

}  // namespace meshedit
