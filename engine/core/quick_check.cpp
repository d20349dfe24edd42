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

#include "core/clean_rules.h"
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

  // Halfedges first: the walks below rely on every live halfedge passing its rule.
  const bool halfedges_ok = all_of(threads, m.halfedge_capacity(), unused, [&](size_t i, size_t&) {
    const HalfedgeId h(static_cast<uint32_t>(i));
    return !m.alive(h) || clean_rules::halfedge_ok(m, h);
  });
  if (!halfedges_ok) return false;
  const bool edges_ok = all_of(threads, m.edge_capacity(), unused, [&](size_t i, size_t&) {
    const EdgeId e(static_cast<uint32_t>(i));
    return !m.alive(e) || clean_rules::edge_ok(m, e);
  });
  if (!edges_ok) return false;

  // Faces and loops: each cycle passes its rule (triangles for Loop input), and the cycles hold every live halfedge.
  const auto cycle = [&](FaceId f, size_t& in_cycles) {
    if (!m.alive(f)) return true;
    const size_t length = clean_rules::cycle_length(m, f, live, loop_input);
    in_cycles += length;
    return length != 0;
  };
  size_t in_faces = 0, in_loops = 0;
  if (!all_of(threads, m.face_capacity(), in_faces,
              [&](size_t i, size_t& sum) { return cycle(FaceId::face(static_cast<uint32_t>(i)), sum); }) ||
      !all_of(threads, m.boundary_capacity(), in_loops,
              [&](size_t i, size_t& sum) { return cycle(FaceId::boundary(static_cast<uint32_t>(i)), sum); }) ||
      in_faces + in_loops != live) {
    return false;
  }

  // Vertices: each fan passes its rule, and the fans hold every live halfedge.
  size_t in_fans = 0;
  const bool fans_ok = all_of(threads, m.vertex_capacity(), in_fans, [&](size_t i, size_t& sum) {
    const VertexId v(static_cast<uint32_t>(i));
    if (!m.alive(v)) return true;
    const size_t length = clean_rules::fan_length(m, v, live);
    sum += length;
    return length != 0;
  });
  if (!fans_ok || in_fans != live) return false;

  return !loop_input || splits_cleanly(m, threads);
}

}  // namespace

bool mesh_is_clean(const HalfedgeMesh& mesh, int threads) {
  // Vouched valid (just built or subdivided): validate() would find nothing, so nothing to walk (a whole walk of the
  // millions of faces after L, in the window, where the status bar validates every new state).
  return mesh.proven_valid_triangles() || clean(mesh, false, threads);
}
bool loop_input_is_clean(const HalfedgeMesh& mesh, int threads) {
  // A mesh vouched valid with triangle faces (just built or subdivided) needs only the split condition.
  if (mesh.proven_valid_triangles()) return splits_cleanly(mesh, threads);
  return clean(mesh, true, threads);
}

}  // namespace meshedit
