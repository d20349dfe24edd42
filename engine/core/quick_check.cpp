// The quick sufficient checks of quick_check.h: every invariant validate.h lists (plus, for Loop input, triangles
// and split()'s conditions) tested in O(H + V + E + F) with bounded walks, stopping at the first doubt.
//
// How coverage is argued without per-element bookkeeping: every live halfedge's next is live and no halfedge is
// the next of two, so next is a permutation of the live halfedges; each face's and loop's cycle from its halfedge
// keeps its face, and the cycle lengths add up to the number of live halfedges, so every halfedge lies in its own
// face's cycle; each vertex's fan walk meets only halfedges leaving that vertex, and the fans add up to the number
// of live halfedges, so no halfedge is missed by its vertex's fan (no hourglass).
#include "core/quick_check.h"

#include <cmath>
#include <vector>


namespace meshedit {
namespace {

// Loop input beyond validity and triangles: split() refuses an interior edge whose two triangles have the same third
// corner (two faces with the same corners, which a valid mesh may hold). Reads a valid mesh only.
bool splits_cleanly(const HalfedgeMesh& m) {
  for (EdgeId e : m.edges()) {
    const HalfedgeId a = m.halfedge(e), b = m.twin(a);
    if (m.face(a).is_boundary() || m.face(b).is_boundary()) continue;
    if (m.vertex(m.next(m.next(a))) == m.vertex(m.next(m.next(b)))) return false;
  }
  return true;
}

bool clean(const HalfedgeMesh& m, bool loop_input) {
  const size_t live = m.num_halfedges();

  // Halfedges: live targets, twins paired on one edge, next a permutation within one face.
  std::vector<uint8_t> is_next(m.halfedge_capacity(), 0), on_edge(m.edge_capacity(), 0);
  for (HalfedgeId h : m.halfedges()) {
    const HalfedgeId next = m.next(h), twin = m.twin(h);
    const EdgeId edge = m.edge(h);
    const FaceId face = m.face(h);
    if (!m.alive(next) || !m.alive(twin) || !m.alive(m.vertex(h)) || !m.alive(edge) || !m.alive(face)) return false;
    if (twin == h || m.twin(twin) != h || m.edge(twin) != edge || m.face(twin) == face) return false;
    if (face.is_boundary() && m.face(twin).is_boundary()) return false;
    if (m.face(next) != face || m.vertex(twin) != m.vertex(next) || m.vertex(h) == m.vertex(twin)) return false;
    if (is_next[next.index]++ || on_edge[edge.index]++ > 1) return false;
  }
  for (EdgeId e : m.edges()) {
    const HalfedgeId h = m.halfedge(e);
    if (on_edge[e.index] != 2 || !m.alive(h) || m.edge(h) != e) return false;
  }

  // Faces and loops: each cycle from the element's halfedge has >= 3 halfedges (exactly 3 with distinct corners
  // for Loop input), and the cycles hold every live halfedge.
  size_t in_cycles = 0;
  const auto cycle = [&](FaceId f) {
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
  for (FaceId f : m.faces()) {
    if (!cycle(f)) return false;
  }
  for (FaceId b : m.boundaries()) {
    if (!cycle(b)) return false;
  }
  if (in_cycles != live) return false;

  // Vertices: a finite position; a fan from v.halfedge that leaves v at every step, closes, holds a face and at
  // most one boundary halfedge; and the fans hold every live halfedge.
  size_t in_fans = 0;
  for (VertexId v : m.vertices()) {
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
    in_fans += length;
  }
  if (in_fans != live) return false;

  return !loop_input || splits_cleanly(m);
}

}  // namespace

bool mesh_is_clean(const HalfedgeMesh& mesh) {
  // Vouched valid (just built or subdivided): validate() would find nothing, so nothing to walk (0.75 s at 2.5M faces
  // after L in the window, where the status bar validates every new state).
  return mesh.proven_valid_triangles() || clean(mesh, false);
}
bool loop_input_is_clean(const HalfedgeMesh& mesh) {
  // A mesh vouched valid with triangle faces (just built or subdivided) needs only the split condition.
  if (mesh.proven_valid_triangles()) return splits_cleanly(mesh);
  return clean(mesh, true);
}

}  // namespace meshedit
