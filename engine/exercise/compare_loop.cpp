// compare_upsample: the student's Loop subdivision against the reference's, with the diagnoses of its usual
// mistakes (zero weights first: loop_zero_weight_diagnosis.h; flips: loop_flip_diagnosis.h) (see
// internal/exercise_checks.h).
#include "exercise/internal/exercise_checks.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/translation.h"
#include "exercise/internal/loop_boundary_diagnosis.h"
#include "exercise/internal/loop_flip_diagnosis.h"
#include "exercise/internal/loop_position_diagnosis.h"
#include "exercise/internal/loop_zero_weight_diagnosis.h"

namespace meshedit::exercise_checks {

namespace {

// Zero weights put vertices at the origin. Returns how many of yours are there; says so when `tell`.
size_t diagnose_zero_weights(const HalfedgeMesh& mine, const HalfedgeMesh& reference, double tolerance, bool tell,
                             Messages& out) {
  size_t at_origin = 0, reference_at_origin = 0;
  for (VertexId v : mine.vertices()) at_origin += within(mine.position(v), glm::dvec3(0.0), tolerance) ? 1 : 0;
  for (VertexId v : reference.vertices()) {
    reference_at_origin += within(reference.position(v), glm::dvec3(0.0), tolerance) ? 1 : 0;
  }
  if (tell && at_origin >= 2 && at_origin > reference_at_origin) {
    out.add(
        tr_format("{count} of your vertices are at (0, 0, 0): a weight that should not be zero is (in Lua 3 // 8 "
                  "is 0, an integer division; write 3 / 8)",
                  {{"count", std::to_string(at_origin)}}));
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
    const bool right = within(mine.position(v), reference.position(v), tolerance);
    if (!right && within(mine.position(v), before.position(v), tolerance)) ++unmoved;
  }
  if (unmoved > 0 && unmoved * 2 >= originals) {
    out.add(
        tr_format("{count} of the {total} original vertices kept their old positions: step 5 must move them to "
                  "the positions of step 1, (1 - n u) p + u (sum of the neighbours)",
                  {{"count", std::to_string(unmoved)}, {"total", std::to_string(originals)}}));
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
    out.add(
        tr_format("{count} of your vertices sit exactly on another one: were new positions written to the wrong "
                  "vertices? Keep them in a table indexed by v.id and move each vertex to its own",
                  {{"count", std::to_string(shared)}}));
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

}  // namespace

void compare_upsample(const ExerciseInput& input, ExerciseReport& report, Messages& out) {
  const HalfedgeMesh& before = *input.mesh;
  const HalfedgeMesh& mine = *report.mine.mesh;
  if (!report.reference.refused.empty()) {
    return compare_refusal(input, report, tr("subdivide this mesh"), "upsample", out);
  }
  if (mine.same_as(before)) {
    out.add(tr_format("your upsample changed nothing; the reference makes {faces} faces out of {before}",
                      {{"faces", std::to_string(report.reference.mesh->num_faces())},
                       {"before", std::to_string(before.num_faces())}}));
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
  if (report.equal) note_pointer_differences(report, tr("a correct subdivision"));
}

}  // namespace meshedit::exercise_checks
