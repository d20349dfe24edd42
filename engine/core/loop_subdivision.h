// Loop subdivision (Part 6), as four phases a lesson can step through, plus one call for all four and a fast
// whole-mesh path that gives the identical result.
//
//   1. loop_compute_positions: new positions for the original vertices and a position for each
//      original edge's midpoint vertex, from the original mesh (nothing changes yet);
//   2. loop_split_edges:   split every original edge (only those: new edges are never split); new
//                          vertices sit at edge midpoints until phase 4;
//   3. loop_flip_edges:    flip every new edge that joins an original vertex and a new vertex;
//   4. loop_commit_positions: move every vertex to its computed position.
//
// Weights (LoopWeights):
//   Course  the assignment's: old vertex (1 - n u) p + u * sum(neighbours), u = 3/16 if n = 3 else 3/(8n)
//   Loop    Loop's original: u = beta / n, beta = 5/8 - (3/8 + 1/4 cos(2 pi / n))^2 (matches OpenMesh, CGAL)
//   interior edge point: 3/8 (a + b) + 1/8 (c + d); boundary edge point: (a + b) / 2;
//   boundary vertex: 3/4 p + 1/8 (left + right boundary neighbours).
// Refused, changing nothing: a mesh validate() rejects (the reason quotes its first problem) and a mesh
// with a non-triangle face ("f3 has 4 sides; Loop subdivision needs triangles; triangulate first: ..." naming
// the menu item, the Lua call and the command: triangulate.h), or with an edge split()
// refuses (two faces with the same three corners), quoting split's reason. An interior vertex's
// valence n counts its neighbours; a boundary vertex uses only its two neighbours along the boundary loop.
// Counts, closed or not: V' = V + E, E' = 2E + 3F, F' = 4F (boundary loops stay one per hole).
// Ids: original vertices keep theirs (ids 0..V-1 of a freshly built mesh stay in place); the vertex and
// edges each split makes are appended, in split()'s documented order (mesh_ops.h), edge by edge in id order.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/check.h"
#include "core/halfedge_mesh.h"

namespace meshedit {

enum class LoopWeights { Course, Loop };

// What phases 1-3 compute and later phases read; indexed by id (size = capacity at the time).
struct LoopState {
  LoopWeights weights = LoopWeights::Course;
  std::vector<glm::dvec3> vertex_position;  // phase 1: new position of each original vertex
  std::vector<glm::dvec3> edge_position;    // phase 1: position of each original edge's new vertex
  std::vector<EdgeId> original_edges;       // phase 1: the edges phase 2 splits, in id order
  std::vector<uint8_t> is_new_vertex;       // phase 2: 1 for vertices created by splits
  std::vector<uint8_t> is_new_edge;         // phase 2: 1 for edges created by splits that cut across a
                                            //          face (not the halves of an original edge)
  std::vector<glm::dvec3> new_position;     // phase 2: final position of every vertex, by id
};

// `threads`: for the quick check of a big mesh (quick_check.h); the answer does not depend on it.
Check can_loop_subdivide(const HalfedgeMesh& mesh, int threads = 1);
// Every check, always, without quick_check.h's shortcut (for tests of that shortcut).
Check can_loop_subdivide_without_shortcut(const HalfedgeMesh& mesh);
// Each phase assumes the previous ones ran on the same mesh; phase 1 refuses what can_loop_subdivide refuses.
OpResult<LoopState> loop_compute_positions(const HalfedgeMesh& mesh, LoopWeights weights = LoopWeights::Course);
void loop_split_edges(HalfedgeMesh& mesh, LoopState& state);
void loop_flip_edges(HalfedgeMesh& mesh, LoopState& state);
void loop_commit_positions(HalfedgeMesh& mesh, const LoopState& state);

// All four phases in turn, through split() and flip(): the teaching path, what a lesson steps through.
// Refuses (and changes nothing) like can_loop_subdivide.
Check loop_subdivide_by_phases(HalfedgeMesh& mesh, LoopWeights weights = LoopWeights::Course);

// `levels` levels of Loop subdivision in a few passes over the flat arrays (loop_subdivision_fast.cpp): the same
// mesh as `levels` calls of loop_subdivide_by_phases, id for id, pointer for pointer and bit for bit (a test
// holds them together on every fixture). The input is checked once, like can_loop_subdivide; a refused mesh is
// left unchanged. `threads` > 1 splits each pass over that many threads (the result does not depend on it).
Check loop_subdivide(HalfedgeMesh& mesh, LoopWeights weights = LoopWeights::Course, int levels = 1, int threads = 1);

}  // namespace meshedit
