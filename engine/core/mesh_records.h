// A HalfedgeMesh as text with every record kept: each slot of each kind (live or dead) with its pointers and
// positions, so the mesh reads back with the same ids, the same pointers and the same dead slots, even a mesh a
// student's code broke. What the grader sends when a test fails (grade/failing_case.h): the window opens it with the
// ids the grader's words name, and the renderer draws a broken mesh as the window would.
//
//   meshedit mesh records 1
//   v 0 + 0 0 0 h0          a vertex: its slot, + live or - dead, x y z, its halfedge
//   h 0 + h1 h3 v0 e0 f0    a halfedge: next, twin, vertex, edge, face (f or b)
//   e 0 + h0                an edge, a face (f), a boundary loop (b): its halfedge
//   f 0 + h0
//   b 0 + h3
// A pointer that is not set is `-`. Slots of a kind come in order from 0.
//
// Invariants:
// - parse_mesh_records(format_mesh_records(m)) has m's capacities, alive flags, pointers and positions exactly (the
//   shortest decimal text of a double reads back to the same double).
// - Reading refuses, with a MeshError naming `name` and the line, a text of another format or version, a slot out of
//   order, and a pointer to a slot the text does not have; a pointer to a dead slot is kept (that is what broke).
#pragma once

#include <string>
#include <string_view>

#include "core/halfedge_mesh.h"

namespace meshedit {

std::string format_mesh_records(const HalfedgeMesh& mesh);
HalfedgeMesh parse_mesh_records(std::string_view text, const std::string& name);

}  // namespace meshedit
