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

#include "core/mesh_storage.h"
#include "core/parallel_for.h"

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

namespace {

// face_term for a face whose halfedge, its next and that one's next are live, close a triangle and leave live
// vertices: the same arithmetic, without the generic walk. False (nothing written) for any other face.
bool triangle_term(const MeshStorage::ReadView& r, uint32_t f, glm::dvec3& out) {
  const HalfedgeId h0 = r.face_halfedge[f];
  if (!r.alive(h0)) return false;
  const HalfedgeId h1 = r.h[h0.index].next;
  if (!r.alive(h1)) return false;
  const HalfedgeId h2 = r.h[h1.index].next;
  if (!r.alive(h2) || r.h[h2.index].next != h0) return false;
  const VertexId v0 = r.h[h0.index].vertex, v1 = r.h[h1.index].vertex, v2 = r.h[h2.index].vertex;
  if (!r.alive(v0) || !r.alive(v1) || !r.alive(v2)) return false;
  // Term by term as face_term adds them, so the bits agree.
  const glm::dvec3 origin = r.position[v0.index];
  glm::dvec3 sum(0.0), previous(0.0);
  const glm::dvec3 p1 = r.position[v1.index] - origin;
  sum += glm::cross(previous, p1);
  double size_sq = std::max(0.0, glm::dot(p1, p1));
  previous = p1;
  const glm::dvec3 p2 = r.position[v2.index] - origin;
  sum += glm::cross(previous, p2);
  size_sq = std::max(size_sq, glm::dot(p2, p2));
  if (!(glm::length(sum) > kZeroAreaRelative * size_sq)) sum = glm::dvec3(0.0);
  out = sum;
  return true;
}

}  // namespace

void vertex_normals(const HalfedgeMesh& mesh, std::vector<glm::dvec3>& normals, int threads) {
  // vertex_normal for every vertex, with its for_each_outgoing / sum_around_vertex walk fused over the raw records
  // and each triangle's term from triangle_term: the same terms in the same order, so the same bits. A face's term
  // is recomputed for each of its corners rather than kept in a per-face array: that costs some arithmetic but no
  // fresh memory, which on a big mesh costs more (page faults).
  const MeshStorage::ReadView r = MeshStorage::read_view(mesh);
  normals.resize(r.vertices);
  parallel_for(threads, r.vertices, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      normals[v] = glm::dvec3(0.0);
      if (!r.vertex_alive[v]) continue;
      const HalfedgeId start = r.vertex_halfedge[v];
      HalfedgeId h = start;
      glm::dvec3 sum(0.0), term;
      bool ok = true, fan_closed = false;
      for (uint32_t steps = 0; steps <= r.halfedges; ++steps) {
        if (!r.alive(h)) break;
        const HalfedgeRecord& rec = r.h[h.index];
        const FaceId f = rec.face;
        if (!ok || !r.alive(f)) {
          ok = false;
        } else if (!f.is_boundary()) {
          if (!triangle_term(r, f.slot(), term) && !face_term(mesh, f, term)) ok = false;
          sum += term;
        }
        if (!r.alive(rec.twin)) break;
        h = r.h[rec.twin.index].next;
        if (h == start) {
          fan_closed = true;
          break;
        }
      }
      if (fan_closed && ok) normals[v] = unit_or_zero(sum);
    }
  });
}

std::vector<glm::dvec3> vertex_normals(const HalfedgeMesh& mesh, int threads) {
  std::vector<glm::dvec3> normals;
  vertex_normals(mesh, normals, threads);
  return normals;
}

}  // namespace meshedit
