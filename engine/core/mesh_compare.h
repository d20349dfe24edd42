// Comparing a mesh ("yours", what a student's code made) with a reference mesh, in two strengths:
//
// - compare_meshes_exact: pointer for pointer. The same ids are alive in both, every pointer of every live
//   element is the same id, positions agree within the tolerance. For operations that create nothing (flip)
//   or whose id order is fixed by a contract (the core's split order). Dead slots' stale pointers are ignored.
// - compare_meshes: up to renumbering. Vertices are paired by position (within the tolerance, one to one,
//   nearest pairs first), then the faces (as cyclic vertex sequences, orientation included), the boundary
//   loops (likewise) and the edges (unordered vertex pairs) must correspond under that pairing. Which
//   halfedge a vertex, edge or face points to is not compared: it is not part of the shape.
//
// Invariants of the result:
// - `equal` is true exactly when `total_differences` is 0.
// - `differences` holds the first `max_differences` messages in a fixed order (counts, vertices, faces,
//   boundary loops, edges; each in id order), so the same inputs give the same text. Messages past the cap
//   are counted, never formatted (comparing two huge different meshes stays O(n log n)).
// - Messages name elements with format_id and say whose they are: "your vertex v12 at (0.5, 0, 0) has no
//   match in the reference; the nearest is reference v9 at (0.5, 0.1, 0), 0.1 away", "reference face f3
//   (v0 v4 v7) is missing from yours", "the reference has 48 faces, yours 36".
// - Neither mesh has to be valid: every walk is bounded and every id is checked before it is followed; a
//   face whose cycle does not close is reported, not followed forever.
// - Vertex pairing is O(n log n) expected (a hash grid with cells the size of the tolerance). Positions that
//   are not finite never match anything. When several reference vertices lie within the tolerance of each
//   other the pairing may pick the wrong twin of them; meshes with coincident vertices should be compared
//   exactly instead.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit {

struct CompareOptions {
  double position_tolerance = 1e-9;  // largest distance between positions that count as the same point
  size_t max_differences = 20;       // messages kept in MeshComparison::differences
};

struct MeshComparison {
  bool equal = true;
  std::vector<std::string> differences;  // the first max_differences messages
  size_t total_differences = 0;          // every difference found, including those past the cap

  // Filled by compare_meshes (up to renumbering) only; ids of the mesh named in each comment.
  std::vector<VertexId> vertex_map;           // your vertex id -> reference vertex (invalid if unmatched);
                                              // size = your vertex capacity
  std::vector<VertexId> unmatched_vertices;   // yours, no reference vertex at that position
  std::vector<VertexId> unmatched_reference;  // reference vertices none of yours matched
  std::vector<FaceId> extra_faces;            // yours, not in the reference (reversed ones included)
  std::vector<FaceId> missing_faces;          // the reference's, not in yours (reversed ones included)
  std::vector<FaceId> reversed_faces;         // yours, in the reference with the opposite orientation
  std::vector<FaceId> extra_boundaries;       // yours
  std::vector<FaceId> missing_boundaries;     // the reference's
  std::vector<EdgeId> extra_edges;            // yours, joining two vertices the reference does not join
  std::vector<EdgeId> missing_edges;          // the reference's, joining two vertices yours does not join

  // "equal", or "3 differences; first: <message>".
  std::string summary() const;
};

// Pointer for pointer (see above). With position_tolerance 0 positions must be equal bit for bit.
MeshComparison compare_meshes_exact(const HalfedgeMesh& yours, const HalfedgeMesh& reference,
                                    const CompareOptions& options = {});

// Up to renumbering (see above).
MeshComparison compare_meshes(const HalfedgeMesh& yours, const HalfedgeMesh& reference,
                              const CompareOptions& options = {});

// The position tolerance for comparing what was made from `input` with the reference: 1e-9 x the bounding-box
// diagonal of its live vertices, at least 1e-9 (and 1e-9 when the diagonal is not finite), so a unit cube and a scan
// in millimetres are held to the same relative precision. Every check of one exercise on a mesh uses this one.
double mesh_tolerance(const HalfedgeMesh& input);
// The same for a list of points (a curve step's, a patch's): 1e-9 x their largest coordinate, at least 1e-9 (and 1e-9
// when it is not finite).
double points_tolerance(std::span<const glm::dvec3> points);

}  // namespace meshedit
