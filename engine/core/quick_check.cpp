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

#include "core/mesh_storage.h"

namespace meshedit {
namespace {

bool clean(const HalfedgeMesh& mesh, bool loop_input) {
  const MeshStorage::ReadView r = MeshStorage::read_view(mesh);
  const size_t live = mesh.num_halfedges();

  // Halfedges: live targets, twins paired on one edge, next a permutation within one face.
  std::vector<uint8_t> is_next(r.halfedges, 0), on_edge(r.edges, 0);
  for (uint32_t h = 0; h < r.halfedges; ++h) {
    if (!r.h_alive[h]) continue;
    const HalfedgeRecord& x = r.h[h];
    if (!r.alive(x.next) || !r.alive(x.twin) || !r.alive(x.vertex) || !r.alive(x.edge) || !r.alive(x.face)) {
      return false;
    }
    if (x.twin.index == h) return false;
    const HalfedgeRecord& t = r.h[x.twin.index];
    if (t.twin.index != h || t.edge != x.edge || t.face == x.face) return false;
    if (x.face.is_boundary() && t.face.is_boundary()) return false;
    const HalfedgeRecord& n = r.h[x.next.index];
    if (n.face != x.face || t.vertex != n.vertex || x.vertex == t.vertex) return false;
    if (is_next[x.next.index]++ || on_edge[x.edge.index]++ > 1) return false;
  }
  for (uint32_t e = 0; e < r.edges; ++e) {
    if (!r.edge_alive[e]) continue;
    const HalfedgeId h = r.edge_halfedge[e];
    if (on_edge[e] != 2 || !r.alive(h) || r.h[h.index].edge.index != e) return false;
  }

  // Faces and loops: each cycle from the element's halfedge has >= 3 halfedges (exactly 3 with distinct corners
  // for Loop input), and the cycles hold every live halfedge.
  size_t in_cycles = 0;
  const auto cycle = [&](FaceId f, HalfedgeId first) {
    if (!r.alive(first) || r.h[first.index].face != f) return false;
    size_t length = 0;
    HalfedgeId h = first;
    do {
      if (++length > live) return false;
      h = r.h[h.index].next;
    } while (h != first);
    if (length < 3) return false;
    if (loop_input && !f.is_boundary()) {
      if (length != 3) return false;
      const HalfedgeRecord& a = r.h[first.index];
      const HalfedgeRecord& b = r.h[a.next.index];
      const VertexId v0 = a.vertex, v1 = b.vertex, v2 = r.h[b.next.index].vertex;
      if (v0 == v1 || v1 == v2 || v0 == v2) return false;
    }
    in_cycles += length;
    return true;
  };
  for (uint32_t f = 0; f < r.faces; ++f) {
    if (r.face_alive[f] && !cycle(FaceId::face(f), r.face_halfedge[f])) return false;
  }
  for (uint32_t b = 0; b < r.boundaries; ++b) {
    if (r.boundary_alive[b] && !cycle(FaceId::boundary(b), r.boundary_halfedge[b])) return false;
  }
  if (in_cycles != live) return false;

  // Vertices: a finite position; a fan from v.halfedge that leaves v at every step, closes, holds a face and at
  // most one boundary halfedge; and the fans hold every live halfedge.
  size_t in_fans = 0;
  for (uint32_t v = 0; v < r.vertices; ++v) {
    if (!r.vertex_alive[v]) continue;
    const glm::dvec3& p = r.position[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    const HalfedgeId first = r.vertex_halfedge[v];
    if (!r.alive(first)) return false;
    size_t length = 0, boundary = 0;
    HalfedgeId h = first;
    do {
      const HalfedgeRecord& x = r.h[h.index];
      if (x.vertex.index != v || ++length > live) return false;
      boundary += x.face.is_boundary() ? 1 : 0;
      h = r.h[x.twin.index].next;
    } while (h != first);
    if (boundary > 1 || boundary == length) return false;
    in_fans += length;
  }
  if (in_fans != live) return false;

  // Loop input: split() refuses an interior edge whose two triangles have the same third corner.
  if (loop_input) {
    for (uint32_t e = 0; e < r.edges; ++e) {
      if (!r.edge_alive[e]) continue;
      const HalfedgeRecord& a = r.h[r.edge_halfedge[e].index];
      const HalfedgeRecord& b = r.h[a.twin.index];
      if (a.face.is_boundary() || b.face.is_boundary()) continue;
      if (r.h[r.h[a.next.index].next.index].vertex == r.h[r.h[b.next.index].next.index].vertex) return false;
    }
  }
  return true;
}

}  // namespace

bool mesh_is_clean(const HalfedgeMesh& mesh) { return clean(mesh, false); }
bool loop_input_is_clean(const HalfedgeMesh& mesh) { return clean(mesh, true); }

}  // namespace meshedit
