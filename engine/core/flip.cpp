// Edge flip (Part 4): the check and the rewiring, with the names and post-conditions of mesh_ops.h.
//
// Invariants: flip() writes nothing unless can_flip() accepted; it creates and deletes nothing, so every id
// keeps its meaning; it touches only the six halfedges of the two triangles, the two faces, and the
// halfedge of a or b when that one moved away from its vertex.
#include "core/mesh_ops.h"
#include "core/mesh_ops_support.h"
#include "core/translation.h"

namespace meshedit {

Check can_flip(const HalfedgeMesh& mesh, EdgeId e) {
  ops_detail::EdgeHalves halves;
  if (Check edge_ok = ops_detail::check_edge(mesh, e, halves); !edge_ok) return edge_ok;
  const HalfedgeId h0 = halves.h0, h1 = halves.h1;
  for (HalfedgeId h : {h0, h1}) {
    if (mesh.face(h).is_boundary()) {
      return Check::no(tr_format("{edge} is on the boundary ({loop}); only interior edges can be flipped",
                                 {{"edge", format_id(e)}, {"loop", format_id(mesh.face(h))}}));
    }
  }
  constexpr const char* kPurpose = "only edges between two triangles can be flipped";
  for (HalfedgeId h : {h0, h1}) {
    if (Check tri = ops_detail::check_triangle(mesh, h, kPurpose); !tri) return tri;
  }

  const HalfedgeId h3 = mesh.next(mesh.next(h0));
  const HalfedgeId h5 = mesh.next(mesh.next(h1));
  const VertexId c = mesh.vertex(h3), d = mesh.vertex(h5);
  if (c == d) {
    return Check::no(
        tr_format("{face} and {other} have the same corners; flipping {edge} would join {vertex} to itself",
                  {{"face", format_id(mesh.face(h0))},
                   {"other", format_id(mesh.face(h1))},
                   {"edge", format_id(e)},
                   {"vertex", format_id(c)}}));
  }
  // The flip would create c-d; if c already has a neighbour d, the mesh would hold two c-d edges.
  EdgeId existing;
  const bool closed = ops_detail::walk_fan(mesh, h3, [&](HalfedgeId o) {
    if (mesh.vertex(mesh.twin(o)) == d) existing = mesh.edge(o);
  });
  if (!closed) {
    const MessageParts parts = {{"edge", format_id(e)}, {"vertex", format_id(c)}};
    return ops_detail::broken_fan(c, h3, tr_format("flipping {edge} needs {vertex}'s neighbours", parts));
  }
  if (existing.valid()) {
    return Check::no(tr_format(
        "flipping {edge} would join {c} and {d}, which are already joined by {existing}",
        {{"edge", format_id(e)}, {"c", format_id(c)}, {"d", format_id(d)}, {"existing", format_id(existing)}}));
  }
  return Check::yes();
}

OpResult<EdgeId> flip(HalfedgeMesh& mesh, EdgeId e) {
  if (Check ok = can_flip(mesh, e); !ok) return {ok, EdgeId()};

  const HalfedgeId h0 = mesh.halfedge(e), h1 = mesh.twin(h0);
  const HalfedgeId h2 = mesh.next(h0), h3 = mesh.next(h2);
  const HalfedgeId h4 = mesh.next(h1), h5 = mesh.next(h4);
  const VertexId a = mesh.vertex(h0), b = mesh.vertex(h1);
  const VertexId c = mesh.vertex(h3), d = mesh.vertex(h5);
  const FaceId f0 = mesh.face(h0), f1 = mesh.face(h1);

  // f0 = (d, c, a)
  mesh.set_vertex(h0, d);
  mesh.set_next(h0, h3);
  mesh.set_next(h3, h4);
  mesh.set_next(h4, h0);
  mesh.set_face(h4, f0);
  mesh.set_halfedge(f0, h0);
  // f1 = (c, d, b)
  mesh.set_vertex(h1, c);
  mesh.set_next(h1, h5);
  mesh.set_next(h5, h2);
  mesh.set_next(h2, h1);
  mesh.set_face(h2, f1);
  mesh.set_halfedge(f1, h1);
  // h0 no longer leaves a, h1 no longer leaves b.
  if (mesh.halfedge(a) == h0) mesh.set_halfedge(a, h4);
  if (mesh.halfedge(b) == h1) mesh.set_halfedge(b, h2);
  return {Check::yes(), e};
}

}  // namespace meshedit
