// compare() for the six exercises (exercises.h): the verdict, and diagnoses that name the likely mistake before the
// raw differences (the students' real mistakes: a step that drops the last point or swaps the weights, u and v
// swapped, a normal made of the wrong faces, weights or orientation, forgotten halfedge pointers, a next pointer left
// as it was that breaks a face cycle, a flipped boundary edge, a split vertex at the wrong place, wrong flips, wrong
// weights or misplaced positions in Loop subdivision, a loop that never ends, a flip or a split that walks the whole
// mesh). The grader checks through this same code (grade/exercise_expectation.h), so a failure there reads like the
// window.
//
// Tolerances: points within points_tolerance of the input, normals within 1e-9, meshes within mesh_tolerance of the
// input (both in core/mesh_compare.h: 1e-9 scaled by the input's size); "identical" means bit for bit and, for
// meshes, pointer for pointer (compare_meshes_exact with tolerance 0).
//
// Map of this file (each part starts at its `// ---- name` banner):
//   messages                       Messages (the capped list a verdict fills), bitwise_equal, close
//   curve step                     compare_curve: a dropped last point, swapped weights
//   patch point and vertex normal  compare_patch (u and v swapped), compare_normal (what a wrong normal is made of:
//                                  normal_diagnosis.h)
//   meshes: shared checks          validation, unchanged next pointers, the comparison, pointer and boundary notes,
//                                  the locality bound (exercise_locality.h)
//   flip                           compare_flip
//   split                          compare_split: where the new vertex is, which pointers were forgotten
//   upsample                       diagnose_upsample and its diagnoses (zero weights first:
//                                  loop_zero_weight_diagnosis.h; flips: loop_flip_diagnosis.h), compare_upsample
//   scripted exercises             compare_scripted: exercises defined in Lua (scripted_exercise.h), on a mesh or,
//                                  compare_scripted_values, on points or a patch (value_compare.h)
//   runs that failed               add_run_failure: an error or a limit, with its hint
//   public functions               unfinished_run_hint, ExerciseReport::summary, compare (the dispatch)
#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/history.h"
#include "core/mesh_compare.h"
#include "core/value_format.h"
#include "script/exercise_locality.h"
#include "script/exercises.h"
#include "script/loop_boundary_diagnosis.h"
#include "script/loop_flip_diagnosis.h"
#include "script/loop_position_diagnosis.h"
#include "script/loop_zero_weight_diagnosis.h"
#include "script/normal_diagnosis.h"
#include "script/scripted_exercise.h"
#include "script/upsample_runaway.h"
#include "script/value_compare.h"

namespace meshedit {
namespace {

// ---- messages --------------------------------------------------------------------------------------

// Keeps the first kMaxMessages messages and counts all.
class Messages {
 public:
  explicit Messages(ExerciseReport& report) : report_(report) {}
  void add(std::string message) {
    ++report_.total_differences;
    if (report_.differences.size() < ExerciseReport::kMaxMessages) report_.differences.push_back(std::move(message));
  }
  // Differences another check counted but did not spell out (past its own cap).
  void count(size_t n) { report_.total_differences += n; }
  bool any() const { return report_.total_differences > 0; }

