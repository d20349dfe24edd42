// The checks compare() (exercises.h) is made of, one file per kind of exercise, and what they share (internal to
// engine/exercise): the capped list of messages a verdict fills, and the checks every mesh exercise runs.
//
// Each compare_KIND fills `report` (equal, identical, notes) and adds its differences to `out`, diagnoses that name
// the likely mistake before the raw differences:
//   compare_curve      compare_curve.cpp      one de Casteljau step: a dropped last point, swapped weights
//   compare_patch      compare_patch.cpp      a patch point: u and v swapped
//   compare_normal     compare_normal.cpp     a vertex normal: what a wrong one is made of (normal_diagnosis.h)
//   compare_flip       compare_mesh_ops.cpp   flip_edge: created or deleted elements, the returned edge
//   compare_split      compare_mesh_ops.cpp   split_edge: where the new vertex is, which pointers were forgotten
//   compare_upsample   compare_loop.cpp       Loop: zero weights, unmoved originals, misplaced positions, flips
//   compare_scripted   compare_scripted.cpp   exercises defined in Lua, on a mesh or on values (value_compare.h)
//
// Tolerances: points within points_tolerance of the input, normals within 1e-9, meshes within mesh_tolerance of the
// input (core/mesh_compare.h: 1e-9 scaled by the input's size); "identical" is bit for bit and, for meshes, pointer
// for pointer (compare_meshes_exact with tolerance 0).
#pragma once

#include <cstring>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/mesh_compare.h"
#include "core/value_format.h"
#include "exercise/exercises.h"
#include "exercise/scripted_exercise.h"

namespace meshedit::exercise_checks {

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

inline std::string position_text(const glm::dvec3& p) { return format_position(p); }
inline bool bitwise_equal(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }
inline bool within(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
  return glm::distance(a, b) <= tolerance;
}

// ---- the checks of every mesh exercise (compare_mesh_checks.cpp) ----------------------------------------------
// The validator's problems after the student's `function`, the first one introduced.
void add_validation(const ExerciseReport& report, const char* function, Messages& out);
// When a face cycle is broken: the next pointers the reference rewrote and the student's left as they were.
void add_unchanged_next(const ExerciseReport& report, const HalfedgeMesh& before, const char* function, Messages& out);
// "h3.next was h4, is h7": the first field that differs, or "".
std::string first_change(const HalfedgeMesh& before, const HalfedgeMesh& after);
// The differences of a surface comparison, those past its cap counted.
void add_comparison(const MeshComparison& c, Messages& out);
// Pointer-level differences when the surface is right, as notes (sets report.identical).
void note_pointer_differences(ExerciseReport& report, const std::string& what);
// A boundary vertex whose halfedge is not on the boundary loop: accepted, with a note.
void note_boundary_convention(ExerciseReport& report);
// A flip or a split that touched more of a big mesh than its edge's neighbourhood (exercise_locality.h).
void add_locality(Exercise exercise, const ExerciseInput& input, const ExerciseReport& report, Messages& out);
// Refused by the reference (`what` is "flip e3"...): the student's must change nothing and return nil.
void compare_refusal(const ExerciseInput& input, ExerciseReport& report, const std::string& what, const char* function,
                     Messages& out);

// ---- one per kind of exercise ------------------------------------------------------------------------------
void compare_curve(const ExerciseInput& input, ExerciseReport& report, Messages& out);
void compare_patch(const ExerciseInput& input, ExerciseReport& report, Messages& out);
void compare_normal(const ExerciseInput& input, ExerciseReport& report, Messages& out);
void compare_flip(const ExerciseInput& input, ExerciseReport& report, Messages& out);
void compare_split(const ExerciseInput& input, ExerciseReport& report, Messages& out);
void compare_upsample(const ExerciseInput& input, ExerciseReport& report, Messages& out);
void compare_scripted(const ScriptedExercise& scripted, const ExerciseInput& input, ExerciseReport& report,
                      Messages& out);

}  // namespace meshedit::exercise_checks
