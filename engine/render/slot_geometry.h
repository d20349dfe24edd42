// SlotGeometry: what the renderer's GPU buffers hold, laid out by element slot, built on the CPU (no GL).
//
// Every buffer is indexed by the id of the element it draws, so one element's change rewrites its own slots and
// nothing else moves (incremental_update.h relies on it):
// - vertex slot v: position, smooth normal, and a point (hidden when v is dead or not finite);
// - face slot f: the first triangle of f's fan (h0's vertex and the next two corners), or 0 0 0 (nothing is
//   rasterised) when f is dead or not drawable, and f's unit normal (zero when not drawn). The later fan triangles
//   of polygons are packed after, in face order, with their face slots (`extra_*`);
// - edge slot e: its segment, or a hidden one (kEdgeHiddenFlag, id kInvalidIndex) when e is not drawable;
// - halfedge slot h (arrows, built on demand): three segments, hidden when h has no arrow.
// What is drawable is mesh_geometry.h's rule, and the drawn set equals build_mesh_geometry's (a test checks it).
//
// Normals: a face's term is twice its vector area (Newell's sum relative to its first corner, zero below the
// core's zero-area rule: core/normals.h), its flat normal the unit term. A vertex's smooth normal is the unit sum
// of the terms of the drawn faces it is a corner of, added in face id order (once per corner it is). On a valid mesh
// that is core's vertex_normal up to the order of the sum; on a broken one it is the normal of what is drawn. It
// depends on nothing but drawn faces, so an edit's effect on it is found from the faces it redraws.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/halfedge_mesh.h"
#include "render/camera.h"
#include "render/mesh_geometry.h"

namespace meshedit {

// How one face is drawn: its corners' vertex ids in cycle order (empty when not drawn) and its term.
struct FaceDraw {
  FaceWalk walk = FaceWalk::Broken;
  std::vector<uint32_t> corners;
  glm::dvec3 term{0.0};

  bool drawn() const { return walk == FaceWalk::Closed; }
  size_t triangle_count() const { return drawn() ? corners.size() - 2 : 0; }
};

// f's drawing (see walk_face_cycle for `visited` and `max_steps`); `cycle` is scratch space and holds the walk.
void draw_face(const HalfedgeMesh& mesh, FaceId f, FaceDraw& out, std::vector<HalfedgeId>& cycle,
               std::vector<uint8_t>* visited = nullptr, uint32_t max_steps = kInvalidIndex);
// The same in the state before an edit, read through its patch (the renderer's in-place update).
void draw_face(const StateBefore& mesh, FaceId f, FaceDraw& out, std::vector<HalfedgeId>& cycle,
               std::vector<uint8_t>* visited = nullptr, uint32_t max_steps = kInvalidIndex);

// The unit vector along a term, or zero (core/normals.h's rule).
glm::dvec3 unit_or_zero(const glm::dvec3& v);
// A face's flat normal from its term: the unit term as a vec4 with w = 0 (zero where the term is).
glm::vec4 flat_normal(const glm::dvec3& term);

struct SlotCounts {
  size_t triangles = 0;      // drawn triangles (first and extra)
  size_t skipped_faces = 0;  // live faces not drawable
  size_t edges = 0;          // drawn edges
  size_t skipped_edges = 0;  // live edges not drawable
  size_t vertices = 0;       // drawn points
  bool operator==(const SlotCounts&) const = default;
};

// The per-slot arrays are MeshArrays (core/halfedge_mesh.h): at a million faces they are over 100 MB written once
// per full build, and huge pages fault them in 512 times fewer steps.
struct SlotGeometry {
  MeshArray<glm::vec3> positions;         // per vertex slot; zero where hidden
  MeshArray<glm::vec3> smooth_normals;    // per vertex slot
  MeshArray<VertexPoint> points;          // per vertex slot; hidden: position 0, id kInvalidIndex
  MeshArray<uint32_t> triangles;          // 3 per face slot
  MeshArray<glm::vec4> face_normals;      // per face slot (w = 0)
  std::vector<uint32_t> extra_triangles;  // 3 per later fan triangle of a polygon, in face order
  std::vector<uint32_t> extra_faces;      // the face slot of each of those
  MeshArray<EdgeSegment> edges;           // per edge slot
  std::vector<uint32_t> boundary_edges;   // drawn edges flagged boundary, ascending ids
  SlotCounts counts;
  BoundingBox bounds;  // of the drawn points
};

// The whole build, on up to `threads` threads (parallel_for.h); the result does not depend on the thread count,
// byte for byte.
SlotGeometry build_slot_geometry(const HalfedgeMesh& mesh, int threads = 1);

// One slot's value, as build_slot_geometry computes it.
VertexPoint slot_point(const HalfedgeMesh& mesh, VertexId v);
EdgeSegment slot_edge(const HalfedgeMesh& mesh, EdgeId e);
VertexPoint slot_point(const StateBefore& mesh, VertexId v);  // in the state before an edit
EdgeSegment slot_edge(const StateBefore& mesh, EdgeId e);
std::array<EdgeSegment, 3> slot_arrow(const HalfedgeMesh& mesh, HalfedgeId h);  // hidden when h has no arrow
inline constexpr EdgeSegment kHiddenSegment{glm::vec3(0.0f), glm::vec3(0.0f), kInvalidIndex, kEdgeHiddenFlag};
inline constexpr VertexPoint kHiddenPoint{glm::vec3(0.0f), kInvalidIndex};
inline bool hidden(const EdgeSegment& s) { return (s.flags & kEdgeHiddenFlag) != 0; }

// Three segments per halfedge slot (see the header comment); build_halfedge_arrows' arrows at their slots.
std::vector<EdgeSegment> build_slot_arrows(const HalfedgeMesh& mesh);

// The smooth normal of a vertex from the drawings of the faces it is a corner of, in ascending face id order
// (each with its corner count): the whole-mesh build's sum, term for term.
struct CornerFace {
  uint32_t face;
  const FaceDraw* draw;
};
glm::vec3 smooth_normal(uint32_t vertex, std::vector<CornerFace>& faces);

}  // namespace meshedit
