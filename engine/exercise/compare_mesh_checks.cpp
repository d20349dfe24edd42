// The checks every mesh exercise runs (see internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/history.h"
#include "core/translation.h"
#include "core/validate.h"
#include "exercise/exercise_locality.h"

namespace meshedit::exercise_checks {

void add_validation(const ExerciseReport& report, const char* function, Messages& out) {
  const ValidationReport& v = *report.mine.validation;
  if (v.ok()) return;
  for (size_t i = 0; i < v.violations.size(); ++i) {
    std::string message = v.violations[i].message;
    if (i == 0) {
      const MessageParts parts = {{"function", function}, {"count", std::to_string(v.total)}, {"first", message}};
      message = v.total == 1
                    ? tr_format("after your {function} the mesh is not valid ({count} problem): {first}", parts)
                    : tr_format("after your {function} the mesh is not valid ({count} problems): {first}", parts);
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
      items +=
          (items.empty() ? "" : ", ") + tr_format("{halfedge}.next is still {next}",
                                                  {{"halfedge", format_id(h)}, {"next", format_id(before.next(h))}});
    }
  }
  if (count == 0) return;
  const MessageParts parts = {{"items", items}, {"more", std::to_string(count - 3)}, {"function", function}};
  if (count == 1) {
    out.add(
        tr_format("{items} after your {function}, as before the call; the reference changes it: that pointer "
                  "breaks the face cycle",
                  parts));
  } else if (count <= 3) {
    out.add(
        tr_format("{items} after your {function}, as before the call; the reference changes them: these "
                  "pointers break the face cycle",
                  parts));
  } else {
    out.add(
        tr_format("{items} (and {more} more) after your {function}, as before the call; the reference changes "
                  "them: these pointers break the face cycle",
                  parts));
  }
}

std::string first_change(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  const std::vector<FieldChange> changes = diff(before, after);
  if (changes.empty()) return "";
  const FieldChange& c = changes.front();
  return tr_format("{element}.{field} was {before}, is {after}",
                   {{"element", format_id(c.element)}, {"field", c.field}, {"before", c.before}, {"after", c.after}});
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
  report.notes.push_back(tr_format(
      "{what} ({count} pointer or id differences from the reference, which is accepted); first: {first}",
      {{"what", what}, {"count", std::to_string(exact.total_differences)}, {"first", exact.differences.front()}}));
}

// The course's rule for a boundary vertex's halfedge: any halfedge leaving it (the course's own builder picks an
// interior one). MeshEdit's operations keep it on the boundary loop; a student's that does not is accepted, and
// the window says so in a note, as the grader (which compares through this code) accepts it.
void note_boundary_convention(ExerciseReport& report) {
  const HalfedgeMesh& m = *report.mine.mesh;
  for (VertexId v : m.vertices()) {
    const HalfedgeId h = m.halfedge(v);
    if (!m.alive(h) || m.face(h).is_boundary() || !m.is_boundary(v)) continue;
    report.notes.push_back(
        tr_format("{vertex} is on the boundary and its halfedge {halfedge} is not on the boundary loop: accepted (the "
                  "course lets a vertex's halfedge be any halfedge leaving it; MeshEdit's own operations keep a "
                  "boundary vertex's on the loop)",
                  {{"vertex", format_id(v)}, {"halfedge", format_id(h)}}));
    return;
  }
}

// A flip or a split that touched more of a big mesh than its edge's neighbourhood (exercise_locality.h).
void add_locality(Exercise exercise, const ExerciseInput& input, const ExerciseReport& report, Messages& out) {
  std::string message = locality_failure(exercise, input, report.mine, report.reference);
  if (!message.empty()) out.add(std::move(message));
}

// Refused by the reference (`what` is "flip e3", "split e3", "subdivide this mesh", in the window's language):
// mine must change nothing and return nil.
void compare_refusal(const ExerciseInput& input, ExerciseReport& report, const std::string& what, const char* function,
                     Messages& out) {
  if (!report.mine.mesh->same_as(*input.mesh)) {
    out.add(tr_format("the reference does not {what} ({reason}), but your {function} changed the mesh: {change}",
                      {{"what", what},
                       {"reason", report.reference.refused},
                       {"function", function},
                       {"change", first_change(*input.mesh, *report.mine.mesh)}}));
  }
  if (report.mine.returned != "nil" && !report.mine.returned.empty()) {
    out.add(tr_format("the reference returns nil here ({reason}); yours returned {returned}",
                      {{"reason", report.reference.refused}, {"returned", tr(report.mine.returned)}}));
  }
  report.equal = !out.any();
  report.identical = report.equal;
}

}  // namespace meshedit::exercise_checks
