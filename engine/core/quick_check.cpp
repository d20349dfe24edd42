// The quick sufficient checks of quick_check.h: every invariant validate.h lists (plus, for Loop input, triangles
// and split()'s conditions) tested in O(H + V + E + F) with bounded walks, stopping at the first doubt.
//
// How coverage is argued without per-element bookkeeping (so every pass only reads, and runs on several threads):
// every live halfedge's next is live and in the same face, so each face's and loop's cycle from its halfedge, once it
// closes, holds only halfedges of that face: the cycles of different faces are disjoint. Their lengths add up to the
// number of live halfedges, so they cover every live halfedge, and next, a map of the live halfedges onto themselves
// whose every element lies on a cycle, is a permutation. Twins pair halfedges on one edge, and the edge's halfedge
// is one of each pair on it, so each live edge (whose halfedge points back to it) holds exactly one pair. Each
// vertex's fan walk meets only halfedges leaving that vertex, and the fans add up to the number of live halfedges,
// so no halfedge is missed by its vertex's fan (no hourglass).
#include "core/quick_check.h"

#include <atomic>
#include <cmath>

#include "core/parallel_for.h"

namespace meshedit {
namespace {

// True when test(i, sum) holds for every i in [0, n), run on `threads` threads; `sum` adds up what the tests add
// to it (integers, so the total does not depend on the order). Every thread stops at its next index once one
// test has failed.
template <class Test>
bool all_of(int threads, size_t n, size_t& sum, Test&& test) {
  std::atomic<bool> ok{true};
  std::atomic<size_t> total{0};
  parallel_for(threads, n, [&](size_t begin, size_t end) {
    size_t block_sum = 0;
    for (size_t i = begin; i < end && ok.load(std::memory_order_relaxed); ++i) {
      if (!test(i, block_sum)) {
        ok.store(false, std::memory_order_relaxed);
        return;
      }
    }
    total.fetch_add(block_sum, std::memory_order_relaxed);
  });
  sum = total.load();
  return ok.load();
}

// Loop input beyond validity and triangles: split() refuses an interior edge whose two triangles have the same third
// corner (two faces with the same corners, which a valid mesh may hold). Reads a valid mesh only.
bool splits_cleanly(const HalfedgeMesh& m, int threads) {
  size_t unused = 0;
  return all_of(threads, m.edge_capacity(), unused, [&](size_t i, size_t&) {
    const EdgeId e(static_cast<uint32_t>(i));
    if (!m.alive(e)) return true;
    const HalfedgeId a = m.halfedge(e), b = m.twin(a);
    if (m.face(a).is_boundary() || m.face(b).is_boundary()) return true;
    return m.vertex(m.next(m.next(a))) != m.vertex(m.next(m.next(b)));
  });
}

bool clean(const HalfedgeMesh& m, bool loop_input, int threads) {
  const size_t live = m.num_halfedges();
  size_t unused = 0;

  // Halfedges: live targets, twins paired on one edge whose halfedge is one of the pair, next within one face.
  const bool halfedges_ok = all_of(threads, m.halfedge_capacity(), unused, [&](size_t i, size_t&) {
    const HalfedgeId h(static_cast<uint32_t>(i));
    if (!m.alive(h)) return true;
    const HalfedgeId next = m.next(h), twin = m.twin(h);
    const EdgeId edge = m.edge(h);
    const FaceId face = m.face(h);
    if (!m.alive(next) || !m.alive(twin) || !m.alive(m.vertex(h)) || !m.alive(edge) || !m.alive(face)) return false;
    if (twin == h || m.twin(twin) != h || m.edge(twin) != edge || m.face(twin) == face) return false;
    if (face.is_boundary() && m.face(twin).is_boundary()) return false;
    if (m.face(next) != face || m.vertex(twin) != m.vertex(next) || m.vertex(h) == m.vertex(twin)) return false;
    const HalfedgeId on_edge = m.halfedge(edge);
    return on_edge == h || on_edge == twin;
  });
  if (!halfedges_ok) return false;
  const bool edges_ok = all_of(threads, m.edge_capacity(), unused, [&](size_t i, size_t&) {
    const EdgeId e(static_cast<uint32_t>(i));
    if (!m.alive(e)) return true;
    const HalfedgeId h = m.halfedge(e);
    return m.alive(h) && m.edge(h) == e;
  });
  if (!edges_ok) return false;

  // Faces and loops: each cycle from the element's halfedge has >= 3 halfedges (exactly 3 with distinct corners
  // for Loop input), and the cycles hold every live halfedge.
  const auto cycle = [&](FaceId f, size_t& in_cycles) {
    if (!m.alive(f)) return true;
    const HalfedgeId first = m.halfedge(f);
    if (!m.alive(first) || m.face(first) != f) return false;
    size_t length = 0;
    HalfedgeId h = first;
    do {
      if (++length > live) return false;
      h = m.next(h);
    } while (h != first);
    if (length < 3) return false;
    if (loop_input && !f.is_boundary()) {
      if (length != 3) return false;
      const VertexId v0 = m.vertex(first), v1 = m.vertex(m.next(first)), v2 = m.vertex(m.next(m.next(first)));
      if (v0 == v1 || v1 == v2 || v0 == v2) return false;
    }
    in_cycles += length;
    return true;
  };
  size_t in_faces = 0, in_loops = 0;
  if (!all_of(threads, m.face_capacity(), in_faces,
              [&](size_t i, size_t& sum) { return cycle(FaceId::face(static_cast<uint32_t>(i)), sum); }) ||
      !all_of(threads, m.boundary_capacity(), in_loops,
              [&](size_t i, size_t& sum) { return cycle(FaceId::boundary(static_cast<uint32_t>(i)), sum); }) ||
      in_faces + in_loops != live) {
    return false;
  }

  // Vertices: a finite position; a fan from v.halfedge that leaves v at every step, closes, holds a face and at
  // most one boundary halfedge; and the fans hold every live halfedge.
  size_t in_fans = 0;
  const bool fans_ok = all_of(threads, m.vertex_capacity(), in_fans, [&](size_t i, size_t& sum) {
    const VertexId v(static_cast<uint32_t>(i));
    if (!m.alive(v)) return true;
    const glm::dvec3& p = m.position(v);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    const HalfedgeId first = m.halfedge(v);
    if (!m.alive(first)) return false;
    size_t length = 0, boundary = 0;
    HalfedgeId h = first;
    do {
      if (m.vertex(h) != v || ++length > live) return false;
      boundary += m.face(h).is_boundary() ? 1 : 0;
      h = m.next(m.twin(h));
    } while (h != first);
    if (boundary > 1 || boundary == length) return false;
    sum += length;
    return true;
  });
  if (!fans_ok || in_fans != live) return false;

  return !loop_input || splits_cleanly(m, threads);
}

}  // namespace

bool mesh_is_clean(const HalfedgeMesh& mesh, int threads) {
  // Vouched valid (just built or subdivided): validate() would find nothing, so nothing to walk (0.75 s at 2.5M faces
  // after L in the window, where the status bar validates every new state).
  return mesh.proven_valid_triangles() || clean(mesh, false, threads);
}
bool loop_input_is_clean(const HalfedgeMesh& mesh, int threads) {
  // A mesh vouched valid with triangle faces (just built or subdivided) needs only the split condition.
  if (mesh.proven_valid_triangles()) return splits_cleanly(mesh, threads);
  return clean(mesh, true, threads);
}

}  // namespace meshedit
