// Face normals, face areas and area-weighted vertex normals (see normals.h for the definitions).
//
// Invariants kept here:
// - Every walk is bounded (HalfedgeMesh's own walks) and every id is checked with alive() before its
//   pointers or position are read, so a broken mesh yields zero vectors, never a hang or a stray read.
// - The per-element and whole-mesh functions add the same terms in the same order, so they agree bit
//   for bit, except on a mesh with triangle rows or proven valid with triangle faces only: there vertex_normals
//   adds each face's term (taken from the face's own halfedge) in row or face order, which agrees with
//   vertex_normal to rounding. Rows describe a valid triangle mesh's connectivity, so their ids need no check.
#include "core/normals.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "core/memory_hints.h"
#include "core/mesh_storage.h"
#include "core/parallel_for.h"
#include "core/triangle_rows.h"

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

// Adds the term of every live face in [begin, end), taken from the face's own halfedge (face_term_from's
// arithmetic, as face_normal uses it), to its three corners' sums. Only for a mesh proven valid with triangle faces.
// After subdivision a face's halfedges and corners lie far apart in the arrays, so the chain face -> h0 -> h1 -> h2
// and the corners' positions and sums are prefetched a few faces ahead, one link per stage (dead faces are skipped
// there too: their halfedge may be any id). The prefetches are written out at each stage (memory_hints.h's inline
// calls): GCC drops a prefetch inside a helper lambda, a call with no effect it can see.
void add_face_terms(const HalfedgeMesh& mesh, size_t begin, size_t end, glm::dvec3* sums) {
  constexpr size_t kAhead = 32;
  const auto live = [&](size_t f) { return f < end && mesh.alive(FaceId::face(uint32_t(f))); };
  const auto first = [&](size_t f) -> const HalfedgeRecord& {
    return mesh.record(mesh.halfedge(FaceId::face(uint32_t(f))));
  };
  for (size_t f = begin; f < end; ++f) {
    if (live(f + 2 * kAhead)) memory_hints::prefetch(&first(f + 2 * kAhead));
    if (live(f + kAhead)) {
      const HalfedgeRecord& r0 = first(f + kAhead);
      memory_hints::prefetch(&mesh.record(r0.next));
      memory_hints::prefetch(&mesh.position(r0.vertex));
      memory_hints::prefetch(&sums[r0.vertex.index]);
    }
    if (live(f + kAhead / 2)) {
      const HalfedgeRecord& r1 = mesh.record(first(f + kAhead / 2).next);
      memory_hints::prefetch(&mesh.record(r1.next));
      memory_hints::prefetch(&mesh.position(r1.vertex));
      memory_hints::prefetch(&sums[r1.vertex.index]);
    }
    if (!live(f)) continue;
    const HalfedgeRecord& r0 = first(f);
    const HalfedgeRecord& r1 = mesh.record(r0.next);
    const HalfedgeRecord& r2 = mesh.record(r1.next);
    const glm::dvec3 term = corner_term(mesh.position(r0.vertex), mesh.position(r1.vertex), mesh.position(r2.vertex));
    sums[r0.vertex.index] += term;
    sums[r1.vertex.index] += term;
    sums[r2.vertex.index] += term;
  }
}

// The term of a row's triangle, taken from its first corner as add_face_terms takes it.
glm::dvec3 row_term(const HalfedgeMesh& mesh, const TriangleRow& row) {
  const VertexId* c = row.corner;
  return corner_term(mesh.position(c[0]), mesh.position(c[1]), mesh.position(c[2]));
}

// A row whose term some of its corners take only after every run is done: bit k of `corners` for corner k.
struct SeamRow {
  uint32_t row;
  uint8_t corners;
};

// Adds the term of each triangle in rows [begin, end) (triangle_rows.h) to its three corners' sums, except to the
// corners in `seam` (none when it is null), which are listed in `deferred` instead. The rows keep neighbours
// together, so most corners are in cache already; the corners of a row a little ahead are prefetched for the rest.
void add_row_terms(const HalfedgeMesh& mesh, const TriangleRow* rows, size_t begin, size_t end, glm::dvec3* sums,
                   const uint64_t* seam, std::vector<SeamRow>* deferred) {
  constexpr size_t kAhead = 8;
  for (size_t r = begin; r < end; ++r) {
    if (r + kAhead < end) {
      for (VertexId c : rows[r + kAhead].corner) {
        memory_hints::prefetch(&mesh.position(c));
        memory_hints::prefetch(&sums[c.index]);
      }
    }
    const VertexId* c = rows[r].corner;
    const glm::dvec3 term = row_term(mesh, rows[r]);
    uint8_t on_seam = 0;
    for (int k = 0; k < 3; ++k) {
      if (seam != nullptr && vertex_bit(seam, c[k])) on_seam |= uint8_t(1u << k);
      else sums[c[k].index] += term;
    }
    if (on_seam != 0) deferred->push_back({static_cast<uint32_t>(r), on_seam});
  }
}

