// Linear (midpoint) subdivision: the connectivity refines, the shape stays exactly as it was.
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

#include "core/check.h"
#include "core/halfedge_mesh.h"

namespace meshedit {

Check can_linear_subdivide(const HalfedgeMesh& mesh);

// `levels` levels. The input is checked once (each level's result passes the check); a refused mesh is unchanged.
Check linear_subdivide(HalfedgeMesh& mesh, int levels = 1);

}  // namespace meshedit
