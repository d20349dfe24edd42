// compare_flip and compare_split: the student's flip_edge and split_edge against the reference's, with the
// elements of the diagrams in core/mesh_ops.h named (see internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <algorithm>
#include <string>

#include "core/translation.h"

namespace meshedit::exercise_checks {

namespace {

// The elements of the diagrams in mesh_ops.h, read from the input (valid where the reference accepted e).
struct Diamond {
  VertexId a, b, c, d;  // d invalid on a boundary edge
};

Diamond diamond(const HalfedgeMesh& mesh, EdgeId e) {
  Diamond out;
  HalfedgeId h0 = mesh.halfedge(e);
  if (!mesh.alive(h0)) return out;
  if (mesh.face(h0).is_boundary() && mesh.alive(mesh.twin(h0))) h0 = mesh.twin(h0);
  const HalfedgeId h1 = mesh.twin(h0);
  if (!mesh.alive(h1)) return out;
  out.a = mesh.vertex(h0);
  out.b = mesh.vertex(h1);
  const HalfedgeId h3 = mesh.next(mesh.next(h0));
  if (mesh.alive(h3)) out.c = mesh.vertex(h3);
  if (!mesh.face(h1).is_boundary()) {
    const HalfedgeId h5 = mesh.next(mesh.next(h1));
    if (mesh.alive(h5)) out.d = mesh.vertex(h5);
  }
  return out;
}

}  // namespace

void compare_flip(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  if (!report.reference.refused.empty()) {
    add_locality(Exercise::FlipEdge, input, report, out);
    return compare_refusal(input, report, tr_format("flip {edge}", {{"edge", format_id(input.element)}}), "flip_edge",
                           out);
  }
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const EdgeId e(input.element.index);
  const Diamond q = diamond(before, e);
  const std::string turn = tr_format("{from} becomes {to}", {{"from", format_id(q.a) + "-" + format_id(q.b)},
                                                             {"to", format_id(q.d) + "-" + format_id(q.c)}});
  const MessageParts flipped = {{"edge", format_id(e)}, {"turn", turn}};
  if (mine.same_as(before)) {
    out.add(
        report.mine.returned == "nil"
            ? tr_format("your flip_edge changed nothing and returned nil; the reference flips {edge} ({turn})", flipped)
            : tr_format("your flip_edge changed nothing; the reference flips {edge} ({turn})", flipped));
    report.equal = false;
    return;
  }
  add_unchanged_next(report, before, "flip_edge", out);
  add_validation(report, "flip_edge", out);
  if (report.mine.element != ElementRef(e)) {
    out.add(tr_format("your flip_edge returned {returned}; it must return the flipped edge {edge}",
                      {{"returned", tr(report.mine.returned)}, {"edge", format_id(e)}}));
  }
  for (ElementKind kind : {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face}) {
    for (uint32_t i = 0; i < std::max(mine.capacity(kind), before.capacity(kind)); ++i) {
      const ElementRef r(kind, i);
      if (mine.alive(r) && !before.alive(r)) {
        out.add(tr_format("your flip_edge created {element}; a flip reuses the elements it has",
                          {{"element", format_id(r)}}));
      } else if (!mine.alive(r) && before.alive(r)) {
        out.add(tr_format("your flip_edge deleted {element}; a flip reuses the elements it has",
                          {{"element", format_id(r)}}));
      }
    }
  }
  // On a broken mesh the surface comparison would only restate the broken pointers less clearly.
  if (report.mine.validation->ok()) {
    add_comparison(compare_meshes(mine, *report.reference.mesh, {mesh_tolerance(before), 20}), out);
  }
  add_locality(Exercise::FlipEdge, input, report, out);
  report.equal = !out.any();
  if (report.equal) {
    note_pointer_differences(report, tr_format("a correct flip of {edge} ({turn})", flipped));
    note_boundary_convention(report);
  }
}

namespace {

// A split that changed nothing: what the reference does instead.
void add_split_changed_nothing(const ExerciseReport& report, const HalfedgeMesh& before, EdgeId e,
                               const glm::dvec3& midpoint, Messages& out) {
  const MessageParts parts = {{"edge", format_id(e)}, {"midpoint", position_text(midpoint)}};
  const bool nil = report.mine.returned == "nil";
  if (!before.is_boundary(e)) {
    out.add(nil ? tr_format("your split_edge changed nothing and returned nil; the reference splits {edge} at its "
                            "midpoint {midpoint}",
                            parts)
                : tr_format("your split_edge changed nothing; the reference splits {edge} at its midpoint {midpoint}",
                            parts));
  } else {
    out.add(nil ? tr_format("your split_edge changed nothing and returned nil; the reference splits {edge} at its "
                            "midpoint {midpoint} (a boundary edge: only the triangle side is split; extra credit in "
                            "the course)",
                            parts)
                : tr_format("your split_edge changed nothing; the reference splits {edge} at its midpoint {midpoint} "
                            "(a boundary edge: only the triangle side is split; extra credit in the course)",
                            parts));
  }
}

// The vertex the student's split returned: that it is one, where it sits, and where its halfedge runs.
void add_split_vertex(const ExerciseReport& report, const HalfedgeMesh& before, const Diamond& q,
                      const glm::dvec3& midpoint, double tolerance, Messages& out) {
  const HalfedgeMesh& mine = *report.mine.mesh;
  const ElementRef m = report.mine.element;
  if (m.kind != ElementKind::Vertex || !mine.alive(m)) {
    out.add(tr_format("your split_edge returned {returned}; it must return the new vertex",
                      {{"returned", tr(report.mine.returned)}}));
    return;
  }
  const VertexId v(m.index);
  const glm::dvec3& p = mine.position(v);
  const MessageParts placed = {{"vertex", format_id(v)},
                               {"position", position_text(p)},
                               {"a", format_id(q.a)},
                               {"b", format_id(q.b)},
                               {"midpoint", position_text(midpoint)}};
  if (!within(p, midpoint, tolerance)) {
    glm::dvec3 corners = before.position(q.a) + before.position(q.b) + before.position(q.c);
    double count = 3.0;
    if (q.d.valid()) {
      corners += before.position(q.d);
      count = 4.0;
    }
    if (within(p, corners / count, tolerance)) {
      MessageParts averaged = placed;
      averaged.emplace_back("corners", format_id(q.a) + " " + format_id(q.b) + " " + format_id(q.c) +
                                           (q.d.valid() ? " " + format_id(q.d) : ""));
      out.add(
          tr_format("your new vertex {vertex} is at {position}, the average of the corners {corners}; it belongs "
                    "at the midpoint of {a} and {b}, {midpoint}",
                    averaged));
    } else {
      out.add(
          tr_format("your new vertex {vertex} is at {position}; it belongs at the midpoint of {a} and {b}, "
                    "{midpoint}",
                    placed));
    }
  }
  // The course: the new vertex's halfedge runs along the split edge (towards a or b).
  const HalfedgeId h = mine.halfedge(v);
  if (mine.alive(h) && mine.alive(mine.twin(h)) && mine.alive(mine.vertex(mine.twin(h)))) {
    const glm::dvec3& to = mine.position(mine.vertex(mine.twin(h)));
    if (!within(to, before.position(q.a), tolerance) && !within(to, before.position(q.b), tolerance)) {
      MessageParts across = placed;
      across.emplace_back("halfedge", format_id(h));
      across.emplace_back("to", format_id(mine.vertex(mine.twin(h))));
      out.add(
          tr_format("{vertex}.halfedge is {halfedge}, which runs to {to} across a face; the new vertex's "
                    "halfedge must run along the split edge (towards {a} or {b})",
                    across));
    }
  }
}
}  // namespace

void compare_split(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  if (!report.reference.refused.empty()) {
    add_locality(Exercise::SplitEdge, input, report, out);
    return compare_refusal(input, report, tr_format("split {edge}", {{"edge", format_id(input.element)}}), "split_edge",
                           out);
  }
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const HalfedgeMesh& reference = *report.reference.mesh;
  const EdgeId e(input.element.index);
  const Diamond q = diamond(before, e);
  const glm::dvec3 midpoint = reference.position(VertexId(report.reference.element.index));
  const double tolerance = mesh_tolerance(before);
  if (mine.same_as(before)) {
    add_split_changed_nothing(report, before, e, midpoint, out);
    report.equal = false;
    return;
  }
  add_unchanged_next(report, before, "split_edge", out);
  add_validation(report, "split_edge", out);
  add_split_vertex(report, before, q, midpoint, tolerance, out);
  if (report.mine.validation->ok()) add_comparison(compare_meshes(mine, reference, {tolerance, 20}), out);
  add_locality(Exercise::SplitEdge, input, report, out);
  report.equal = !out.any();
  if (report.equal) {
    note_pointer_differences(report, tr_format("a correct split of {edge}", {{"edge", format_id(e)}}));
    note_boundary_convention(report);
  }
}

}  // namespace meshedit::exercise_checks
