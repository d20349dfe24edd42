// What the renderer draws of a HalfedgeMesh, built on the CPU: pure functions, no GL, unit-tested. The rules below
// decide what is drawable; the renderer's buffers lay the same things out by element slot (slot_geometry.h), and
// build_mesh_geometry is the compact reference they are tested against.
//
// Every primitive carries the id of its element, for colouring and picking.
// - Faces become triangles fanned from the face's first halfedge (h0's vertex, then each consecutive
//   pair of the cycle), with the face's slot per triangle.
// - A face is drawn only if its next-cycle closes within the bound, every halfedge of the cycle is live
//   and points back to the face, and every corner is a live vertex with a finite position. Anything
//   else (a student's script can leave the mesh broken) is skipped and listed, never followed forever:
//   each halfedge is visited at most once by the whole build, so a broken mesh costs no more than a
//   good one.
// - An edge is drawn from vertex(h) to vertex(twin(h)) of its halfedge h when those are live and finite;
//   it is flagged boundary when either halfedge's face is a boundary loop.
// - A halfedge arrow lies inside its face: from near h.vertex to near h.next.vertex, moved towards the
//   face centre, with a head of two barbs. Every point is a convex combination of the two corners and
//   the centre (the barbs stay nearer the centre than the edge), so for a convex face the whole arrow
//   is inside it. Halfedges on boundary loops have no face to sit in and get no arrow.
// - Normals: flat = core's face normal (Newell), smooth = core's area-weighted vertex normal
//   (core/normals.h); either is the zero vector where it is undefined, and the shaders fall back.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"
#include "core/state_before.h"
#include "render/camera.h"

namespace meshedit {

inline constexpr uint32_t kEdgeBoundaryFlag = 1u;
inline constexpr uint32_t kEdgeHiddenFlag = 2u;  // a slot with nothing to draw (slot_geometry.h); shaders skip it

struct EdgeSegment {
  glm::vec3 start{0.0f};
  glm::vec3 end{0.0f};
  uint32_t edge = kInvalidIndex;
  uint32_t flags = 0;  // kEdgeBoundaryFlag
};

struct VertexPoint {
  glm::vec3 position{0.0f};
  uint32_t vertex = kInvalidIndex;
};

struct HalfedgeArrow {
  glm::vec3 tail{0.0f};
  glm::vec3 tip{0.0f};
  glm::vec3 barb_inner{0.0f};  // the barb on the face-centre side
  glm::vec3 barb_outer{0.0f};  // the barb on the edge side
  uint32_t halfedge = kInvalidIndex;
};

struct MeshGeometry {
  // Indexed by vertex id (size = vertex_capacity()); slots no drawn primitive uses hold zeros.
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> smooth_normals;
  // Indexed by face slot (size = face_capacity()).
  std::vector<glm::vec3> face_normals;
  // Three vertex ids per triangle, and the face slot of each triangle.
  std::vector<uint32_t> triangle_corners;
  std::vector<uint32_t> triangle_faces;
  std::vector<EdgeSegment> edges;     // drawable live edges, in id order
  std::vector<VertexPoint> points;    // live vertices with finite positions, in id order
  std::vector<FaceId> skipped_faces;  // live faces that could not be walked, in id order
  std::vector<EdgeId> skipped_edges;  // live edges with a dead or non-finite end
  BoundingBox bounds;                 // of `points`

  size_t triangle_count() const { return triangle_faces.size(); }
};

MeshGeometry build_mesh_geometry(const HalfedgeMesh& mesh);

// One face's walk by the rule above. Closed: `cycle` holds its halfedges from halfedge(f) on. Broken: the face
// is not drawable. TooLong: it did not close within `max_steps` halfedges (only when max_steps is below the
// halfedge capacity; the caller decides what to do). With `visited` (one flag per halfedge slot, shared by the
// calls of one whole-mesh build) no halfedge is walked twice; a halfedge is marked only once its face matched,
// so the flags never change another face's outcome.
enum class FaceWalk { Closed, Broken, TooLong };
FaceWalk walk_face_cycle(const HalfedgeMesh& mesh, FaceId f, std::vector<HalfedgeId>& cycle,
                         std::vector<uint8_t>* visited, uint32_t max_steps);
// The same in the state before an edit, read through its patch (the renderer's in-place update).
FaceWalk walk_face_cycle(const StateBefore& mesh, FaceId f, std::vector<HalfedgeId>& cycle,
                         std::vector<uint8_t>* visited, uint32_t max_steps);
// The arrows of a closed cycle, appended in cycle order: what build_halfedge_arrows makes for that face.
void add_cycle_arrows(const HalfedgeMesh& mesh, const std::vector<HalfedgeId>& cycle, std::vector<HalfedgeArrow>& out);
// Arrows of every halfedge of every drawable face, face by face in id order, each cycle from the face's
// halfedge. Costs about 100 bytes per halfedge on the GPU, so the renderer builds it only on demand.
std::vector<HalfedgeArrow> build_halfedge_arrows(const HalfedgeMesh& mesh);

// One element at a time (for highlights and labels); nullopt where the whole-mesh build draws nothing.
std::optional<HalfedgeArrow> halfedge_arrow(const HalfedgeMesh& mesh, HalfedgeId h);
std::optional<EdgeSegment> edge_segment(const HalfedgeMesh& mesh, EdgeId e);
std::optional<EdgeSegment> edge_segment(const StateBefore& mesh, EdgeId e);
// The face's corners in cycle order, if the face is drawable.
std::optional<std::vector<glm::dvec3>> face_corners(const HalfedgeMesh& mesh, FaceId f);

// Bounding box of the live vertices with finite positions.
BoundingBox mesh_bounds(const HalfedgeMesh& mesh);

}  // namespace meshedit
