// The local consistency checks shared by flip, split and collapse (see mesh_ops_support.h).
// Each check reads a pointer only after alive() accepted the element that holds it.
#include "core/mesh_ops_support.h"

namespace meshedit::ops_detail {
namespace {

// "h12, which is dead", "h99, which does not exist" or "not set": what is wrong with a pointer's target.
template <class IdT>
std::string bad_target(const HalfedgeMesh& mesh, IdT target) {
  const ElementRef ref(target);
  if (!ref.valid()) return "not set";
  if (ref.index >= mesh.capacity(ref.kind)) return format_id(ref) + ", which does not exist";
  return format_id(ref) + ", which is dead";
}

}  // namespace

Check check_edge(const HalfedgeMesh& mesh, EdgeId e, EdgeHalves& halves) {
  if (!e.valid()) return Check::no("no edge was given");
  if (e.index >= mesh.edge_capacity()) return Check::no(format_id(e) + " does not exist");
  if (!mesh.alive(e)) return Check::no(format_id(e) + " is dead");

  const HalfedgeId h0 = mesh.halfedge(e);
  if (!mesh.alive(h0)) return Check::no(format_id(e) + ".halfedge is " + bad_target(mesh, h0));
  if (mesh.edge(h0) != e) {
    return Check::no(format_id(e) + ".halfedge is " + format_id(h0) + ", but " + format_id(h0) + ".edge is " +
                     format_id(mesh.edge(h0)));
  }
  const HalfedgeId h1 = mesh.twin(h0);
  if (!mesh.alive(h1)) return Check::no(format_id(h0) + ".twin is " + bad_target(mesh, h1));
  if (h1 == h0) return Check::no(format_id(h0) + " is its own twin");
  if (mesh.twin(h1) != h0) {
    return Check::no(format_id(h0) + ".twin is " + format_id(h1) + ", but " + format_id(h1) + ".twin is " +
                     format_id(mesh.twin(h1)));
  }
  if (mesh.edge(h1) != e) {
    return Check::no(format_id(h1) + " is the twin of " + format_id(h0) + " but lies on " + format_id(mesh.edge(h1)) +
                     ", not " + format_id(e));
  }
  for (HalfedgeId h : {h0, h1}) {
    if (!mesh.alive(mesh.vertex(h))) return Check::no(format_id(h) + ".vertex is " + bad_target(mesh, mesh.vertex(h)));
    if (!mesh.alive(mesh.face(h))) return Check::no(format_id(h) + ".face is " + bad_target(mesh, mesh.face(h)));
  }
  if (mesh.vertex(h0) == mesh.vertex(h1)) {
    return Check::no(format_id(e) + " joins " + format_id(mesh.vertex(h0)) + " to itself");
  }
  if (mesh.face(h0) == mesh.face(h1)) {
    return Check::no(format_id(e) + " has " + format_id(mesh.face(h0)) + " on both sides");
  }
  halves = {h0, h1};
  return Check::yes();
}

Check check_triangle(const HalfedgeMesh& mesh, HalfedgeId h, const char* purpose) {
  const FaceId f = mesh.face(h);
  // Count the sides first: a quad is refused as a quad even if its pointers are fine.
  uint32_t sides = 0;
  HalfedgeId x = h, previous = h;
  for (;;) {
    if (!mesh.alive(x)) return Check::no(format_id(previous) + ".next is " + bad_target(mesh, x));
    if (mesh.face(x) != f) {
      return Check::no(format_id(x) + " is in the next-cycle of " + format_id(f) + " but its face is " +
                       format_id(mesh.face(x)));
    }
    ++sides;
    previous = x;
    x = mesh.next(x);
    if (x == h) break;
    if (sides > mesh.halfedge_capacity()) {
      return Check::no("the next-cycle of " + format_id(f) + " from " + format_id(h) + " does not come back to " +
                       format_id(h));
    }
  }
  if (sides != 3) {
    return Check::no(format_id(f) + " is not a triangle (" + std::to_string(sides) + " sides); " + purpose);
  }

  const HalfedgeId cycle[3] = {h, mesh.next(h), mesh.next(mesh.next(h))};
  for (int i = 0; i < 3; ++i) {
    const HalfedgeId y = cycle[i];
    const VertexId tail = mesh.vertex(y);
    if (!mesh.alive(tail)) return Check::no(format_id(y) + ".vertex is " + bad_target(mesh, tail));
    const HalfedgeId t = mesh.twin(y);
    if (!mesh.alive(t)) return Check::no(format_id(y) + ".twin is " + bad_target(mesh, t));
    if (t == y) return Check::no(format_id(y) + " is its own twin");
    if (mesh.twin(t) != y) {
      return Check::no(format_id(y) + ".twin is " + format_id(t) + ", but " + format_id(t) + ".twin is " +
                       format_id(mesh.twin(t)));
    }
    if (!mesh.alive(mesh.edge(y))) return Check::no(format_id(y) + ".edge is " + bad_target(mesh, mesh.edge(y)));
    if (mesh.edge(t) != mesh.edge(y)) {
      return Check::no(format_id(y) + " and its twin " + format_id(t) + " lie on different edges (" +
                       format_id(mesh.edge(y)) + ", " + format_id(mesh.edge(t)) + ")");
    }
    if (!mesh.alive(mesh.face(t))) return Check::no(format_id(t) + ".face is " + bad_target(mesh, mesh.face(t)));
    const VertexId head = mesh.vertex(cycle[(i + 1) % 3]);
    if (mesh.vertex(t) != head) {
      return Check::no(format_id(y) + " reaches " + format_id(head) + ", but its twin " + format_id(t) + " leaves " +
                       format_id(mesh.vertex(t)));
    }
  }
  const VertexId v0 = mesh.vertex(cycle[0]), v1 = mesh.vertex(cycle[1]), v2 = mesh.vertex(cycle[2]);
  if (v0 == v1 || v0 == v2) return Check::no(format_id(f) + " uses " + format_id(v0) + " twice");
  if (v1 == v2) return Check::no(format_id(f) + " uses " + format_id(v1) + " twice");
  return Check::yes();
}

Check check_loop_step(const HalfedgeMesh& mesh, HalfedgeId h, VertexId head) {
  const HalfedgeId n = mesh.next(h);
  if (!mesh.alive(n)) return Check::no(format_id(h) + ".next is " + bad_target(mesh, n));
  if (mesh.face(n) != mesh.face(h)) {
    return Check::no(format_id(h) + " is in " + format_id(mesh.face(h)) + " but its next " + format_id(n) + " is in " +
                     format_id(mesh.face(n)));
  }
  if (mesh.vertex(n) != head) {
    return Check::no(format_id(h) + " reaches " + format_id(head) + ", but its next " + format_id(n) + " leaves " +
                     format_id(mesh.vertex(n)));
  }
  return Check::yes();
}

Check broken_fan(VertexId v, HalfedgeId start, const std::string& needed_for) {
  return Check::no("the halfedges around " + format_id(v) + " do not form a closed fan (walking twin.next from " +
                   format_id(start) + "); " + needed_for);
}

}  // namespace meshedit::ops_detail
