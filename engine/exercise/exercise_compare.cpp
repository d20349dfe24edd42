// compare() for every exercise (exercises.h): a run that failed is told with its hint; a run that finished goes to
// the checks of its kind of exercise (internal/exercise_checks.h), which the grader runs too
// (grade/exercise_expectation.h), so a failure there reads like the window.
#include <memory>
#include <string>

#include "core/translation.h"
#include "core/validate.h"
#include "exercise/exercises.h"
#include "exercise/internal/exercise_checks.h"
#include "exercise/internal/upsample_runaway.h"
#include "exercise/scripted_exercise.h"

namespace meshedit {
namespace {

using exercise_checks::Messages;

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
  switch (exercise.kind()) {
    case ExerciseKind::Upsample:
      return tr(
          "upsample did not finish: split only the edges of the original mesh (list them before the first "
          "split); a loop over all edges that re-reads mesh:num_edges() keeps finding the edges splits create. "
          "A loop that splits nothing never ends when what its condition waits for never changes");
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge:
    case ExerciseKind::VertexNormal:
      return tr(
          "it did not finish: a walk like `repeat ... h = h.twin.next until h == start` never comes back to "
          "its start when a pointer is wrong");
    default: {
      const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition();
      return scripted ? scripted->hint() : "";
    }
  }
}

std::string ExerciseReport::summary() const {
  if (equal) return tr("same as the reference");
  const MessageParts parts = {{"first", differences.empty() ? std::string() : differences.front()},
                              {"count", std::to_string(total_differences - 1)}};
  if (differences.empty()) {
    return total_differences > 1 ? tr_format("different ({count} more)", parts) : std::string(tr("different"));
  }
  return total_differences > 1 ? tr_format("different: {first} ({count} more)", parts)
                               : tr_format("different: {first}", parts);
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
    report.mine.error =
        tr_format("no mesh came back from {function}", {{"function", exercise_info(exercise).function}});
  }
  if (on_mesh && report.mine.mesh && !report.mine.validation) report.mine.validation = validate(*report.mine.mesh);
  if (!report.mine.ran) {
    add_run_failure(exercise, input, report, out);
    report.equal = false;
    return report;
  }
  switch (exercise.kind()) {
    case ExerciseKind::CurveStep: exercise_checks::compare_curve(input, report, out); break;
    case ExerciseKind::PatchEvaluate: exercise_checks::compare_patch(input, report, out); break;
    case ExerciseKind::VertexNormal: exercise_checks::compare_normal(input, report, out); break;
    case ExerciseKind::FlipEdge: exercise_checks::compare_flip(input, report, out); break;
    case ExerciseKind::SplitEdge: exercise_checks::compare_split(input, report, out); break;
    case ExerciseKind::Upsample: exercise_checks::compare_upsample(input, report, out); break;
    default:
      if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition()) {
        exercise_checks::compare_scripted(*scripted, input, report, out);
      }
  }
  return report;
}

}  // namespace meshedit
