// Catmull-Clark subdivision of any polygon mesh (triangles, quads, n-gons, with or without boundary), as three
// phases a lesson can step through, plus one call that runs them for any number of levels.
//
//   1. catmull_clark_compute_points: from the original mesh, nothing changes yet:
//        face point   the centroid of the face's corners;
//        edge point   interior edge: the mean of its two ends and its two faces' face points;
//                     boundary edge: its midpoint;
//        vertex point interior vertex of valence n: (F + 2R + (n - 3) P) / n, F the mean of its faces' face
//                     points, R the mean of its edges' midpoints, P where it is;
//                     boundary vertex: 3/4 P + 1/8 (its two neighbours along the boundary).
//   2. catmull_clark_refine: the mesh becomes its refinement, every face of n corners replaced by n quads
//      (corner, edge vertex, face vertex, edge vertex: subdivision_refine.h); the shape does not change yet:
//      original vertices stay where they are, edge vertices sit at midpoints, face vertices at centroids
//      (that mesh is what linear subdivision gives for quads and n-gons).
//   3. catmull_clark_commit_positions: every vertex moves to the point phase 1 computed for it.
// Counts after a level: V' = V + E + F, E' = 2E + (sum of face sides), F' = sum of face sides (4F for quads);
// every face is a quad. Ids as subdivision_refine.h lays out under RefineRule::Quads: original vertices keep
// theirs, then one per edge (edge id order), then one per face (face id order).
// Refused, changing nothing: what can_refine refuses (an invalid mesh, the reason quoting validate()'s first
// problem; a face on both sides of an edge or meeting a vertex twice).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "core/check.h"
#include "core/halfedge_mesh.h"
#include "core/subdivision_refine.h"

namespace meshedit {

// What phase 1 computes and phases 2-3 read.
struct CatmullClarkState {
  RefineLayout layout;                   // the ids phase 2 gives the new vertices
  std::vector<glm::dvec3> face_point;    // by original face slot
  std::vector<glm::dvec3> edge_point;    // by original edge id
  std::vector<glm::dvec3> vertex_point;  // by original vertex id (a dead slot keeps its position)
};

Check can_catmull_clark(const HalfedgeMesh& mesh);
// Each phase assumes the previous ones ran on the same mesh; phase 1 refuses what can_catmull_clark refuses.
OpResult<CatmullClarkState> catmull_clark_compute_points(const HalfedgeMesh& mesh);
void catmull_clark_refine(HalfedgeMesh& mesh, const CatmullClarkState& state);
void catmull_clark_commit_positions(HalfedgeMesh& mesh, const CatmullClarkState& state);

// The three phases in turn: the teaching path, what a lesson steps through.
Check catmull_clark_subdivide_by_phases(HalfedgeMesh& mesh);

// `levels` levels, each building the refined mesh with the final positions at once (no midpoint stage): the same
// mesh as `levels` calls of catmull_clark_subdivide_by_phases, id for id and bit for bit. The input is checked once,
// like can_catmull_clark (each level's result passes that check); a refused mesh is left unchanged.
Check catmull_clark_subdivide(HalfedgeMesh& mesh, int levels = 1);

}  // namespace meshedit
