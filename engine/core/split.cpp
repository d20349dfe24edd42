// Edge split (Part 5): the check and the rewiring, with the names, id order and post-conditions of
// mesh_ops.h.
//
// Invariants: split() writes nothing unless can_split() accepted; new elements are allocated in the order
// mesh_ops.h documents (vertex, edges, faces, halfedges) and every field of each is written; old elements
// change only where the new vertex cuts into them (h0's tail, the nexts into and out of the new halfedges,
// the faces of h3 and h4, the faces' halfedges, and a's halfedge when it was h0).
#include "core/mesh_ops.h"
#include "core/mesh_ops_support.h"
#include "core/translation.h"

namespace meshedit {

Check can_split(const HalfedgeMesh& mesh, EdgeId e) {
  ops_detail::EdgeHalves halves;
  if (Check edge_ok = ops_detail::check_edge(mesh, e, halves); !edge_ok) return edge_ok;
  if (mesh.face(halves.h0).is_boundary() && mesh.face(halves.h1).is_boundary()) {
    return Check::no(
        tr_format("{edge} has boundary loops on both sides ({loop} and {other}); there is no face to split",
                  {{"edge", format_id(e)},
                   {"loop", format_id(mesh.face(halves.h0))},
                   {"other", format_id(mesh.face(halves.h1))}}));
  }
  const auto [h0, h1] = ops_detail::face_side_first(mesh, halves);
  constexpr const char* kPurpose = "only edges of triangles can be split";
  if (Check tri = ops_detail::check_triangle(mesh, h0, kPurpose); !tri) return tri;
  if (mesh.face(h1).is_boundary()) return ops_detail::check_loop_step(mesh, h1, mesh.vertex(h0));

  if (Check tri = ops_detail::check_triangle(mesh, h1, kPurpose); !tri) return tri;
  const VertexId c = mesh.vertex(mesh.next(mesh.next(h0)));
  const VertexId d = mesh.vertex(mesh.next(mesh.next(h1)));
  if (c == d) {
    return Check::no(tr_format(
        "{face} and {other} have the same corners; splitting {edge} would join the new vertex to {vertex} twice",
        {{"face", format_id(mesh.face(h0))},
         {"other", format_id(mesh.face(h1))},
         {"edge", format_id(e)},
         {"vertex", format_id(c)}}));
  }
  return Check::yes();
}

OpResult<VertexId> split(HalfedgeMesh& mesh, EdgeId e) {
  if (Check ok = can_split(mesh, e); !ok) return {ok, VertexId()};

  const auto [h0, h1] = ops_detail::face_side_first(mesh, {mesh.halfedge(e), mesh.twin(mesh.halfedge(e))});
  const bool interior = !mesh.face(h1).is_boundary();
  const HalfedgeId h2 = mesh.next(h0), h3 = mesh.next(h2);
  const HalfedgeId h4 = mesh.next(h1);  // on a boundary edge: the loop's halfedge after h1
  const HalfedgeId h5 = interior ? mesh.next(h4) : HalfedgeId();
  const VertexId a = mesh.vertex(h0), b = mesh.vertex(h1), c = mesh.vertex(h3);
  const VertexId d = interior ? mesh.vertex(h5) : VertexId();
  const FaceId f0 = mesh.face(h0), f1 = mesh.face(h1);

  // New ids in the documented order: vertex, edges, faces, halfedges.
  const VertexId m = mesh.new_vertex((mesh.position(a) + mesh.position(b)) * 0.5);
  const EdgeId ea = mesh.new_edge();
  const EdgeId ec = mesh.new_edge();
  const EdgeId ed = interior ? mesh.new_edge() : EdgeId();
  const FaceId g0 = mesh.new_face();
  const FaceId g1 = interior ? mesh.new_face() : FaceId();
  const HalfedgeId n0 = mesh.new_halfedge();                            // a->m
  const HalfedgeId n1 = mesh.new_halfedge();                            // m->a
  const HalfedgeId n2 = mesh.new_halfedge();                            // m->c
  const HalfedgeId n3 = mesh.new_halfedge();                            // c->m
  const HalfedgeId n4 = interior ? mesh.new_halfedge() : HalfedgeId();  // m->d
  const HalfedgeId n5 = interior ? mesh.new_halfedge() : HalfedgeId();  // d->m

  // f0 = (m, b, c) and g0 = (a, m, c).
  mesh.set_neighbors(n0, n2, n1, a, ea, g0);
  mesh.set_neighbors(n2, h3, n3, m, ec, g0);
  mesh.set_neighbors(n3, h0, n2, c, ec, f0);
  mesh.set_vertex(h0, m);
  mesh.set_next(h2, n3);
  mesh.set_next(h3, n0);
  mesh.set_face(h3, g0);
  mesh.set_halfedge(f0, h0);
  mesh.set_halfedge(g0, n0);

  if (interior) {
    // f1 = (b, m, d) and g1 = (m, a, d).
    mesh.set_neighbors(n1, h4, n0, m, ea, g1);
    mesh.set_neighbors(n4, h5, n5, m, ed, f1);
    mesh.set_neighbors(n5, n1, n4, d, ed, g1);
    mesh.set_next(h1, n4);
    mesh.set_next(h4, n5);
    mesh.set_face(h4, g1);
    mesh.set_halfedge(f1, h1);
    mesh.set_halfedge(g1, n1);
    mesh.set_halfedge(ed, n4);
  } else {
    // The boundary loop: ... -> h1 (b->m) -> n1 (m->a) -> h4.
    mesh.set_neighbors(n1, h4, n0, m, ea, f1);
    mesh.set_next(h1, n1);
  }
  mesh.set_halfedge(ea, n0);
  mesh.set_halfedge(ec, n2);
  mesh.set_halfedge(m, n1);
  if (mesh.halfedge(a) == h0) mesh.set_halfedge(a, n0);  // h0 now leaves m
  return {Check::yes(), m};
}

}  // namespace meshedit
