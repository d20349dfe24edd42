// TriangleRows: every face of a triangle mesh as one row, its three corners (in the face's own order, from its
// halfedge) and its id, in an order that keeps faces that share vertices close together. Loop subdivision leaves
// them on the mesh it makes: each face's four children take four consecutive rows, in the order the rows of the
// faces before had (or face id order when there were none), so after a few levels the rows walk the surface patch
// by patch while the stable ids scatter neighbours across the arrays. A whole-mesh pass that reads the rows
// (vertex_normals) then finds each vertex in cache for all of its faces.
//
// Invariants: the rows list every live face exactly once, with the corners its halfedge cycle has; a mesh keeps its
// rows only while its connectivity is the one they were made from (HalfedgeMesh::triangle_rows): every mutation
// other than a position, and every direct access through MeshStorage, drops them. Rows are immutable once made, so
// copies of a mesh share them.
#pragma once

#include "core/ids.h"
#include "core/mesh_array.h"

namespace meshedit {

struct TriangleRow {
  VertexId corner[3];  // the face's corners, from its halfedge's tail in next order
  FaceId face;
};

static_assert(sizeof(TriangleRow) == 16, "four rows fill one 64-byte cache line (Loop writes them so)");

using TriangleRows = MeshArray<TriangleRow>;

}  // namespace meshedit
