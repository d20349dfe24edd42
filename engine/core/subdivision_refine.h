// The refined connectivity shared by Catmull-Clark and linear subdivision: every original edge gets one new
// vertex, some faces get a centre vertex, and each original face is replaced by its children.
//
// Rules (RefineRule):
//   Quads           every face of n corners becomes n quads (corner, next edge vertex, centre, previous edge
//                   vertex): Catmull-Clark's topology, for any polygon;
//   TrianglesInFour a triangle becomes 4 triangles at its edge vertices (three corners and the middle one);
//                   any other face becomes quads around a centre vertex, as under Quads.
// Ids in the refined mesh (plan_refinement fixes them, refine_mesh builds them):
//   - original vertex ids are kept (a dead original slot stays a dead slot);
//   - then one vertex per live original edge, in edge id order;
//   - then one centre vertex per live face that gets one, in face id order;
//   - faces: each live original face's children in face id order; a face's children start at the corner
//     halfedge(f) leaves and go round the face in `next` order (under TrianglesInFour the middle triangle
//     comes last); edges, halfedges and boundary loops in build_halfedge_mesh's order (mesh_build.h).
// Invariant: refine_mesh reads the original mesh only and returns a new one, so a caller that refuses keeps
// the original unchanged; on a mesh can_refine accepts the result is one validate() accepts, with the ids
// build_halfedge_mesh gives the children (mesh_build.h).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/check.h"
#include "core/halfedge_mesh.h"
#include "core/polygon_mesh.h"

namespace meshedit {

enum class RefineRule { Quads, TrianglesInFour };

// Where the new vertices go in the refined mesh, by the original mesh's ids.
struct RefineLayout {
  static constexpr uint32_t kNone = ~uint32_t(0);
  std::vector<uint32_t> edge_vertex;  // by original edge id: the id of the vertex on that edge (kNone if dead)
  std::vector<uint32_t> face_vertex;  // by original face slot: the id of its centre vertex, or kNone
  uint32_t vertex_count = 0;          // vertex capacity of the refined mesh
};

// A valid mesh (validate()) with no face that lies on both sides of one of its edges or meets a vertex twice
// (either would give a child face with a repeated corner). The reason names the face or the first problem.
Check can_refine(const HalfedgeMesh& mesh, const char* scheme);

RefineLayout plan_refinement(const HalfedgeMesh& mesh, RefineRule rule);

// The positions of linear refinement, by refined vertex id: original vertices where they are, edge vertices at
// their edge's midpoint, centre vertices at their face's centroid (the mean of its corners).
std::vector<glm::dvec3> midpoint_positions(const HalfedgeMesh& mesh, const RefineLayout& layout);

// The children as indexed polygons, vertex i at positions[i] (positions.size() == layout.vertex_count): what
// build_halfedge_mesh would be given. Precondition: layout == plan_refinement(mesh, rule).
PolygonMesh refined_polygons(const HalfedgeMesh& mesh, RefineRule rule, const RefineLayout& layout,
                             const std::vector<glm::dvec3>& positions);

// The refined mesh: exactly build_halfedge_mesh(refined_polygons(...)) (a test holds the two together), built
// without the builder's search for twins, since each child's twins follow from the original mesh's.
// Precondition: can_refine(mesh) and layout == plan_refinement(mesh, rule).
HalfedgeMesh refine_mesh(const HalfedgeMesh& mesh, RefineRule rule, const RefineLayout& layout,
                         const std::vector<glm::dvec3>& positions);

}  // namespace meshedit