 private:
  ExerciseReport& report_;
};

std::string pos(const glm::dvec3& p) { return format_position(p); }

bool bitwise_equal(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

bool close(const glm::dvec3& a, const glm::dvec3& b, double tolerance) { return glm::distance(a, b) <= tolerance; }

// ---- curve step -------------------------------------------------------------------------------------------

void compare_curve(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const auto& got = report.mine.points;
  const auto& want = report.reference.points;
  const double tolerance = points_tolerance(input.points);
  const size_t common = std::min(got.size(), want.size());
  bool prefix_matches = true;
  for (size_t i = 0; i < common; ++i) prefix_matches = prefix_matches && close(got[i], want[i], tolerance);

  // Swapped weights: t p_i + (1 - t) p_(i+1).
  if (got.size() == want.size() && !prefix_matches) {
    bool swapped = true;
    for (size_t i = 0; i < got.size(); ++i) {
      const glm::dvec3 other = input.t * input.points[i] + (1.0 - input.t) * input.points[i + 1];
      swapped = swapped && close(got[i], other, tolerance);
    }
    if (swapped) {
      out.add(
          "the weights are swapped: point i of the step must be (1 - t) * p_i + t * p_(i+1), and yours are "
          "t * p_i + (1 - t) * p_(i+1)");
    }
  }
  const std::string expected = std::to_string(want.size());
  if (got.size() < want.size()) {
    const size_t missing = want.size() - got.size();
    if (prefix_matches && missing == 1) {
      out.add("point " + expected + " of the step is missing (got " + std::to_string(got.size()) +
              " points, expected " + expected + "): n points give n - 1, so the loop runs i = 1, ..., n - 1");
    } else if (prefix_matches) {
      out.add("points " + std::to_string(got.size() + 1) + " to " + expected + " of the step are missing (got " +
              std::to_string(got.size()) + " points, expected " + expected + ")");
    } else {
      out.add("the step has " + std::to_string(got.size()) + " points, expected " + expected +
              " (n points give n - 1)");
    }
  } else if (got.size() > want.size()) {
    out.add("the step has " + std::to_string(got.size()) + " points, expected " + expected +
            ": one step turns n points into n - 1" +
            (got.size() == input.points.size() ? " (yours has as many as it was given)" : ""));
  }
  double worst = 0.0;
  for (size_t i = 0; i < common; ++i) {
    const double d = glm::distance(got[i], want[i]);
    worst = std::max(worst, d);
    if (!(d <= tolerance)) {
      out.add("point " + std::to_string(i + 1) + " is " + pos(got[i]) + ", expected " + pos(want[i]));
    }
  }
  report.equal = !out.any();
  report.identical =
      report.equal && got.size() == want.size() && std::equal(got.begin(), got.end(), want.begin(), bitwise_equal);
  if (report.equal && !report.identical) {
    report.notes.push_back("your points differ from the reference's by at most " + format_number(worst) +
                           " (rounding; accepted)");
  }
}

// ---- patch point and vertex normal ------------------------------------------------------------------------

void compare_patch(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const glm::dvec3 got = report.mine.points[0];
  const glm::dvec3 want = report.reference.points[0];
  const double tolerance = points_tolerance(input.patch.points);
  const double d = glm::distance(got, want);
  if (!(d <= tolerance)) {
    const glm::dvec3 transposed = evaluate_patch(input.patch, input.v, input.u);
    if (close(got, transposed, tolerance) && !close(transposed, want, tolerance)) {
      out.add("your point " + pos(got) + " is the surface point at (u, v) = (" + format_number(input.v) + ", " +
              format_number(input.u) + "), not (" + format_number(input.u) + ", " + format_number(input.v) +
              "): u and v are swapped. Evaluate each row at u, then the column of the four row results at v");
    } else {
      out.add("your point " + pos(got) + " is not the surface point " + pos(want) + " at (u, v) = (" +
              format_number(input.u) + ", " + format_number(input.v) + "); it is " + format_number(d) + " away");
    }
  }
  report.equal = !out.any();
  report.identical = report.equal && bitwise_equal(got, want);
  if (report.equal && !report.identical) {
    report.notes.push_back("your point differs from the reference's by " + format_number(d) + " (rounding; accepted)");
  }
}

// A wrong normal is explained by what it is made of (normal_diagnosis.h); the mesh must not change.
void compare_normal(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const glm::dvec3 got = report.mine.points[0];
  const glm::dvec3 want = report.reference.points[0];
  const HalfedgeMesh& mesh = *input.mesh;
  const double d = glm::distance(got, want);
  if (std::string wrong = explain_vertex_normal(mesh, VertexId(input.element.index), got, want); !wrong.empty()) {
    out.add(std::move(wrong));
  }
  if (report.mine.mesh && !report.mine.mesh->same_as(mesh)) {
    const std::vector<FieldChange> changes = diff(mesh, *report.mine.mesh);
    std::string first;
    if (!changes.empty()) {
      const FieldChange& c = changes.front();
      first = ": " + format_id(c.element) + "." + c.field + " was " + c.before + ", is " + c.after;
    }
    out.add("vertex_normal changed the mesh" + first + " (" + plural(changes.size(), "change", "changes") +
            "); it must only read it");
  }
  report.equal = !out.any();
  report.identical = report.equal && bitwise_equal(got, want);
  if (report.equal && !report.identical) {
    report.notes.push_back("your normal differs from the reference's by " + format_number(d) + " (rounding; accepted)");
  }
}

// ---- meshes: shared checks --------------------------------------------------------------------------------

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

void add_validation(const ExerciseReport& report, const char* function, Messages& out) {
  const ValidationReport& v = *report.mine.validation;
  if (v.ok()) return;
  for (size_t i = 0; i < v.violations.size(); ++i) {
    std::string message = v.violations[i].message;
    if (i == 0) {
      message = "after your " + std::string(function) + " the mesh is not valid (" +
                plural(v.total, "problem", "problems") + "): " + message;
    }
    out.add(message);
  }
  out.count(v.total - v.violations.size());
}

// When a face cycle is broken: the next pointers the reference rewrote and yours left as they were (the pointer
// that breaks the cycle is usually one of them).
void add_unchanged_next(const ExerciseReport& report, const HalfedgeMesh& before, const char* function, Messages& out) {
  const ValidationReport& v = *report.mine.validation;
  const bool cycle_broken = std::any_of(v.violations.begin(), v.violations.end(), [](const Violation& x) {
    return x.invariant == Invariant::FaceCycle || x.invariant == Invariant::NextNotPermutation;
  });
  if (!cycle_broken) return;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const HalfedgeMesh& reference = *report.reference.mesh;
  std::string items;
  size_t count = 0;
  for (HalfedgeId h : before.halfedges()) {
    if (!mine.alive(h) || !reference.alive(h)) continue;
    if (reference.next(h) == before.next(h) || mine.next(h) != before.next(h)) continue;
    if (count++ < 3) {
      items += (items.empty() ? "" : ", ") + format_id(h) + ".next is still " + format_id(before.next(h));
    }
  }
  if (count == 0) return;
  out.add(items + (count > 3 ? " (and " + std::to_string(count - 3) + " more)" : "") + " after your " + function +
          ", as before the call; the reference changes " +
          (count == 1 ? "it: that pointer breaks"
                      : "them: these "
                        "pointers break") +
          " the face cycle");
}

std::string first_change(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  const std::vector<FieldChange> changes = diff(before, after);
  if (changes.empty()) return "";
  const FieldChange& c = changes.front();
  return format_id(c.element) + "." + c.field + " was " + c.before + ", is " + c.after;
}

void add_comparison(const MeshComparison& c, Messages& out) {
  for (const std::string& d : c.differences) out.add(d);
  out.count(c.total_differences - c.differences.size());
}

// Pointer-level differences when the surface is right, as notes.
void note_pointer_differences(ExerciseReport& report, const std::string& what) {
  const MeshComparison exact = compare_meshes_exact(*report.mine.mesh, *report.reference.mesh, {0.0, 5});
  report.identical = exact.equal;
  if (exact.equal) return;
  report.notes.push_back(
      what + " (" + std::to_string(exact.total_differences) +
      " pointer or id differences from the reference, which is accepted); first: " + exact.differences.front());
}

// The course's rule for a boundary vertex's halfedge: any halfedge leaving it (the course's own builder picks an
// interior one). MeshEdit's operations keep it on the boundary loop; a student's that does not is accepted, and
// the window says so in a note, as the grader (which compares through this code) accepts it.
void note_boundary_convention(ExerciseReport& report) {
  const HalfedgeMesh& m = *report.mine.mesh;
  for (VertexId v : m.vertices()) {
    const HalfedgeId h = m.halfedge(v);
    if (!m.alive(h) || m.face(h).is_boundary() || !m.is_boundary(v)) continue;
    report.notes.push_back(format_id(v) + " is on the boundary and its halfedge " + format_id(h) +
                           " is not on the boundary loop: accepted (the course lets a vertex's halfedge be any "
                           "halfedge leaving it; MeshEdit's own operations keep a boundary vertex's on the loop)");
    return;
  }
}

// A flip or a split that touched more of a big mesh than its edge's neighbourhood (exercise_locality.h).
void add_locality(Exercise exercise, const ExerciseInput& input, const ExerciseReport& report, Messages& out) {
  std::string message = locality_failure(exercise, input, report.mine, report.reference);
  if (!message.empty()) out.add(std::move(message));
}

// Refused by the reference (`what` is "flip e3", "split e3", "subdivide this mesh"): mine must change nothing
// and return nil.
void compare_refusal(const ExerciseInput& input, ExerciseReport& report, const std::string& what, const char* function,
                     Messages& out) {
  if (!report.mine.mesh->same_as(*input.mesh)) {
    out.add("the reference does not " + what + " (" + report.reference.refused + "), but your " + function +
            " changed the mesh: " + first_change(*input.mesh, *report.mine.mesh));
  }
  if (report.mine.returned != "nil" && !report.mine.returned.empty()) {
    out.add("the reference returns nil here (" + report.reference.refused + "); yours returned " +
            report.mine.returned);
  }
  report.equal = !out.any();
  report.identical = report.equal;
}

// ---- flip -------------------------------------------------------------------------------------------------

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

// ---- split ------------------------------------------------------------------------------------------------

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
            "; the reference splits " + format_id(e) + " at its midpoint " + pos(midpoint) +
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
    if (!close(p, midpoint, tolerance)) {
      glm::dvec3 corners = before.position(q.a) + before.position(q.b) + before.position(q.c);
      double count = 3.0;
      if (q.d.valid()) {
        corners += before.position(q.d);
        count = 4.0;
      }
      if (close(p, corners / count, tolerance)) {
        out.add("your new vertex " + format_id(v) + " is at " + pos(p) + ", the average of the corners " +
                format_id(q.a) + " " + format_id(q.b) + " " + format_id(q.c) +
                (q.d.valid() ? " " + format_id(q.d) : "") + "; it belongs at the midpoint of " + format_id(q.a) +
                " and " + format_id(q.b) + ", " + pos(midpoint));
      } else {
        out.add("your new vertex " + format_id(v) + " is at " + pos(p) + "; it belongs at the midpoint of " +
                format_id(q.a) + " and " + format_id(q.b) + ", " + pos(midpoint));
      }
    }
    // The course: the new vertex's halfedge runs along the split edge (towards a or b).
    const HalfedgeId h = mine.halfedge(v);
    if (mine.alive(h) && mine.alive(mine.twin(h)) && mine.alive(mine.vertex(mine.twin(h)))) {
      const glm::dvec3& to = mine.position(mine.vertex(mine.twin(h)));
      if (!close(to, before.position(q.a), tolerance) && !close(to, before.position(q.b), tolerance)) {
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

// ---- upsample ---------------------------------------------------------------------------------------------

// Zero weights put vertices at the origin. Returns how many of yours are there; says so when `tell`.
size_t diagnose_zero_weights(const HalfedgeMesh& mine, const HalfedgeMesh& reference, double tolerance, bool tell,
                             Messages& out) {
  size_t at_origin = 0, reference_at_origin = 0;
  for (VertexId v : mine.vertices()) at_origin += close(mine.position(v), glm::dvec3(0.0), tolerance) ? 1 : 0;
  for (VertexId v : reference.vertices()) {
    reference_at_origin += close(reference.position(v), glm::dvec3(0.0), tolerance) ? 1 : 0;
  }
  if (tell && at_origin >= 2 && at_origin > reference_at_origin) {
    out.add(std::to_string(at_origin) + " of your vertices are at (0, 0, 0): a weight that should not be zero is " +
            "(in Lua 3 // 8 is 0, an integer division; write 3 / 8)");
  }
  return at_origin;
}

// Original vertices (they keep their ids in both) that did not move.
void diagnose_unmoved_originals(const HalfedgeMesh& before, const HalfedgeMesh& mine, const HalfedgeMesh& reference,
                                double tolerance, Messages& out) {
  size_t originals = 0, unmoved = 0;
  for (VertexId v : before.vertices()) {
    if (!mine.alive(v) || !reference.alive(v)) continue;
    ++originals;
    const bool right = close(mine.position(v), reference.position(v), tolerance);
    if (!right && close(mine.position(v), before.position(v), tolerance)) ++unmoved;
  }
  if (unmoved > 0 && unmoved * 2 >= originals) {
    out.add(std::to_string(unmoved) + " of the " + std::to_string(originals) +
            " original vertices kept their old positions: step 5 must move them to the positions of step 1, "
            "(1 - n u) p + u (sum of the neighbours)");
  }
}

// Coinciding vertices: positions written to the wrong vertices make the mesh collapse (unless zero weights put them
// all at the origin, told first).
void diagnose_coinciding_vertices(const HalfedgeMesh& mine, size_t at_origin, Messages& out) {
  std::vector<glm::dvec3> positions;
  for (VertexId v : mine.vertices()) positions.push_back(mine.position(v));
  std::sort(positions.begin(), positions.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  });
  size_t shared = 0;
  for (size_t i = 1; i < positions.size(); ++i) shared += positions[i] == positions[i - 1] ? 1 : 0;
  if (shared >= 2 && at_origin < 2) {
    out.add(std::to_string(shared) +
            " of your vertices sit exactly on another one: were new positions written to "
            "the wrong vertices? Keep them in a table indexed by v.id and move each vertex to its own");
  }
}

// Likely mistakes, from where your vertices are and which edges you have that the reference does not.
void diagnose_upsample(const ExerciseInput& input, const ExerciseReport& report, const MeshComparison& c,
                       double tolerance, Messages& out) {
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const HalfedgeMesh& reference = *report.reference.mesh;
  // A weight integer division made 0 is told first, before a later step is blamed for what it did.
  const ZeroLoopWeights zero = diagnose_zero_loop_weights(before, mine, tolerance);
  for (const std::string& m : zero.messages) out.add(m);
  const size_t at_origin = diagnose_zero_weights(mine, reference, tolerance, !zero.origin_told, out);
  if (!zero.originals_unmoved) diagnose_unmoved_originals(before, mine, reference, tolerance, out);
  // A position written to the wrong vertex, or a wrong weight (named with the weight it was).
  for (std::string& m : diagnose_loop_positions(before, mine, reference, tolerance, zero.origin_told)) {
    out.add(std::move(m));
  }
  for (std::string& m : diagnose_loop_boundary(before, mine, tolerance)) out.add(std::move(m));
  diagnose_coinciding_vertices(mine, at_origin, out);
  for (std::string& m : diagnose_loop_flips(before, mine, reference, c)) out.add(std::move(m));
}

void compare_upsample(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  if (!report.reference.refused.empty()) return compare_refusal(input, report, "subdivide this mesh", "upsample", out);
  if (mine.same_as(before)) {
    out.add("your upsample changed nothing; the reference makes " + std::to_string(report.reference.mesh->num_faces()) +
            " faces out of " + std::to_string(before.num_faces()));
    report.equal = false;
    return;
  }
  add_validation(report, "upsample", out);
  if (report.mine.validation->ok()) {
    const double tolerance = mesh_tolerance(before);
    const MeshComparison c = compare_meshes(mine, *report.reference.mesh, {tolerance, 20});
    if (!c.equal) diagnose_upsample(input, report, c, tolerance, out);
    add_comparison(c, out);
  }
  report.equal = !out.any();
  if (report.equal) note_pointer_differences(report, "a correct subdivision");
}

// ---- scripted exercises ---------------------------------------------------------------------------------------

// What a returned element is, for comparing returns across meshes that number their elements differently: a
// vertex by its position, an edge by its two ends' positions, a face or halfedge by its corners'.
std::vector<glm::dvec3> element_points(const HalfedgeMesh& mesh, ElementRef r) {
  std::vector<glm::dvec3> points;
  if (!r.valid() || !mesh.alive(r)) return points;
  switch (r.kind) {
    case ElementKind::Vertex: points.push_back(mesh.position(VertexId(r.index))); break;
    case ElementKind::Edge: {
      const HalfedgeId h = mesh.halfedge(EdgeId(r.index));
      points = {mesh.position(mesh.vertex(h)), mesh.position(mesh.vertex(mesh.twin(h)))};
      break;
    }
    case ElementKind::Halfedge: {
      const HalfedgeId h(r.index);
      points = {mesh.position(mesh.vertex(h)), mesh.position(mesh.vertex(mesh.twin(h)))};
      return points;  // a halfedge's direction counts
    }
    default: {
      const FaceId f(r.index);
      mesh.for_each_face_halfedge(f, [&](HalfedgeId h) { points.push_back(mesh.position(mesh.vertex(h))); });
      break;
    }
  }
  std::sort(points.begin(), points.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  });
  return points;
}

bool same_element(const HalfedgeMesh& mine, ElementRef a, const HalfedgeMesh& reference, ElementRef b,
                  double tolerance) {
  if (a.valid() != b.valid()) return false;
  if (!a.valid()) return true;
  if (a.kind != b.kind) return false;
  const std::vector<glm::dvec3> p = element_points(mine, a), q = element_points(reference, b);
  if (p.size() != q.size()) return false;
  for (size_t i = 0; i < p.size(); ++i) {
    if (!close(p[i], q[i], tolerance)) return false;
  }
  return true;
}

// Puts the definition's diagnoses before the messages the checks added (called only when something differs).
void diagnoses_first(const ScriptedExercise& scripted, const ExerciseInput& input, ExerciseReport& report,
                     Messages& out) {
  std::vector<std::string> checks = std::move(report.differences);
  const size_t counted = report.total_differences;
  report.differences.clear();
  report.total_differences = 0;
  for (std::string& m : scripted.diagnose(input, report.mine, report.reference)) out.add(std::move(m));
  for (std::string& m : checks) out.add(std::move(m));
  out.count(counted - checks.size());
}

// An exercise on points or a patch: the returned values item by item (value_compare.h), the definition's diagnoses
// first.
void compare_scripted_values(const ScriptedExercise& scripted, const ExerciseInput& input, ExerciseReport& report,
                             Messages& out) {
  const ValueComparison c = compare_values(report.mine.value, report.reference.value, scripted.tolerance(input),
                                           ExerciseReport::kMaxMessages);
  for (const std::string& d : c.differences) out.add(d);
  out.count(c.total - c.differences.size());
  if (out.any()) diagnoses_first(scripted, input, report, out);
  report.equal = !out.any();
  report.identical = report.equal && c.identical;
  if (report.equal && !report.identical) {
    report.notes.push_back("your values differ from the reference's by at most " + format_number(c.worst) +
                           " (rounding; accepted)");
  }
}

// An exercise defined in Lua: a refusal as for flip; else the definition's diagnoses first (only when something
// differs), then what breaks the mesh, what it returned, and the surface up to renumbering.
void compare_scripted(const ScriptedExercise& scripted, const ExerciseInput& input, ExerciseReport& report,
                      Messages& out) {
  const char* function = scripted.info().function;
  if (!report.reference.ran) {
    out.add(report.reference.error);
    report.equal = false;
    return;
  }
  if (scripted.takes_values()) return compare_scripted_values(scripted, input, report, out);
  const std::string what = std::string(function) + (input.element.valid() ? " on " + format_id(input.element) : "");
  if (!report.reference.refused.empty()) {
    return compare_refusal(input, report, "change the mesh in " + what, function, out);
  }
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const HalfedgeMesh& reference = *report.reference.mesh;
  const double tolerance = mesh_tolerance(before);
  if (mine.same_as(before)) {
    out.add("your " + std::string(function) + " changed nothing; the reference changes " +
            first_change(before, reference));
  } else {
    add_unchanged_next(report, before, function, out);
    add_validation(report, function, out);
    if (report.mine.validation->ok()) add_comparison(compare_meshes(mine, reference, {tolerance, 20}), out);
  }
  if (!same_element(mine, report.mine.element, reference, report.reference.element, tolerance)) {
    out.add("your " + std::string(function) + " returned " + report.mine.returned + "; the reference returns " +
            report.reference.returned);
  }
  if (out.any()) diagnoses_first(scripted, input, report, out);
  report.equal = !out.any();
  if (report.equal) note_pointer_differences(report, "a correct " + std::string(function));
}

// ---- runs that failed ------------------------------------------------------------------------------

// A Lua error or a limit, with a hint for the usual reasons. An upsample that did not finish (a limit or a cap stopped
// it) is explained from where it was stopped and what it had done (upsample_runaway.h), its line first.
void add_run_failure(Exercise exercise, const ExerciseInput& input, const ExerciseReport& report, Messages& out) {
  const std::string& error = report.mine.error;
  const bool unfinished = report.mine.limit != ScriptError::Limit::None;
  if (unfinished && exercise == Exercise::Upsample && input.mesh) {
    out.add(explain_unfinished_upsample(error, *input.mesh, report.mine.mesh.get(), report.mine.edits));
  } else {
    out.add(error);
  }
  if (!unfinished) return;
  if (std::string hint = unfinished_run_hint(exercise); !hint.empty()) out.add(std::move(hint));
}

}  // namespace

// ---- public functions ------------------------------------------------------------------------------

std::string unfinished_run_hint(Exercise exercise) {
  switch (exercise) {
    case Exercise::Upsample:
      return "upsample did not finish: split only the edges of the original mesh (list them before the first "
             "split); a loop over all edges that re-reads mesh:num_edges() keeps finding the edges splits create. A "
             "loop that splits nothing never ends when what its condition waits for never changes";
    case Exercise::FlipEdge:
    case Exercise::SplitEdge:
    case Exercise::VertexNormal:
      return "it did not finish: a walk like `repeat ... h = h.twin.next until h == start` never comes back to its "
             "start when a pointer is wrong";
    default: {
      const std::shared_ptr<const ScriptedExercise> scripted = scripted_exercise(exercise);
      return scripted ? scripted->hint() : "";
    }
  }
}

std::string ExerciseReport::summary() const {
  if (equal) return "same as the reference";
  std::string s = "different";
  if (!differences.empty()) s += ": " + differences.front();
  if (total_differences > 1) s += " (" + std::to_string(total_differences - 1) + " more)";
  return s;
}

ExerciseReport compare(Exercise exercise, const ExerciseInput& input, ExerciseOutcome mine, ExerciseOutcome reference) {
  ExerciseReport report;
  report.exercise = exercise;
  report.mine = std::move(mine);
  report.reference = std::move(reference);
  Messages out(report);
  const bool on_mesh = is_mesh_exercise(exercise);
  if (on_mesh && report.mine.ran && !report.mine.mesh) {
    report.mine.ran = false;
    report.mine.error = "no mesh came back from " + std::string(exercise_info(exercise).function);
  }
  if (on_mesh && report.mine.mesh && !report.mine.validation) report.mine.validation = validate(*report.mine.mesh);
  if (!report.mine.ran) {
    add_run_failure(exercise, input, report, out);
    report.equal = false;
    return report;
  }
  switch (exercise) {
    case Exercise::CurveStep: compare_curve(input, report, out); break;
    case Exercise::PatchEvaluate: compare_patch(input, report, out); break;
    case Exercise::VertexNormal: compare_normal(input, report, out); break;
    case Exercise::FlipEdge: compare_flip(input, report, out); break;
    case Exercise::SplitEdge: compare_split(input, report, out); break;
    case Exercise::Upsample: compare_upsample(input, report, out); break;
    default:
      if (const std::shared_ptr<const ScriptedExercise> scripted = scripted_exercise(exercise)) {
        compare_scripted(*scripted, input, report, out);
      }
  }
  return report;
}

}  // namespace meshedit
