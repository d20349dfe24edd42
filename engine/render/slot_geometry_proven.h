// build_slot_geometry_of_proven_triangles: the renderer's slot buffers (slot_geometry.h) of a mesh vouched valid with
// triangle faces only (HalfedgeMesh::proven_valid_triangles: just built or Loop-subdivided, unchanged since).
//
// Such a mesh needs none of the walks' checks: every live face is a closed 3-cycle of live halfedges pointing back to
// it, every halfedge is on one cycle, every vertex is live where it is used and its position finite, every edge's two
// halfedges are live twins. So each face is read from its three halfedge records, and the result is byte for byte
// build_slot_geometry_by_walks' (same corner order, same term arithmetic, same face order of the sums), which
// tests/render/slot_geometry_proven_test.cpp checks on fixtures, boundaries, dead slots and subdivided meshes.
#pragma once

#include "render/slot_geometry.h"

namespace meshedit {

// Precondition: mesh.proven_valid_triangles().
SlotGeometry build_slot_geometry_of_proven_triangles(const HalfedgeMesh& mesh);

}  // namespace meshedit
