// The per-element rules of the quick validity check (quick_check.h), shared by its whole-mesh passes and by the check
// of one edit (patch_check.h). A mesh is clean when every live element passes its rule and the face cycles and the
// vertex fans each add up to the number of live halfedges (quick_check.cpp argues why that is enough).
//
// Each rule reads only the element and the elements its fields name (listed per rule), so an edit can change its
// answer only for the elements patch_check.cpp re-checks. Rules never read an array through an id before checking
// that the id is live, and walks stop after `live` steps, so they end on any mesh. The two walks expect every live
// halfedge to pass halfedge_ok already (their callers check halfedges first), so they only meet live halfedges.
#pragma once

#include <cmath>
#include <cstddef>

#include "core/halfedge_mesh.h"

namespace meshedit::clean_rules {

// A live halfedge h: next, twin, vertex, edge and face are live; twin pairs h on h's edge, in another face, with
// not both sides boundary; next is in h's face and leaves the vertex twin reaches; h's edge's halfedge is h or twin.
// Reads h, twin(h), next(h) and edge(h) (their fields), and whether vertex(h) and face(h) are live.
inline bool halfedge_ok(const HalfedgeMesh& m, HalfedgeId h) {
  const HalfedgeId next = m.next(h), twin = m.twin(h);
  const EdgeId edge = m.edge(h);
  const FaceId face = m.face(h);
  if (!m.alive(next) || !m.alive(twin) || !m.alive(m.vertex(h)) || !m.alive(edge) || !m.alive(face)) return false;
  if (twin == h || m.twin(twin) != h || m.edge(twin) != edge || m.face(twin) == face) return false;
  if (face.is_boundary() && m.face(twin).is_boundary()) return false;
  if (m.face(next) != face || m.vertex(twin) != m.vertex(next) || m.vertex(h) == m.vertex(twin)) return false;
  const HalfedgeId on_edge = m.halfedge(edge);
  return on_edge == h || on_edge == twin;
}

// A live edge e: its halfedge is live and lies on e. Reads e and halfedge(e).
inline bool edge_ok(const HalfedgeMesh& m, EdgeId e) {
  const HalfedgeId h = m.halfedge(e);
  return m.alive(h) && m.edge(h) == e;
}

// A live face or boundary loop f: the length of the next-cycle from f's halfedge, which must be live, lie in f,
// close within `live` steps and hold at least 3 halfedges (exactly 3 with distinct corners when `triangles` and f is
// a face). 0 when the rule fails. Reads f and every halfedge on the cycle.
inline size_t cycle_length(const HalfedgeMesh& m, FaceId f, size_t live, bool triangles) {
  const HalfedgeId first = m.halfedge(f);
  if (!m.alive(first) || m.face(first) != f) return 0;
  size_t length = 0;
  HalfedgeId h = first;
  do {
    if (++length > live) return 0;
    h = m.next(h);
  } while (h != first);
  if (length < 3) return 0;
  if (triangles && !f.is_boundary()) {
    if (length != 3) return 0;
    const VertexId v0 = m.vertex(first), v1 = m.vertex(m.next(first)), v2 = m.vertex(m.next(m.next(first)));
    if (v0 == v1 || v1 == v2 || v0 == v2) return 0;
  }
  return length;
}

// A live vertex v: the length of its fan (h -> next(twin(h)) from v's halfedge), which must start live, leave v at
// every step, close within `live` steps, hold a face and at most one boundary halfedge; and v's position is finite.
// 0 when the rule fails. Reads v, every halfedge on the fan and the twin of each.
inline size_t fan_length(const HalfedgeMesh& m, VertexId v, size_t live) {
  const glm::dvec3& p = m.position(v);
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0;
  const HalfedgeId first = m.halfedge(v);
  if (!m.alive(first)) return 0;
  size_t length = 0, boundary = 0;
  HalfedgeId h = first;
  do {
    if (m.vertex(h) != v || ++length > live) return 0;
    boundary += m.face(h).is_boundary() ? 1 : 0;
    h = m.next(m.twin(h));
  } while (h != first);
  if (boundary > 1 || boundary == length) return 0;
  return length;
}

}  // namespace meshedit::clean_rules
