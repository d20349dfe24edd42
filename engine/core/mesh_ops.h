// Local operations on triangle meshes (flip, split and collapse, each with its check) and the invariants they all keep:
// - can_X(mesh, e) only reads the mesh, follows no pointer before checking that its target is in range and alive,
//   and walks only with bounds, so a mesh a script has broken is refused with a reason rather than crashing or
//   hanging. The reason is a sentence naming the elements with format_id: "e5 is on the boundary (b0); only interior
//   edges can be flipped", "f3 is not a triangle (4 sides); ...", "e7 is dead".
// - X(mesh, e) runs can_X first. A refused operation changes nothing at all, not even version().
// - On a mesh validate() accepts, an accepted operation gives a mesh validate() accepts: every pointer into a
//   deleted element is redirected (the lists below say where), and a boundary vertex's halfedge is still its
//   outgoing boundary halfedge (the convention of halfedge_mesh.h).
// - Deleted elements are only marked dead (delete_element); their slots and stored pointers keep their last
//   values, so pointer tables and history can still show them. New ids are appended, never reused.
//
// Names used below. For an edge e, h0 is the halfedge of e the operation works from and h1 = h0.twin;
// a = h0.vertex, b = h1.vertex, so h0 runs a->b and h1 runs b->a. f0 = h0.face holds the triangle (a, b, c)
// as h0 (a->b), h2 = h0.next (b->c), h3 = h2.next (c->a). When f1 = h1.face is a face (not a boundary loop)
// it holds (b, a, d) as h1 (b->a), h4 = h1.next (a->d), h5 = h4.next (d->b). Faces are counter-clockwise
// seen from the side their normals point to; every picture is drawn from that side:
/*
                 c
                / \
            h3 /   \ h2
              /  f0 \
             /  h0-> \
            a ------- b
             \ <-h1  /
            h4\  f1 / h5
               \   /
                \ /
                 d
*/
#pragma once

#include "core/check.h"
#include "core/halfedge_mesh.h"

