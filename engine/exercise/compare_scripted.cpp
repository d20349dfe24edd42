// compare_scripted: an exercise defined in Lua (scripted_exercise.h) against its reference, on a mesh or, on
// points or a patch, value by value (value_compare.h), with the definition's own diagnoses first (see
// internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/translation.h"
#include "exercise/value_compare.h"

namespace meshedit::exercise_checks {

namespace {

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
    if (!within(p[i], q[i], tolerance)) return false;
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
    report.notes.push_back(
        tr_format("your values differ from the reference's by at most {distance} (rounding; accepted)",
                  {{"distance", format_number(c.worst)}}));
  }
}

}  // namespace

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
  if (!report.reference.refused.empty()) {
    const MessageParts call = {{"function", function}, {"element", format_id(input.element)}};
    return compare_refusal(input, report,
                           input.element.valid() ? tr_format("change the mesh in {function} on {element}", call)
                                                 : tr_format("change the mesh in {function}", call),
                           function, out);
  }
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  const HalfedgeMesh& reference = *report.reference.mesh;
  const double tolerance = mesh_tolerance(before);
  if (mine.same_as(before)) {
    out.add(tr_format("your {function} changed nothing; the reference changes {change}",
                      {{"function", function}, {"change", first_change(before, reference)}}));
  } else {
    add_unchanged_next(report, before, function, out);
    add_validation(report, function, out);
    if (report.mine.validation->ok()) add_comparison(compare_meshes(mine, reference, {tolerance, 20}), out);
  }
  if (!same_element(mine, report.mine.element, reference, report.reference.element, tolerance)) {
    out.add(tr_format(
        "your {function} returned {returned}; the reference returns {expected}",
        {{"function", function}, {"returned", tr(report.mine.returned)}, {"expected", tr(report.reference.returned)}}));
  }
  if (out.any()) diagnoses_first(scripted, input, report, out);
  report.equal = !out.any();
  if (report.equal) note_pointer_differences(report, tr_format("a correct {function}", {{"function", function}}));
}

}  // namespace meshedit::exercise_checks
