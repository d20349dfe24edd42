// Building a HalfedgeMesh from indexed polygons, and turning one back into polygons.
//
// Id order after build_halfedge_mesh (tests and lessons rely on it):
// - vertex i of the input is v_i (an input vertex no face uses is kept as a dead slot, so ids still
//   match the file's indices; BuildReport::unused_vertices counts them);
// - face i is f_i; its corners j = 0..n-1 give halfedges h_(offset_i + j), leaving corner j, in order;
// - edges are numbered in the order their first halfedge appears; e.halfedge is that halfedge;
// - boundary loops b_0, b_1... follow the first interior halfedge on each hole; their halfedges come
//   after all interior ones, in walking order; b.halfedge is the first of them;
// - v.halfedge is v's outgoing boundary halfedge when v is on a boundary, else its lowest outgoing id.
//
// Input that is not an oriented manifold surface is refused with a MeshError naming the faces and the
// vertex or edge: a face with fewer than 3 corners or a repeated corner, an out-of-range index, an edge
// with more than two faces, two faces using an edge in the same direction (inconsistent orientation),
// a repeated face, and a vertex whose faces form more than one fan (bow-tie).
#pragma once

#include <cstddef>

#include "core/halfedge_mesh.h"
#include "core/polygon_mesh.h"

namespace meshedit {

struct BuildReport {
  size_t unused_vertices = 0;  // input vertices no face refers to (kept as dead ids)
};

// Throws MeshError for input that is not a manifold surface; never changes anything else.
HalfedgeMesh build_halfedge_mesh(const PolygonMesh& in, BuildReport* report = nullptr);

// Live vertices renumbered densely in id order, live faces in id order, each starting at its
// face.halfedge. Throws MeshError naming the face if a face cycle does not close.
PolygonMesh to_polygon_mesh(const HalfedgeMesh& mesh);

}  // namespace meshedit
