// compare_flip and compare_split: the student's flip_edge and split_edge against the reference's, with the
// elements of the diagrams in core/mesh_ops.h named (see internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <algorithm>
#include <string>

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
    return compare_refusal(input, report, "flip " + format_id(input.element), "flip_edge", out);
  }
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const EdgeId e(input.element.index);
  const Diamond q = diamond(before, e);
  const std::string turn = format_id(q.a) + "-" + format_id(q.b) + " becomes " + format_id(q.d) + "-" + format_id(q.c);
  if (mine.same_as(before)) {
    out.add("your flip_edge changed nothing" + std::string(report.mine.returned == "nil" ? " and returned nil" : "") +
            "; the reference flips " + format_id(e) + " (" + turn + ")");
    report.equal = false;
    return;
  }
  add_unchanged_next(report, before, "flip_edge", out);
  add_validation(report, "flip_edge", out);
  if (report.mine.element != ElementRef(e)) {
    out.add("your flip_edge returned " + report.mine.returned + "; it must return the flipped edge " + format_id(e));
  }
  for (ElementKind kind : {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face}) {
    for (uint32_t i = 0; i < std::max(mine.capacity(kind), before.capacity(kind)); ++i) {
      const ElementRef r(kind, i);
      if (mine.alive(r) && !before.alive(r)) {
        out.add("your flip_edge created " + format_id(r) + "; a flip reuses the elements it has");
      } else if (!mine.alive(r) && before.alive(r)) {
        out.add("your flip_edge deleted " + format_id(r) + "; a flip reuses the elements it has");
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
    note_pointer_differences(report, "a correct flip of " + format_id(e) + " (" + turn + ")");
    note_boundary_convention(report);
  }
}

void compare_split(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  if (!report.reference.refused.empty()) {
    add_locality(Exercise::SplitEdge, input, report, out);
    return compare_refusal(input, report, "split " + format_id(input.element), "split_edge", out);
  }
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const HalfedgeMesh& reference = *report.reference.mesh;
  const EdgeId e(input.element.index);
  const Diamond q = diamond(before, e);
  const glm::dvec3 midpoint = reference.position(VertexId(report.reference.element.index));
  const double tolerance = mesh_tolerance(before);
  if (mine.same_as(before)) {
    out.add("your split_edge changed nothing" + std::string(report.mine.returned == "nil" ? " and returned nil" : "") +
            "; the reference splits " + format_id(e) + " at its midpoint " + position_text(midpoint) +
            (before.is_boundary(e) ? " (a boundary edge: only the triangle side is split; extra credit in the course)"
                                   : ""));
    report.equal = false;
    return;
  }
  add_unchanged_next(report, before, "split_edge", out);
  add_validation(report, "split_edge", out);

  const ElementRef m = report.mine.element;
  if (m.kind != ElementKind::Vertex || !mine.alive(m)) {
    out.add("your split_edge returned " + report.mine.returned + "; it must return the new vertex");
  } else {
    const VertexId v(m.index);
    const glm::dvec3& p = mine.position(v);
    if (!within(p, midpoint, tolerance)) {
      glm::dvec3 corners = before.position(q.a) + before.position(q.b) + before.position(q.c);
      double count = 3.0;
      if (q.d.valid()) {
        corners += before.position(q.d);
        count = 4.0;
      }
      if (within(p, corners / count, tolerance)) {
        out.add("your new vertex " + format_id(v) + " is at " + position_text(p) + ", the average of the corners " +
                format_id(q.a) + " " + format_id(q.b) + " " + format_id(q.c) +
                (q.d.valid() ? " " + format_id(q.d) : "") + "; it belongs at the midpoint of " + format_id(q.a) +
                " and " + format_id(q.b) + ", " + position_text(midpoint));
      } else {
        out.add("your new vertex " + format_id(v) + " is at " + position_text(p) + "; it belongs at the midpoint of " +
                format_id(q.a) + " and " + format_id(q.b) + ", " + position_text(midpoint));
      }
    }
    // The course: the new vertex's halfedge runs along the split edge (towards a or b).
    const HalfedgeId h = mine.halfedge(v);
    if (mine.alive(h) && mine.alive(mine.twin(h)) && mine.alive(mine.vertex(mine.twin(h)))) {
      const glm::dvec3& to = mine.position(mine.vertex(mine.twin(h)));
      if (!within(to, before.position(q.a), tolerance) && !within(to, before.position(q.b), tolerance)) {
        out.add(format_id(v) + ".halfedge is " + format_id(h) + ", which runs to " +
                format_id(mine.vertex(mine.twin(h))) +
                " across a face; the new vertex's halfedge must run along the split edge (towards " + format_id(q.a) +
                " or " + format_id(q.b) + ")");
      }
    }
  }
  if (report.mine.validation->ok()) add_comparison(compare_meshes(mine, reference, {tolerance, 20}), out);
  add_locality(Exercise::SplitEdge, input, report, out);
  report.equal = !out.any();
  if (report.equal) {
    note_pointer_differences(report, "a correct split of " + format_id(e));
    note_boundary_convention(report);
  }
}

}  // namespace meshedit::exercise_checks