namespace meshedit {

// ---- flip -------------------------------------------------------------------------------------------
// h0 = e.halfedge. The edge turns counter-clockwise inside the quad a, d, b, c: each end moves one corner
// forward along the quad (a to d, b to c), so a-b becomes d-c.
//
/*
                 c                                  c
                / \                                /|\
            h3 /   \ h2                        h3 / | \ h2
              /  f0 \                            /  |  \
             /  h0-> \                          / f0|f1 \
            a ------- b          flip(e)       a   |   b       h0 runs d->c (left of the new edge, in f0),
             \ <-h1  /          -------->       \  |  /        h1 runs c->d (right of it, in f1)
            h4\  f1 / h5                       h4\ | / h5
               \   /                              \|/
                \ /                                |
                 d                                  d
*/
//
// Afterwards (no element is created or deleted; twins, edges and e.halfedge = h0 are unchanged):
//   f0 = (d, c, a): h0 d->c, h3 c->a, h4 a->d   h0.next = h3, h3.next = h4, h4.next = h0, f0.halfedge = h0
//   f1 = (c, d, b): h1 c->d, h5 d->b, h2 b->c   h1.next = h5, h5.next = h2, h2.next = h1, f1.halfedge = h1
//   h0.vertex = d, h1.vertex = c; h4.face = f0 and h2.face = f1 (the two halfedges that change faces);
//   a.halfedge = h4 if it was h0, b.halfedge = h2 if it was h1; c and d keep theirs.
// Flipping the same edge again (the convention is what makes these hold, and tests assert them):
//   twice: e joins a and b again with h0 running b->a; f0 holds (b, a, d) as h0, h4, h5 and f1 holds (a, b, c)
//          as h1, h2, h3 — the same halfedges per triangle, the two faces' triangles swapped;
//   four times: every halfedge pointer is back where it started; f0.halfedge = h0, f1.halfedge = h1, and
//          a.halfedge, b.halfedge stay as the first flip left them.
// Refused: a dead or inconsistent edge; a boundary edge; a non-triangle beside e; c == d; and c, d already
// joined by an edge (the flip would duplicate it — on a tetrahedron every flip is refused for this reason).
Check can_flip(const HalfedgeMesh& mesh, EdgeId e);
// Returns e (flip keeps every id).
OpResult<EdgeId> flip(HalfedgeMesh& mesh, EdgeId e);

// ---- split ------------------------------------------------------------------------------------------
// h0 is e's halfedge inside a face: e.halfedge, or its twin when e.halfedge lies on a boundary loop. A new
// vertex m goes to the exact midpoint (a + b) * 0.5 and is joined to c (and to d): e keeps its id as the half
// m-b, the half a-m is a new edge.
//
/*
                 c                                    c
                / \                                 / | \
            h3 /   \ h2                         h3 /  |  \ h2
              /  f0 \                             / g0 | f0\
             /  h0-> \          split(e)         /   ec|   \
            a ------- b        --------->       a ---- m ---- b      a-m is ea, m-b is e
             \ <-h1  /                           \   ed|   /
            h4\  f1 / h5                       h4 \ g1 | f1/ h5
               \   /                               \  |  /
                \ /                                 \ | /
                 d                                    d
*/
//
// New ids, allocated in this order, each appended after the existing ids of its kind:
//   vertex     m
//   edges      ea = a-m, ec = m-c, ed = m-d                          (ed only when f1 is a face)
//   faces      g0 = (a, m, c), g1 = (m, a, d)                        (g1 only when f1 is a face)
//   halfedges  n0 a->m, n1 m->a, n2 m->c, n3 c->m, n4 m->d, n5 d->m   (n4, n5 only when f1 is a face)
// Pointers afterwards:
//   h0.vertex = m (h0 runs m->b), h1 runs b->m; e.halfedge is unchanged. Twins: h0/h1, n0/n1, n2/n3, n4/n5;
//   ea.halfedge = n0, ec.halfedge = n2, ed.halfedge = n4.
//   Face cycles, each face's halfedge listed first:
//     f0 = (m, b, c): h0 -> h2 -> n3        g0 = (a, m, c): n0 -> n2 -> h3
//     f1 = (b, m, d): h1 -> n4 -> h5        g1 = (m, a, d): n1 -> h4 -> n5
//   Boundary edge (f1 is a boundary loop): only f0 is split; the loop gains n1 after h1:
//     ... -> h1 (b->m) -> n1 (m->a) -> (h1's old next); the loop's halfedge is unchanged.
//   m.halfedge = n1: it leaves m along the half a-m of the split edge, toward a. On a boundary edge n1 lies
//   on the boundary loop, as the boundary-vertex convention requires.
//   a.halfedge = n0 if it was h0; b, c and d keep theirs.
// Counts: interior edge +1 vertex, +3 edges, +2 faces, +6 halfedges; boundary edge +1, +2, +1, +4.
// Refused: a dead or inconsistent edge; a non-triangle face beside e; boundary loops on both sides of e;
// two triangles with the same three corners (c == d; the split would join m to c twice).
Check can_split(const HalfedgeMesh& mesh, EdgeId e);
// Returns the new vertex m.
OpResult<VertexId> split(HalfedgeMesh& mesh, EdgeId e);

// ---- collapse ---------------------------------------------------------------------------------------
// h0 as for split: e's halfedge inside a face. b merges into a: a survives, moves to the exact midpoint
// (a + b) * 0.5 and is returned; the triangles beside e vanish, and of each one's two other edges the one
// that touched b vanishes with it.
//
/*
                 c                                c
                / \                               |
            h3 /   \ h2                        t2 | t3       (edge e3)
              /  f0 \                             |
             /  h0-> \        collapse(e)         |
            a ------- b       ----------->        a  (at the midpoint of a and b)
             \ <-h1  /                            |
            h4\  f1 / h5                       t4 | t5       (edge e4)
               \   /                              |
                \ /                               |
                 d                                d
*/
//
// With t2 = h2.twin (c->b), t3 = h3.twin (a->c), t4 = h4.twin (d->a), t5 = h5.twin (b->d), e2 = h2.edge,
// e3 = h3.edge, e4 = h4.edge, e5 = h5.edge:
//   deleted: b, e, f0, h0, h1, h2, h3, e2; and when f1 is a face also f1, h4, h5, e5.
//   kept edges: e3 (c-a) now has halfedges t3 (a->c) and t2 (c->a); e4 (a-d) has t4 (d->a) and t5 (a->d).
//   Every live halfedge that left b now leaves a. t2.twin = t3, t3.twin = t2, t2.edge = e3;
//   t4.twin = t5, t5.twin = t4, t5.edge = e4 (the dead halfedges' own fields are left as they were).
//   Pointers into dead elements move to the halfedge that took the dead one's place:
//     e3.halfedge = t2 if it was h3, e4.halfedge = t5 if it was h4, c.halfedge = t2 if it was h3,
//     d.halfedge = t4 if it was h5;
//     boundary edge (f1 is a boundary loop): the halfedge before h1 in the loop gets next = h1's old next,
//     and the loop's halfedge becomes h1's old next if it was h1.
//   a.halfedge: a's outgoing boundary halfedge if a is on a boundary afterwards; otherwise t3 if it was h0,
//   t5 if it was h4, else unchanged.
// Counts: interior edge -1 vertex, -3 edges, -2 faces, -6 halfedges; boundary edge -1, -2, -1, -4.
// Refused (besides a dead or inconsistent edge, boundary loops on both sides, a non-triangle beside e, c == d,
// or a fan around a or b that does not close) when the result would not be a manifold surface:
//   - link condition: a and b have a common neighbour other than c (and d) — it would be joined twice;
//   - e is interior but a and b are both on the boundary — the surface would pinch at the merged vertex;
//   - a face other than f0 and f1 has both a and b as corners — it would use the merged vertex twice;
//   - e is interior and a face beside a and one beside b (not f0, f1) both have c and d as corners — on a
//     tetrahedron the two would fold onto each other, leaving a closed "mesh" of 3 vertices;
//   - e is a boundary edge and f0's other two edges are on the boundary too (a lone triangle).
Check can_collapse(const HalfedgeMesh& mesh, EdgeId e);
// Returns the surviving vertex a, moved to the midpoint of e.
OpResult<VertexId> collapse(HalfedgeMesh& mesh, EdgeId e);

}  // namespace meshedit
