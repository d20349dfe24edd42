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

#include "core/parallel_for.h"

namespace meshedit {

namespace {

// Area below this fraction of the squared size of the face counts as zero: rounding in the cross
// products of a collinear polygon leaves ~1e-17 relative noise, which must not become a direction.
constexpr double kZeroAreaRelative = 1e-14;

// Twice the vector area of the face cycle that starts at `start` (Newell's sum, taken relative to start's tail so
// precision does not depend on where the mesh sits), or zero for a face with (numerically) no area. False, with
// zero, if the cycle does not close, has fewer than 3 halfedges, or reaches a dead halfedge or vertex.
bool face_term_from(const HalfedgeMesh& mesh, HalfedgeId start, glm::dvec3& out) {
  out = glm::dvec3(0.0);
  bool ok = true;
  bool first = true;
  glm::dvec3 origin(0.0), previous(0.0);
  double size_sq = 0.0;  // squared distance of the farthest corner from the first
  bool closed = false;
  HalfedgeId h = start;
  uint32_t steps = 0;
  for (; steps <= mesh.halfedge_capacity(); ++steps) {
    if (!mesh.alive(h)) break;
    const VertexId v = mesh.vertex(h);
    if (!ok || !mesh.alive(v)) {
      ok = false;
    } else if (first) {
      origin = mesh.position(v);
      first = false;
    } else {
      const glm::dvec3 p = mesh.position(v) - origin;
      out += glm::cross(previous, p);  // the closing term cross(last, origin - origin) is zero
      size_sq = std::max(size_sq, glm::dot(p, p));
      previous = p;
    }
    h = mesh.next(h);
    if (h == start) {
      closed = steps >= 2;  // a cycle of one or two halfedges is no face
      break;
    }
  }
  if (!closed || !ok) {
    out = glm::dvec3(0.0);
    return false;
  }
  if (!(glm::length(out) > kZeroAreaRelative * size_sq)) out = glm::dvec3(0.0);
  return true;
}

// The term of f from its own halfedge (face normals and areas).
bool face_term(const HalfedgeMesh& mesh, FaceId f, glm::dvec3& out) {
  if (!mesh.alive(f)) {
    out = glm::dvec3(0.0);
    return false;
  }
  return face_term_from(mesh, mesh.halfedge(f), out);
}

// Unit vector along `n`, or zero when `n` is zero (or not finite).
glm::dvec3 unit_or_zero(const glm::dvec3& n) {
  const double length = glm::length(n);
  if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0);
  return n / length;
}

// The summed vector areas of v's real faces, each face's term taken from the outgoing halfedge h of the fan
// (term_of(h, term)). False (and zero) if the fan does not close or meets a dead face.
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
    if (!term_of(h, term)) ok = false;
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
  const auto term = [&](HalfedgeId h, glm::dvec3& out) { return face_term_from(mesh, h, out); };
  if (!sum_around_vertex(mesh, v, term, sum)) return glm::dvec3(0.0);
  return unit_or_zero(sum);
}

std::vector<glm::dvec3> face_normals(const HalfedgeMesh& mesh) {
  std::vector<glm::dvec3> normals(mesh.face_capacity(), glm::dvec3(0.0));
  for (FaceId f : mesh.faces()) normals[f.slot()] = face_normal(mesh, f);
  return normals;
}

