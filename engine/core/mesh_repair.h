// Repairing indexed polygons so the half-edge builder (mesh_build.h) accepts them, with a report of every change.
//
// The steps, in order (each sees the previous ones' result):
// 1. faces that are not polygons are dropped: an index out of range, fewer than 3 corners, a repeated corner, or
//    zero area (Newell normal of length below 1e-12 of the squared perimeter);
// 2. a face with the same corners as an earlier face (in any order or direction) is dropped;
// 3. at an edge used by three or more faces, the first face and the first later one that uses the edge the other
//    way (else the second) keep it; each other face is detached: its two corners on that edge become new vertices
//    (copies of the positions) used by that face alone;
// 4. per connected component (faces joined by edges of exactly two faces), faces are re-oriented to agree by a
//    breadth-first walk from the component's lowest face: a face's orientation is fixed when the walk first reaches
//    it, and an edge whose two faces the walk has already fixed to use it the same way is cut (there is one only
//    where the component is one-sided: a Moebius strip, a Klein bottle). Whichever orientation more of the
//    component's faces already had is kept. A cut splits the corners at each end of the edge into pieces, joined
//    through the edges of exactly two faces that are not cut; within each fan (as step 5 counts them) the piece
//    with the lowest face keeps the vertex and each other piece gets a new vertex. Around a vertex whose faces close
//    into a ring an even number of edges are cut (whatever the walk fixed), so each cut edge's two faces end up on
//    different vertices at both its ends: it becomes two boundary edges, and every other edge stays joined;
// 5. a vertex whose faces form several fans (joined through edges of exactly two faces) keeps the fan with the
//    lowest face; each other fan gets a new vertex (a bow-tie split);
// 6. vertices no face uses any more (or ever did) are dropped.
//
// Invariants:
// - Surviving faces keep their order; surviving original vertices keep their order, followed by the new vertices
//   of steps 3, 4 and 5 in the order they were made. Positions are never moved.
// - The repaired polygons always build (build_halfedge_mesh), whatever the input's indices, and the mesh validates
//   when every position is finite (positions are never checked here); repairing them again changes nothing.
// - The report names original vertex and face numbers (what the file says); a new vertex is named by its number in
//   the repaired polygons ("vertex 12 was a bow-tie: split into 12 and new vertex 40 (faces 3, 4 moved)"; "the edge
//   between vertex 4 and vertex 5 was cut: faces 2 and 7 disagree on its direction; it is now between vertex 4 and
//   vertex 5 in face 2, and between new vertex 12 and new vertex 13 in face 7").
//   A mesh with nothing to repair gives an empty report and identical polygons.
// - Each change also has its spots: where it is in the REPAIRED polygons, as output vertex and face indices (which
//   build_halfedge_mesh keeps as VertexId and FaceId: mesh_build.h). A bow-tie split: the vertex's output index,
//   then its new vertices; the faces moved. A detached face: its output face and its two new vertices. Reversed
//   faces: their output faces. A cut edge: the vertices at its ends in its lower face, then in its other face (the
//   edge on each side, as the message names them); its two output faces. A dropped face points at its nearest
//   survivors: a degenerate face at those of its corners that are still used (no face), a repeated face at the face
//   it repeats. Dropped unused vertices point at nothing (empty spots). spots.size() == changes.size().
// - Nothing here builds a half-edge mesh: build_halfedge_mesh keeps refusing unrepaired input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/polygon_mesh.h"

namespace meshedit {

// Where one change is in the repaired polygons (see the invariants): output indices, sorted as the change lists them.
struct RepairSpots {
  std::vector<uint32_t> vertices;
  std::vector<uint32_t> faces;
  bool empty() const { return vertices.empty() && faces.empty(); }
};

struct RepairReport {
  std::vector<std::string> changes;   // one sentence per change, in the order of the steps
  std::vector<RepairSpots> spots;     // spots[i]: where changes[i] is in the repaired polygons
  size_t dropped_bad_faces = 0;       // step 1
  size_t dropped_repeated_faces = 0;  // step 2
  size_t detached_faces = 0;          // step 3
  size_t reversed_faces = 0;          // step 4
  size_t cut_edges = 0;               // step 4: edges whose faces cannot agree
  size_t split_vertices = 0;          // step 5: vertices that were bow-ties
  size_t dropped_vertices = 0;        // step 6

  bool empty() const { return changes.empty(); }
  // One line: "nothing to repair", or the counts ("repaired: 1 bow-tie vertex split, 2 faces reversed").
  std::string summary() const;
};

struct RepairResult {
  PolygonMesh polygons;
  RepairReport report;
};

RepairResult repair_polygons(const PolygonMesh& polygons);

// "3", "3, 5", "20..35", "1, 4..6": sorted numbers with runs of three or more written as ranges.
std::string number_list(std::vector<size_t> numbers);

}  // namespace meshedit
