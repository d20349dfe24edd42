// Edge collapse: the check (the link condition, read on the half-edge structure) and the rewiring, with
// the names and post-conditions of mesh_ops.h.
//
// The link condition, with the boundary treated as a virtual vertex joined to every boundary vertex of its
// loop: the collapse of a-b keeps a manifold iff the vertices and edges a's and b's links share are exactly
// the link of a-b. Shared vertices other than c, d are a common neighbour (or, for an interior edge, both
// ends on the boundary); shared edges are c-d seen from both sides (a tetrahedron) or, for a boundary edge,
// c's two boundary edges (a lone triangle). can_collapse checks each, plus faces that hold both a and b
// (possible only with polygons), which the link of a triangle mesh does not cover.
//
// Invariants: collapse() writes nothing unless can_collapse() accepted; it deletes only what mesh_ops.h
// lists, writes no field of a deleted element, and redirects every live pointer into a deleted element.
#include <algorithm>
#include <string>
#include <vector>

#include "core/mesh_ops.h"
#include "core/mesh_ops_support.h"
#include "core/translation.h"

namespace meshedit {

namespace {

// What can_collapse learns about one endpoint by walking its fan.
struct EndpointFan {
  std::vector<VertexId> neighbours;  // sorted
  bool on_boundary = false;
  FaceId face_with_other;  // a face other than f0, f1 with the other endpoint as a corner
  FaceId face_with_cd;     // a face other than f0, f1 with both c and d as corners
};

// "collapsing e3 needs the faces around it": the end of a refusal of read_fan's (made only when it refuses).
std::string needs_faces(EdgeId e) {
  return tr_format("collapsing {edge} needs the faces around it", {{"edge", format_id(e)}});
}

// Walks the fan of vertex(start) and the corners of each face in it, both bounded; refuses if either breaks (for
// the collapse of e).
Check read_fan(const HalfedgeMesh& mesh, HalfedgeId start, FaceId f0, FaceId f1, VertexId other, VertexId c, VertexId d,
               EdgeId e, EndpointFan& out) {
  FaceId broken_face;
  const bool closed = ops_detail::walk_fan(mesh, start, [&](HalfedgeId o) {
    out.neighbours.push_back(mesh.vertex(mesh.twin(o)));
    const FaceId f = mesh.face(o);
    if (f.is_boundary()) {
      out.on_boundary = true;
      return;
    }
    if (f == f0 || f == f1 || broken_face.valid()) return;
    bool has_other = false, has_c = false, has_d = false;
    const bool cycle_ok = mesh.for_each_face_halfedge(f, [&](HalfedgeId x) {
      const VertexId v = mesh.vertex(x);
      has_other = has_other || v == other;
      has_c = has_c || v == c;
      has_d = has_d || (d.valid() && v == d);
    });
    if (!cycle_ok) broken_face = f;
    if (has_other && !out.face_with_other.valid()) out.face_with_other = f;
    if (has_c && has_d && !out.face_with_cd.valid()) out.face_with_cd = f;
  });
  if (!closed) return ops_detail::broken_fan(mesh.vertex(start), start, needs_faces(e));
  if (broken_face.valid()) {
    return Check::no(tr_format(
        "the next-cycle of {face} (beside {vertex}) does not close; {needed_for}",
        {{"face", format_id(broken_face)}, {"vertex", format_id(mesh.vertex(start))}, {"needed_for", needs_faces(e)}}));
  }
  std::sort(out.neighbours.begin(), out.neighbours.end());
  return Check::yes();
}

// The corners around an edge to collapse, as can_collapse reads them (d: none on a boundary edge).
struct CollapseCorners {
  EdgeId e;
  bool interior = false;
  VertexId a, b, c, d;
  FaceId f0;
  HalfedgeId h2, h3;
};

// What merging the two fans would break: a pinch, a vertex joined twice, a face using the vertex twice, a fold.
Check check_merged_fans(const HalfedgeMesh& mesh, const CollapseCorners& q, const EndpointFan& fan_a,
                        const EndpointFan& fan_b) {
  const EdgeId e = q.e;
  const bool interior = q.interior;
  const VertexId a = q.a, b = q.b, c = q.c, d = q.d;
  const FaceId f0 = q.f0;
  const HalfedgeId h2 = q.h2, h3 = q.h3;
  if (interior && fan_a.on_boundary && fan_b.on_boundary) {
    return Check::no(tr_format(
        "{a} and {b} are both on the boundary but {edge} is not; collapsing it would pinch the surface at the merged "
        "vertex",
        {{"a", format_id(a)}, {"b", format_id(b)}, {"edge", format_id(e)}}));
  }
  std::vector<VertexId> common;
  std::set_intersection(fan_a.neighbours.begin(), fan_a.neighbours.end(), fan_b.neighbours.begin(),
                        fan_b.neighbours.end(), std::back_inserter(common));
  for (VertexId v : common) {
    if (v == c || v == d) continue;
    const MessageParts parts = {{"a", format_id(a)}, {"b", format_id(b)}, {"vertex", format_id(v)},
                                {"c", format_id(c)}, {"d", format_id(d)}, {"edge", format_id(e)}};
    return Check::no(interior ? tr_format("{a} and {b} are both joined to {vertex} (besides {c} and {d}); collapsing "
                                          "{edge} would join the merged vertex to {vertex} twice",
                                          parts)
                              : tr_format("{a} and {b} are both joined to {vertex} (besides {c}); collapsing {edge} "
                                          "would join the merged vertex to {vertex} twice",
                                          parts));
  }
  for (const EndpointFan* fan : {&fan_a, &fan_b}) {
    if (fan->face_with_other.valid()) {
      return Check::no(tr_format(
          "{face} has both {a} and {b} as corners; collapsing {edge} would make it use the merged vertex twice",
          {{"face", format_id(fan->face_with_other)},
           {"a", format_id(a)},
           {"b", format_id(b)},
           {"edge", format_id(e)}}));
    }
  }
  if (interior && fan_a.face_with_cd.valid() && fan_b.face_with_cd.valid()) {
    return Check::no(tr_format(
        "collapsing {edge} would fold {face} onto {other} (both would join the merged vertex, {c} and {d}): a closed "
        "surface needs at least 4 vertices",
        {{"edge", format_id(e)},
         {"face", format_id(fan_a.face_with_cd)},
         {"other", format_id(fan_b.face_with_cd)},
         {"c", format_id(c)},
         {"d", format_id(d)}}));
  }
  if (!interior && mesh.face(mesh.twin(h2)).is_boundary() && mesh.face(mesh.twin(h3)).is_boundary()) {
    return Check::no(tr_format(
        "{face} is a lone triangle (all its edges are on the boundary); collapsing {edge} would leave no face",
        {{"face", format_id(f0)}, {"edge", format_id(e)}}));
  }
  return Check::yes();
}

}  // namespace

Check can_collapse(const HalfedgeMesh& mesh, EdgeId e) {
  ops_detail::EdgeHalves halves;
  if (Check edge_ok = ops_detail::check_edge(mesh, e, halves); !edge_ok) return edge_ok;
  if (mesh.face(halves.h0).is_boundary() && mesh.face(halves.h1).is_boundary()) {
    return Check::no(
        tr_format("{edge} has boundary loops on both sides ({loop} and {other}); there is no face to collapse",
                  {{"edge", format_id(e)},
                   {"loop", format_id(mesh.face(halves.h0))},
                   {"other", format_id(mesh.face(halves.h1))}}));
  }
  const auto [h0, h1] = ops_detail::face_side_first(mesh, halves);
  const bool interior = !mesh.face(h1).is_boundary();
  constexpr const char* kPurpose = "only edges between triangles can be collapsed";
  if (Check tri = ops_detail::check_triangle(mesh, h0, kPurpose); !tri) return tri;
  if (interior) {
    if (Check tri = ops_detail::check_triangle(mesh, h1, kPurpose); !tri) return tri;
  } else if (Check step = ops_detail::check_loop_step(mesh, h1, mesh.vertex(h0)); !step) {
    return step;
  }

  const FaceId f0 = mesh.face(h0), f1 = mesh.face(h1);
  const VertexId a = mesh.vertex(h0), b = mesh.vertex(h1);
  const HalfedgeId h2 = mesh.next(h0), h3 = mesh.next(h2);
  const VertexId c = mesh.vertex(h3);
  const VertexId d = interior ? mesh.vertex(mesh.next(mesh.next(h1))) : VertexId();
  if (interior && c == d) {
    return Check::no(
        tr_format("{face} and {other} have the same corners; collapsing {edge} would leave nothing between them",
                  {{"face", format_id(f0)}, {"other", format_id(f1)}, {"edge", format_id(e)}}));
  }

  EndpointFan fan_a, fan_b;
  if (Check fan = read_fan(mesh, h0, f0, f1, b, c, d, e, fan_a); !fan) return fan;
  if (Check fan = read_fan(mesh, h1, f0, f1, a, c, d, e, fan_b); !fan) return fan;

  return check_merged_fans(mesh, {e, interior, a, b, c, d, f0, h2, h3}, fan_a, fan_b);
}

OpResult<VertexId> collapse(HalfedgeMesh& mesh, EdgeId e) {
  if (Check ok = can_collapse(mesh, e); !ok) return {ok, VertexId()};

  const auto [h0, h1] = ops_detail::face_side_first(mesh, {mesh.halfedge(e), mesh.twin(mesh.halfedge(e))});
  const bool interior = !mesh.face(h1).is_boundary();
  const FaceId f0 = mesh.face(h0), f1 = mesh.face(h1);
  const VertexId a = mesh.vertex(h0), b = mesh.vertex(h1);
  const HalfedgeId h2 = mesh.next(h0), h3 = mesh.next(h2);
  const HalfedgeId t2 = mesh.twin(h2), t3 = mesh.twin(h3);
  const EdgeId e2 = mesh.edge(h2), e3 = mesh.edge(h3);
  const VertexId c = mesh.vertex(h3);
  const HalfedgeId h4 = mesh.next(h1);  // on a boundary edge: the loop's halfedge after h1
  const HalfedgeId h5 = interior ? mesh.next(h4) : HalfedgeId();
  const glm::dvec3 midpoint = (mesh.position(a) + mesh.position(b)) * 0.5;

  // b's outgoing halfedges, read before anything moves (the walk starts at h1, then h2). The last one's twin
  // is the halfedge before h1 in h1's face cycle.
  std::vector<HalfedgeId> from_b;
  ops_detail::walk_fan(mesh, h1, [&](HalfedgeId o) { from_b.push_back(o); });
  const HalfedgeId before_h1 = mesh.twin(from_b.back());
  for (HalfedgeId o : from_b) {
    if (o != h1 && o != h2) mesh.set_vertex(o, a);
  }

  // Glue the two outer edges of f0: t2 (c->a) takes h3's place as t3's twin, on e3.
  mesh.set_twin(t2, t3);
  mesh.set_twin(t3, t2);
  mesh.set_edge(t2, e3);
  if (mesh.halfedge(e3) == h3) mesh.set_halfedge(e3, t2);
  if (mesh.halfedge(c) == h3) mesh.set_halfedge(c, t2);

  if (interior) {
    // Same for f1: t5 (a->d) takes h4's place as t4's twin, on e4.
    const HalfedgeId t4 = mesh.twin(h4), t5 = mesh.twin(h5);
    const EdgeId e4 = mesh.edge(h4), e5 = mesh.edge(h5);
    const VertexId d = mesh.vertex(h5);
    mesh.set_twin(t4, t5);
    mesh.set_twin(t5, t4);
    mesh.set_edge(t5, e4);
    if (mesh.halfedge(e4) == h4) mesh.set_halfedge(e4, t5);
    if (mesh.halfedge(d) == h5) mesh.set_halfedge(d, t4);
    if (mesh.halfedge(a) == h4) mesh.set_halfedge(a, t5);
    mesh.delete_element(h4);
    mesh.delete_element(h5);
    mesh.delete_element(e5);
    mesh.delete_element(f1);
  } else {
    // Take h1 out of its boundary loop.
    mesh.set_next(before_h1, h4);
    if (mesh.halfedge(f1) == h1) mesh.set_halfedge(f1, h4);
  }
  if (mesh.halfedge(a) == h0) mesh.set_halfedge(a, t3);
  mesh.set_position(a, midpoint);

  mesh.delete_element(h0);
  mesh.delete_element(h1);
  mesh.delete_element(h2);
  mesh.delete_element(h3);
  mesh.delete_element(e2);
  mesh.delete_element(e);
  mesh.delete_element(f0);
  mesh.delete_element(b);

  // The merged vertex is on a boundary if b was: keep the convention that its halfedge is the boundary one.
  HalfedgeId boundary_out;
  ops_detail::walk_fan(mesh, t3, [&](HalfedgeId o) {
    if (!boundary_out.valid() && mesh.face(o).is_boundary()) boundary_out = o;
  });
  if (boundary_out.valid() && mesh.halfedge(a) != boundary_out) mesh.set_halfedge(a, boundary_out);
  return {Check::yes(), a};
}

}  // namespace meshedit