namespace {

// The term of triangle (v, a, b) taken from v: face_term_from's arithmetic, step by step, so the bits agree.
glm::dvec3 corner_term(const glm::dvec3& v, const glm::dvec3& a, const glm::dvec3& b) {
  glm::dvec3 sum(0.0), previous(0.0);
  const glm::dvec3 p1 = a - v;
  sum += glm::cross(previous, p1);
  double size_sq = std::max(0.0, glm::dot(p1, p1));
  previous = p1;
  const glm::dvec3 p2 = b - v;
  sum += glm::cross(previous, p2);
  size_sq = std::max(size_sq, glm::dot(p2, p2));
  if (!(glm::length(sum) > kZeroAreaRelative * size_sq)) sum = glm::dvec3(0.0);
  return sum;
}

// face_term_from(h0) for a live h0 whose next and that one's next are live, close a 3-cycle and leave live
// vertices, without the generic walk. False (nothing written) for any other start.
bool triangle_term_from(const HalfedgeMesh& mesh, HalfedgeId h0, glm::dvec3& out) {
  const HalfedgeId h1 = mesh.next(h0);
  if (h1 == h0 || !mesh.alive(h1)) return false;
  const HalfedgeId h2 = mesh.next(h1);
  if (h2 == h0 || !mesh.alive(h2) || mesh.next(h2) != h0) return false;
  const VertexId a = mesh.vertex(h0), b = mesh.vertex(h1), c = mesh.vertex(h2);
  if (!mesh.alive(a) || !mesh.alive(b) || !mesh.alive(c)) return false;
  out = corner_term(mesh.position(a), mesh.position(b), mesh.position(c));
  return true;
}

// vertex_normals on a mesh proven valid with triangle faces only: around v, the face of the k-th outgoing
// halfedge h_k (v -> w_k) is (v, w_k, w_{k-1}), since h_k follows twin(h_{k-1}) in its face; so the one-ring
// positions give every term, with no check and no read of the faces' other halfedges. Same terms, same order,
// same bits as vertex_normal.
void ring_normals(const HalfedgeMesh& mesh, std::vector<glm::dvec3>& normals, int threads) {
  parallel_for(threads, mesh.vertex_capacity(), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const VertexId v(static_cast<uint32_t>(i));
      if (!mesh.alive(v)) {
        normals[i] = glm::dvec3(0.0);
        continue;
      }
      const glm::dvec3& p = mesh.position(v);
      const HalfedgeId start = mesh.halfedge(v);
      // w_{-1}: the tail of the halfedge before h_0 in h_0's face (for a boundary h_0 it is never used).
      glm::dvec3 previous = mesh.position(mesh.vertex(mesh.next(mesh.next(start))));
      glm::dvec3 sum(0.0);
      HalfedgeId h = start;
      do {
        const HalfedgeId t = mesh.twin(h);
        const glm::dvec3& w = mesh.position(mesh.vertex(t));
        if (!mesh.face(h).is_boundary()) sum += corner_term(p, w, previous);
        previous = w;
        h = mesh.next(t);
      } while (h != start);
      normals[i] = unit_or_zero(sum);
    }
  });
}

}  // namespace

void vertex_normals(const HalfedgeMesh& mesh, std::vector<glm::dvec3>& normals, int threads) {
  // vertex_normal for every vertex, each triangle's term from triangle_term_from (the generic walk for anything
  // else): the same terms in the same order, so the same bits. Each face's term is taken from the vertex's own
  // halfedge, so no per-face array is needed (fresh memory costs more than the arithmetic on a big mesh).
  normals.resize(mesh.vertex_capacity());
  if (mesh.proven_valid_triangles()) {
    ring_normals(mesh, normals, threads);
    return;
  }
  const auto term = [&](HalfedgeId h, glm::dvec3& out) {
    return triangle_term_from(mesh, h, out) || face_term_from(mesh, h, out);
  };
  parallel_for(threads, mesh.vertex_capacity(), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      glm::dvec3 sum;
      normals[i] = sum_around_vertex(mesh, VertexId(static_cast<uint32_t>(i)), term, sum) ? unit_or_zero(sum)
                                                                                           : glm::dvec3(0.0);
    }
  });
}

std::vector<glm::dvec3> vertex_normals(const HalfedgeMesh& mesh, int threads) {
  std::vector<glm::dvec3> normals;
  vertex_normals(mesh, normals, threads);
  return normals;
}

}  // namespace meshedit
