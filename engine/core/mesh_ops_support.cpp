// The local consistency checks shared by flip, split and collapse (see mesh_ops_support.h).
// Each check reads a pointer only after alive() accepted the element that holds it.
#include "core/mesh_ops_support.h"

#include "core/translation.h"

namespace meshedit::ops_detail {
namespace {

// "h12, which is dead", "h99, which does not exist" or "not set": what is wrong with a pointer's target.
template <class IdT>
std::string bad_target(const HalfedgeMesh& mesh, IdT target) {
  const ElementRef ref(target);
  if (!ref.valid()) return tr("not set");
  if (ref.index >= mesh.capacity(ref.kind)) {
    return tr_format("{element}, which does not exist", {{"element", format_id(ref)}});
  }
  return tr_format("{element}, which is dead", {{"element", format_id(ref)}});
}

// "h3.twin is h12, which is dead": `element`'s `field` points to what bad_target describes.
template <class IdT>
Check bad_pointer(const HalfedgeMesh& mesh, ElementRef element, const char* field, IdT target) {
  const MessageParts parts = {{"element", format_id(element)}, {"field", field}, {"target", bad_target(mesh, target)}};
  return Check::no(tr_format("{element}.{field} is {target}", parts));
}

// "h3.twin is h7, but h7.twin is h9": a twin pointer that does not come back.
Check unpaired_twin(const HalfedgeMesh& mesh, HalfedgeId h, HalfedgeId t) {
  return Check::no(tr_format("{halfedge}.twin is {twin}, but {twin}.twin is {other}",
                             {{"halfedge", format_id(h)}, {"twin", format_id(t)}, {"other", format_id(mesh.twin(t))}}));
}

}  // namespace

Check check_edge(const HalfedgeMesh& mesh, EdgeId e, EdgeHalves& halves) {
  if (!e.valid()) return Check::no(tr("no edge was given"));
  if (e.index >= mesh.edge_capacity()) return Check::no(tr_format("{edge} does not exist", {{"edge", format_id(e)}}));
  if (!mesh.alive(e)) return Check::no(tr_format("{edge} is dead", {{"edge", format_id(e)}}));

  const HalfedgeId h0 = mesh.halfedge(e);
  if (!mesh.alive(h0)) return bad_pointer(mesh, e, "halfedge", h0);
  if (mesh.edge(h0) != e) {
    return Check::no(
        tr_format("{edge}.halfedge is {halfedge}, but {halfedge}.edge is {other}",
                  {{"edge", format_id(e)}, {"halfedge", format_id(h0)}, {"other", format_id(mesh.edge(h0))}}));
  }
  const HalfedgeId h1 = mesh.twin(h0);
  if (!mesh.alive(h1)) return bad_pointer(mesh, h0, "twin", h1);
  if (h1 == h0) return Check::no(tr_format("{halfedge} is its own twin", {{"halfedge", format_id(h0)}}));
  if (mesh.twin(h1) != h0) return unpaired_twin(mesh, h0, h1);
  if (mesh.edge(h1) != e) {
    return Check::no(tr_format("{twin} is the twin of {halfedge} but lies on {other}, not {edge}",
                               {{"twin", format_id(h1)},
                                {"halfedge", format_id(h0)},
                                {"other", format_id(mesh.edge(h1))},
                                {"edge", format_id(e)}}));
  }
  for (HalfedgeId h : {h0, h1}) {
    if (!mesh.alive(mesh.vertex(h))) return bad_pointer(mesh, h, "vertex", mesh.vertex(h));
    if (!mesh.alive(mesh.face(h))) return bad_pointer(mesh, h, "face", mesh.face(h));
  }
  if (mesh.vertex(h0) == mesh.vertex(h1)) {
    return Check::no(
        tr_format("{edge} joins {vertex} to itself", {{"edge", format_id(e)}, {"vertex", format_id(mesh.vertex(h0))}}));
  }
  if (mesh.face(h0) == mesh.face(h1)) {
    return Check::no(
        tr_format("{edge} has {face} on both sides", {{"edge", format_id(e)}, {"face", format_id(mesh.face(h0))}}));
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
    if (!mesh.alive(x)) return bad_pointer(mesh, previous, "next", x);
    if (mesh.face(x) != f) {
      return Check::no(
          tr_format("{halfedge} is in the next-cycle of {face} but its face is {other}",
                    {{"halfedge", format_id(x)}, {"face", format_id(f)}, {"other", format_id(mesh.face(x))}}));
    }
    ++sides;
    previous = x;
    x = mesh.next(x);
    if (x == h) break;
    if (sides > mesh.halfedge_capacity()) {
      return Check::no(tr_format("the next-cycle of {face} from {halfedge} does not come back to {halfedge}",
                                 {{"face", format_id(f)}, {"halfedge", format_id(h)}}));
    }
  }
  if (sides != 3) {  // "sides" whatever the count (a cycle of 1 reads "1 sides" too)
    return Check::no(tr_format("{face} is not a triangle ({count} sides); {purpose}",
                               {{"face", format_id(f)}, {"count", std::to_string(sides)}, {"purpose", tr(purpose)}}));
  }

  const HalfedgeId cycle[3] = {h, mesh.next(h), mesh.next(mesh.next(h))};
  for (int i = 0; i < 3; ++i) {
    const HalfedgeId y = cycle[i];
    const VertexId tail = mesh.vertex(y);
    if (!mesh.alive(tail)) return bad_pointer(mesh, y, "vertex", tail);
    const HalfedgeId t = mesh.twin(y);
    if (!mesh.alive(t)) return bad_pointer(mesh, y, "twin", t);
    if (t == y) return Check::no(tr_format("{halfedge} is its own twin", {{"halfedge", format_id(y)}}));
    if (mesh.twin(t) != y) return unpaired_twin(mesh, y, t);
    if (!mesh.alive(mesh.edge(y))) return bad_pointer(mesh, y, "edge", mesh.edge(y));
    if (mesh.edge(t) != mesh.edge(y)) {
      return Check::no(tr_format("{halfedge} and its twin {twin} lie on different edges ({edge}, {twin_edge})",
                                 {{"halfedge", format_id(y)},
                                  {"twin", format_id(t)},
                                  {"edge", format_id(mesh.edge(y))},
                                  {"twin_edge", format_id(mesh.edge(t))}}));
    }
    if (!mesh.alive(mesh.face(t))) return bad_pointer(mesh, t, "face", mesh.face(t));
    const VertexId head = mesh.vertex(cycle[(i + 1) % 3]);
    if (mesh.vertex(t) != head) {
      return Check::no(tr_format("{halfedge} reaches {vertex}, but its twin {twin} leaves {other}",
                                 {{"halfedge", format_id(y)},
                                  {"vertex", format_id(head)},
                                  {"twin", format_id(t)},
                                  {"other", format_id(mesh.vertex(t))}}));
    }
  }
  const VertexId v0 = mesh.vertex(cycle[0]), v1 = mesh.vertex(cycle[1]), v2 = mesh.vertex(cycle[2]);
  const auto uses_twice = [&](VertexId v) {
    return Check::no(tr_format("{face} uses {vertex} twice", {{"face", format_id(f)}, {"vertex", format_id(v)}}));
  };
  if (v0 == v1 || v0 == v2) return uses_twice(v0);
  if (v1 == v2) return uses_twice(v1);
  return Check::yes();
}

Check check_loop_step(const HalfedgeMesh& mesh, HalfedgeId h, VertexId head) {
  const HalfedgeId n = mesh.next(h);
  if (!mesh.alive(n)) return bad_pointer(mesh, h, "next", n);
  if (mesh.face(n) != mesh.face(h)) {
    return Check::no(
        tr_format("{halfedge} is in {face} but its next {next} is in {other}", {{"halfedge", format_id(h)},
                                                                                {"face", format_id(mesh.face(h))},
                                                                                {"next", format_id(n)},
                                                                                {"other", format_id(mesh.face(n))}}));
  }
  if (mesh.vertex(n) != head) {
    return Check::no(tr_format("{halfedge} reaches {vertex}, but its next {next} leaves {other}",
                               {{"halfedge", format_id(h)},
                                {"vertex", format_id(head)},
                                {"next", format_id(n)},
                                {"other", format_id(mesh.vertex(n))}}));
  }
  return Check::yes();
}

Check broken_fan(VertexId v, HalfedgeId start, const std::string& needed_for) {
  return Check::no(tr_format(
      "the halfedges around {vertex} do not form a closed fan (walking twin.next from {halfedge}); {needed_for}",
      {{"vertex", format_id(v)}, {"halfedge", format_id(start)}, {"needed_for", needed_for}}));
}

}  // namespace meshedit::ops_detail
