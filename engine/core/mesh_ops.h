// Local operations on triangle meshes: flip, split and collapse, each with its check.
//
// A refused operation changes nothing (the mesh, including version(), is untouched) and the Check says
// why. Post-conditions — rotation direction, which ids are kept, the order new ids are allocated in — are
// documented per operation below and tested pointer by pointer in tests/core.
#pragma once

#include "core/check.h"
#include "core/halfedge_mesh.h"

namespace meshedit {

// ---- flip -------------------------------------------------------------------------------------------
Check can_flip(const HalfedgeMesh& mesh, EdgeId e);
// Returns e (flip keeps every id).
OpResult<EdgeId> flip(HalfedgeMesh& mesh, EdgeId e);

// ---- split ------------------------------------------------------------------------------------------
Check can_split(const HalfedgeMesh& mesh, EdgeId e);
// Returns the new vertex, at the midpoint of e; its halfedge points along the split edge.
OpResult<VertexId> split(HalfedgeMesh& mesh, EdgeId e);

// ---- collapse ---------------------------------------------------------------------------------------
Check can_collapse(const HalfedgeMesh& mesh, EdgeId e);
// Returns the surviving vertex, moved to the midpoint of e.
OpResult<VertexId> collapse(HalfedgeMesh& mesh, EdgeId e);

}  // namespace meshedit