// Every entry of `sums` zero, `vertices` of them.
void zero_sums(std::vector<glm::dvec3>& sums, size_t vertices, int threads) {
  if (sums.size() != vertices) {
    sums.clear();
    sums.resize(vertices);  // value-initialised: zero
    return;
  }
  parallel_for(threads, vertices,
               [&](size_t begin, size_t end) { std::fill(sums.data() + begin, sums.data() + end, glm::dvec3(0.0)); });
}

// vertex_normals on a mesh proven valid with triangle faces only: the faces' terms are scattered to their corners
// in face order (walking each vertex's fan instead makes its halfedges a chain of dependent cache misses). Each vertex
// gets the same terms as vertex_normal, added in another order, so the two agree to rounding. With more threads, each
// adds its share of the faces into its own sums (the first into `normals`) and the sums are added per vertex, so the
// last bits depend on the thread count. The shares are stripes across the faces: the first faces after Loop (the old
// ids) cost about twice as much as the rest.
void face_order_normals(const HalfedgeMesh& mesh, std::vector<glm::dvec3>& normals, int threads) {
  const size_t vertices = mesh.vertex_capacity(), faces = mesh.face_capacity();
  zero_sums(normals, vertices, threads);
  std::vector<MeshArray<glm::dvec3>> extra(chunk_count(threads, faces) - 1);
  parallel_chunks(threads, faces, [&](size_t chunk, size_t, size_t) {
    if (chunk > 0) extra[chunk - 1].assign(vertices, glm::dvec3(0.0));
  });
  parallel_stripes(threads, faces, [&](size_t chunk, size_t begin, size_t end) {
    add_face_terms(mesh, begin, end, chunk == 0 ? normals.data() : extra[chunk - 1].data());
  });
  parallel_for(threads, vertices, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      glm::dvec3 sum = normals[v];
      for (const MeshArray<glm::dvec3>& more : extra) sum += more[v];
      normals[v] = unit_or_zero(sum);
    }
  });
}

// The same over the mesh's triangle rows, which list the same faces with the same first corners: the same terms
// again, added in row order, into one array of sums on any number of threads. Each thread takes one run of rows, a
// patch of the surface, so runs share few vertices (2.5 thousand of 3.2 million after three levels of Loop on a
// torus). Those (the seam, which the rows make once and keep) are left out while the runs add their terms and get
// them afterwards, run by run, each run's in row order: every vertex gets its terms in row order, so the bits do not
// depend on the thread count.
void row_order_normals(const HalfedgeMesh& mesh, const TriangleRows& rows, std::vector<glm::dvec3>& normals,
                       int threads) {
  const size_t vertices = mesh.vertex_capacity();
  zero_sums(normals, vertices, threads);
  if (chunk_count(threads, rows.size()) <= 1) {
    add_row_terms(mesh, rows.data(), 0, rows.size(), normals.data(), nullptr, nullptr);
  } else {
    const std::shared_ptr<const VertexBits> seam = rows.seam_between_runs(threads, vertices);
    std::vector<std::vector<SeamRow>> deferred(chunk_count(threads, rows.size()));
    parallel_chunks(threads, rows.size(), [&](size_t run, size_t begin, size_t end) {
      add_row_terms(mesh, rows.data(), begin, end, normals.data(), seam->data(), &deferred[run]);
    });
    for (const std::vector<SeamRow>& run : deferred) {
      for (const SeamRow& late : run) {
        const TriangleRow& row = rows[late.row];
        const glm::dvec3 term = row_term(mesh, row);
        for (int k = 0; k < 3; ++k) {
          if ((late.corners >> k) & 1u) normals[row.corner[k].index] += term;
        }
      }
    }
  }
  parallel_for(threads, vertices, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) normals[v] = unit_or_zero(normals[v]);
  });
}

}  // namespace

void vertex_normals(const HalfedgeMesh& mesh, std::vector<glm::dvec3>& normals, int threads) {
  // vertex_normal for every vertex, each triangle's term from triangle_term_from (the generic walk for anything
  // else): the same terms in the same order, so the same bits. Each face's term is taken from the vertex's own
  // halfedge, so no per-face array is needed (fresh memory costs more than the arithmetic on a big mesh).
  if (const TriangleRows* rows = mesh.triangle_rows()) {
    row_order_normals(mesh, *rows, normals, threads);
    return;
  }
  if (mesh.proven_valid_triangles()) {
    face_order_normals(mesh, normals, threads);
    return;
  }
  normals.resize(mesh.vertex_capacity());
  const auto term = [&](HalfedgeId h, glm::dvec3& out) {
    return triangle_term_from(mesh, h, out) || face_term_from(mesh, h, out);
  };
  parallel_for(threads, mesh.vertex_capacity(), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      glm::dvec3 sum;
      normals[i] =
          sum_around_vertex(mesh, VertexId(static_cast<uint32_t>(i)), term, sum) ? unit_or_zero(sum) : glm::dvec3(0.0);
    }
  });
}

std::vector<glm::dvec3> vertex_normals(const HalfedgeMesh& mesh, int threads) {
  std::vector<glm::dvec3> normals;
  vertex_normals(mesh, normals, threads);
  return normals;
}

}  // namespace meshedit
