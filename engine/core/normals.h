// Face normals and area-weighted vertex normals (Part 3 of the assignment).
//
// - A face normal is the unit normal of the polygon (Newell's sum, so n-gons work); a zero-area face
//   has the zero vector. "Zero area" allows for rounding: a face whose doubled vector area is no longer
//   than 1e-14 times the largest squared distance from its first corner to another counts as zero (a
//   collinear triangle, however rounded). A boundary loop's FaceId is accepted too and gives the loop's
//   polygon, which runs the other way round from the faces beside the hole.
// - A vertex normal is the sum over the vertex's real faces of (face area x face unit normal) — for a
//   triangle that is half the cross product of two edges — normalised. Each face's vector area is Newell's sum
//   taken from the vertex itself (for a triangle (v, a, b): cross(a - v, b - v)), with the zero-area rule
//   measured from v. Boundary loops are skipped, so
//   boundary vertices get the normal of the faces they do have. A vertex with no area around it gets
//   the zero vector.
// - Walks are bounded and every id is checked before it is followed: a broken mesh yields zero vectors
//   where a fan or cycle does not close or reaches a dead element; dead or out-of-range ids give zero.
// - The whole-mesh versions equal the per-element ones exactly (same terms, same order), with one exception for
//   speed: on a mesh whose connectivity Loop subdivision left (HalfedgeMesh::triangle_rows: its rows, whatever the
//   positions are now) or one proven valid with triangle faces only (HalfedgeMesh::proven_valid_triangles: just
//   built or subdivided), vertex_normals adds each face's vector area, taken from the face's own first corner, to
//   its three corners, in row order or in face order. That agrees with vertex_normal to rounding (a few units in the
//   last place). In row order the bits are the same on any number of threads; in face order they depend on it.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit {

glm::dvec3 face_normal(const HalfedgeMesh& mesh, FaceId f);
double face_area(const HalfedgeMesh& mesh, FaceId f);
glm::dvec3 vertex_normal(const HalfedgeMesh& mesh, VertexId v);

// Indexed by id (size = capacity); dead slots hold zero vectors.
std::vector<glm::dvec3> face_normals(const HalfedgeMesh& mesh);
std::vector<glm::dvec3> vertex_normals(const HalfedgeMesh& mesh, int threads = 1);

// The same, into `normals` (resized to the vertex capacity): a caller that recomputes normals often (the renderer,
// benchmarks) keeps the vector and allocates nothing after the first call. `threads` > 1 splits the work over
// that many threads; the result does not depend on it beyond rounding (see above).
void vertex_normals(const HalfedgeMesh& mesh, std::vector<glm::dvec3>& normals, int threads = 1);

}  // namespace meshedit
