// EditorApp and the lesson's your_turn (lesson/internal/lesson_your_turn.h): the lesson panel's "Show mine vs
// reference" (and the scripted action lesson-show-mine) shows the run the lesson judged wrong where the window compares
// runs.
//   - flip, split, normals, upsample: the your_turn's input mesh goes into the document as a lesson's show() puts it
//     there (ViewRoom::show_lesson_mesh: the view kept, fitted only when it was not the mesh view), its element is
//     selected, the Exercises tab takes the your_turn's exercise and runs mine on it (ExerciseSession::start_mine: the
//     changed pointers mine vs reference, the validation, the write-by-write replay), and the tab comes to the front of
//     the right column, scrolled so the changed-pointers table is in sight.
//   - a scripted exercise on points or a patch: the Exercises tab takes it with the your_turn's input (its control
//     points or patch and args, ExerciseSession::set_values_input), runs mine on it and comes to the front; the
//     document is left as it is.
//   - curve, patch: the input goes into the curve view (its points, its t, every level shown) or the patch view (the
//     patch, the probe at its (u, v)) with the view's "mine" switch on (document/bezier_mine.h).
//
// Invariants:
// - The file run is the lesson's: the Exercises tab's folder is the lesson's student folder (LessonRoom::update keeps
//   them the same), and the curve and patch views' "mine" is given that folder here. The run is on the input the
//   lesson's runs worked on (YourTurnVerdict::exercise_input), so the Exercises tab's report says what the lesson said.
// - Never throws: what stops it (memory running out) is an Error in the status line and the Check it returns. The input
//   is shown whole or not at all (the view's show_lesson_mesh, show_curve, show_patches) before anything else changes;
//   the run then reports as the Exercises tab's Run mine does (a file that no longer loads is its file:line in the tab
//   and the status line).
#include <algorithm>
#include <exception>
#include <new>

#include "app/editor_app.h"
#include "core/translation.h"
#include "document/exception_report.h"

namespace meshedit {

Check EditorApp::show_your_turn_mine() {
  MeshDocument& doc = document_.doc();
  ExerciseSession& exercises = exercises_.session();
  BezierMine& bezier_mine = view_.bezier_mine();
  const YourTurnVerdict* found = your_turn_to_show(lessons_.runner());
  if (!found) {
    const Check no = Check::no("no your_turn waits on a wrong answer: nothing to show beside the reference");
    set_message_noexcept(doc, Severity::Warning, [&] { return tr(no.reason); });
    return no;
  }
  try {
    const YourTurnVerdict verdict = *found;  // the runner's list may grow while the window changes
    const ExerciseInput& input = verdict.exercise_input;
    switch (verdict.exercise.kind()) {
      case ExerciseKind::CurveStep: {
        BezierCurve curve;
        for (const glm::dvec3& p : input.points) curve.control_points.emplace_back(p.x, p.y);
        view_.show_curve(curve);
        CurveEditorState& shown = view_.curve();
        set_t(shown, input.t);
        shown.levels_shown = std::max(0, int(shown.curve.control_points.size()) - 1);
        bezier_mine.set_folder(lessons_.runner().student_folder());
        bezier_mine.set_curve_on(true);
        set_message(doc, Severity::Info,
                    tr_format("mine: your {function} on {input}, every level",
                              {{"function", verdict.function}, {"input", verdict.input}}));
        return Check::yes();
      }
      case ExerciseKind::PatchEvaluate: {
        view_.show_patches({input.patch});
        set_probe(view_.patches(), input.u, input.v);
        bezier_mine.set_folder(lessons_.runner().student_folder());
        bezier_mine.set_patch_on(true);
        set_message(
            doc, Severity::Info,
            tr_format("mine: your {function} at {input}", {{"function", verdict.function}, {"input", verdict.input}}));
        return Check::yes();
      }
      case ExerciseKind::VertexNormal:
      case ExerciseKind::FlipEdge:
      case ExerciseKind::SplitEdge:
      case ExerciseKind::Upsample:
      case ExerciseKind::Scripted: break;
    }
    if (!is_mesh_exercise(verdict.exercise)) {  // a scripted exercise on points or a patch: the tab's text tables
      exercises.finish_replay(doc);
      exercises.set_exercise(verdict.exercise);
      exercises.set_values_input(input, "the lesson's input: " + verdict.input);
      bring_exercises_tab_forward();
      return exercises.start_mine(doc, document_.selection());
    }
    if (!input.mesh) return Check::no("the your_turn kept no mesh");  // every mesh your_turn keeps one
    exercises.finish_replay(doc);
    view_.show_lesson_mesh(*input.mesh, false);
    document_.selection().selected = input.element;  // none for upsample: the whole mesh
    exercises.set_exercise(verdict.exercise);
    bring_exercises_tab_forward();
    exercises_.panel().bring_table_into_view = true;
    return exercises.start_mine(doc, document_.selection());
  } catch (const std::bad_alloc& e) {
    report_exception(doc, e);
    return Check::no(kMemoryRanOut);  // fits std::string's inline buffer: no allocation
  } catch (const std::exception& e) {
    report_exception(doc, e);
    return Check::no(e.what());
  }
}

}  // namespace meshedit
