// EditorApp and File > Check my work (check_room.h): the Check tab's "Open in Exercises" puts a failed test's input in
// the window where it compares runs. The input mesh (with every record and id the grader had: grade/failing_case.h)
// becomes a new document named after the test, the element the student's function was given is selected (the ids are
// the ones the grader's words name), the Exercises tab takes the test's exercise and runs the student's saved function
// on it, and comes to the front.
//
// Invariants: never throws; a case whose mesh cannot be built or whose exercise this window does not know is a Warning
// in the status line with the document as it was (show_mesh is whole or nothing).
#include <exception>
#include <new>

#include "app/editor_app.h"
#include "core/translation.h"
#include "document/exception_report.h"
#include "exercise/exercise_registry.h"
#include "grade/failing_case.h"

namespace meshedit {

Check EditorApp::open_failing_case(size_t row) {
  MeshDocument& doc = document_.doc();
  try {
    const FailingCase* failing = check_.failing_case(row);
    if (!failing) {
      const char* why = "this test has no input to open in the Exercises tab";
      document_.message(Severity::Warning, tr(why));
      return Check::no(why);
    }
    const std::optional<Exercise> exercise = find_exercise(failing->exercise);
    if (!exercise || !is_mesh_exercise(*exercise)) {
      const char* why = "the Exercises tab has no exercise {exercise}";
      const MessageParts parts{{"exercise", failing->exercise}};
      document_.message(Severity::Warning, tr_format(why, parts));
      return Check::no(fill_template(why, parts));
    }
    HalfedgeMesh mesh = case_mesh(*failing);
    const ElementRef element = case_element(mesh, *failing);
    ExerciseSession& exercises = exercises_.session();
    exercises.finish_replay(doc);
    show_mesh(std::move(mesh), "test " + check_.test_name(row) + ": its input");
    document_.selection().selected = element;
    exercises.set_exercise(*exercise);
    bring_exercises_tab_forward();
    exercises_.panel().bring_table_into_view = true;
    return exercises.start_mine(doc, document_.selection());
  } catch (const std::bad_alloc& e) {
    report_exception(doc, e);
    return Check::no(kMemoryRanOut);
  } catch (const std::exception& e) {
    report_exception(doc, e);
    return Check::no(e.what());
  }
}

}  // namespace meshedit
