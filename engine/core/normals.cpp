// Face normals, face areas and area-weighted vertex normals (see normals.h for the definitions).
//
// Invariants kept here:
// - Every walk is bounded (HalfedgeMesh's own walks) and every id is checked with alive() before its
//   pointers or position are read, so a broken mesh yields zero vectors, never a hang or a stray read.
// - The per-element and whole-mesh functions add the same terms in the same order, so they agree bit
//   for bit (the renderer uses one, tests and Lua the other).
#include "core/normals.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace meshedit {

namespace {

// Area below this fraction of the squared size of the face counts as zero: rounding in the cross
// products of a collinear polygon leaves ~1e-17 relative noise, which must not become a direction.
constexpr double kZeroAreaRelative = 1e-14;

// Twice f's vector area (Newell's sum, taken relative to the first corner so precision does not depend
// on where the mesh sits), or zero for a face with (numerically) no area. False, with zero, if the cycle
// does not close or reaches a dead vertex.
bool face_term(const HalfedgeMesh& mesh, FaceId f, glm::dvec3& out) {
  out = glm::dvec3(0.0);
  if (!mesh.alive(f)) return false;
  bool ok = true;
  bool first = true;
  glm::dvec3 origin(0.0), previous(0.0);
  double size_sq = 0.0;  // squared distance of the farthest corner from the first
  const bool closed = mesh.for_each_face_halfedge(f, [&](HalfedgeId h) {
    const VertexId v = mesh.vertex(h);
    if (!ok || !mesh.alive(v)) {
      ok = false;
      return;
    }
    if (first) {
      origin = mesh.position(v);
      first = false;
      return;
    }
    const glm::dvec3 p = mesh.position(v) - origin;
    out += glm::cross(previous, p);  // the closing term cross(last, origin - origin) is zero
    size_sq = std::max(size_sq, glm::dot(p, p));
    previous = p;
  });
  if (!closed || !ok) {
    out = glm::dvec3(0.0);
    return false;
  }
  if (!(glm::length(out) > kZeroAreaRelative * size_sq)) out = glm::dvec3(0.0);
  return true;
}

// Unit vector along `n`, or zero when `n` is zero (or not finite).
glm::dvec3 unit_or_zero(const glm::dvec3& n) {
  const double length = glm::length(n);
  if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0);
  return n / length;
}

// The summed vector areas of v's real faces, taking each face's term from `term_of`.
// False (and zero) if the fan does not close or meets a dead face.
template <class FaceTerm>
bool sum_around_vertex(const HalfedgeMesh& mesh, VertexId v, FaceTerm&& term_of, glm::dvec3& sum) {
  sum = glm::dvec3(0.0);
  if (!mesh.alive(v)) return false;
  bool ok = true;
  const bool closed = mesh.for_each_outgoing(v, [&](HalfedgeId h) {
    const FaceId f = mesh.face(h);
    if (!ok || !mesh.alive(f)) {
      ok = false;
      return;
    }
    if (f.is_boundary()) return;
    glm::dvec3 term;
    if (!term_of(f, term)) ok = false;
    sum += term;
  });
  if (!closed || !ok) {
    sum = glm::dvec3(0.0);
    return false;
  }
  return true;
}

}  // namespace

glm::dvec3 face_normal(const HalfedgeMesh& mesh, FaceId f) {
  glm::dvec3 n;
  return face_term(mesh, f, n) ? unit_or_zero(n) : glm::dvec3(0.0);
}

double face_area(const HalfedgeMesh& mesh, FaceId f) {
  glm::dvec3 n;
  return face_term(mesh, f, n) ? 0.5 * glm::length(n) : 0.0;
}

glm::dvec3 vertex_normal(const HalfedgeMesh& mesh, VertexId v) {
  // area * unit normal is the vector area itself, so no per-face normalisation is needed; the common
  // factor 1/2 does not change the direction.
  glm::dvec3 sum;
  const auto term = [&](FaceId f, glm::dvec3& out) { return face_term(mesh, f, out); };
  if (!sum_around_vertex(mesh, v, term, sum)) return glm::dvec3(0.0);
  return unit_or_zero(sum);
}

std::vector<glm::dvec3> face_normals(const HalfedgeMesh& mesh) {
  std::vector<glm::dvec3> normals(mesh.face_capacity(), glm::dvec3(0.0));
  for (FaceId f : mesh.faces()) normals[f.slot()] = face_normal(mesh, f);
  return normals;
}

std::vector<glm::dvec3> vertex_normals(const HalfedgeMesh& mesh) {
  // Each face's vector area once (O(H) in total), then one fan walk per vertex summing them.
  std::vector<glm::dvec3> areas(mesh.face_capacity(), glm::dvec3(0.0));
  std::vector<uint8_t> closed(mesh.face_capacity(), 0);
  for (FaceId f : mesh.faces()) closed[f.slot()] = face_term(mesh, f, areas[f.slot()]) ? 1 : 0;

  const auto term = [&](FaceId f, glm::dvec3& out) {
    out = areas[f.slot()];
    return closed[f.slot()] != 0;
  };
  std::vector<glm::dvec3> normals(mesh.vertex_capacity(), glm::dvec3(0.0));
  for (VertexId v : mesh.vertices()) {
    glm::dvec3 sum;
    if (sum_around_vertex(mesh, v, term, sum)) normals[v.index] = unit_or_zero(sum);
  }
  return normals;
}

}  // namespace meshedit
