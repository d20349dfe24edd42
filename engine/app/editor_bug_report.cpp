// EditorApp and a bug report opened (see bug_report.h): a TA sees what the student saw. Everything the report holds is
// read and checked first (its text, its meshes with their ids, its selection); then its code files go into a folder
// of their own (never over the TA's own files), the Exercises tab runs that folder, the lesson opens at its step, and
// the mesh is shown with the student's ids, from the student's camera: when the mesh is still the state the student's
// last run left, that run is made again on its input (the Exercises tab then holds it, with its table and its replay),
// else the mesh as saved.
//
// The status line says it (and the console keeps it): the file, the MeshEdit that saved it, the folder of its code and
// what could not be done as the student had it.
//
// Invariants: never throws; a report that cannot be read (or one of whose meshes is not mesh records) is an Error that
// names the file, with the window as it was.
#include <exception>
#include <memory>
#include <new>
#include <optional>

#include "app/editor_app.h"
#include "app/mesh_loading.h"
#include "core/file_bytes.h"
#include "core/ids.h"
#include "core/mesh_records.h"
#include "core/translation.h"
#include "document/bug_report.h"
#include "document/exception_report.h"
#include "document/selection.h"
#include "exercise/exercise_registry.h"

namespace meshedit {
namespace {

// Everything of a report the window shows, read and checked before anything changes.
struct OpenedReport {
  BugReport report;
  std::optional<HalfedgeMesh> mesh;  // the mesh to show: the run's input when the run is made again
  ElementRef run_element;            // the element the run is given
  std::optional<Exercise> exercise;  // the run's exercise, when this window has it
  bool run_again = false;            // the report's mesh is the result of its run: make the run again
  ElementRef selected;               // the student's selection, when it is an element of the shown mesh
  std::filesystem::path lesson;      // the lesson file found here; empty when none (or not found)
  std::string notes;                 // what could not be done as the student had it
};

std::filesystem::path find_lesson(const std::string& name) {
  std::error_code error;
  for (const std::filesystem::path& candidate : {lessons_dir() / name, std::filesystem::path(name)}) {
    if (std::filesystem::is_regular_file(candidate, error)) return candidate;
  }
  return {};
}

OpenedReport read_report(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  OpenedReport opened{read_bug_report(path)};
  const BugReport& report = opened.report;
  if (report.operation) {
    opened.exercise = find_exercise(report.operation->exercise);
    if (!opened.exercise || !is_mesh_exercise(*opened.exercise)) {
      opened.exercise.reset();
      opened.notes +=
          "; " + tr_format("this MeshEdit has no exercise {exercise}", {{"exercise", report.operation->exercise}});
    }
  }
  opened.run_again = report.operation && report.operation->result_shown && opened.exercise;
  if (opened.run_again) {
    opened.mesh = parse_mesh_records(report.operation->input, name + " (its run's input)");
    opened.run_element = live_element(*opened.mesh, report.operation->element);
  } else if (!report.mesh.empty()) {
    opened.mesh = parse_mesh_records(report.mesh, name + " (its mesh)");
    opened.selected = live_element(*opened.mesh, report.selection);
  }
  if (!report.lesson.empty()) {
    opened.lesson = find_lesson(report.lesson);
    if (opened.lesson.empty()) {
      opened.notes += "; " + tr_format("its lesson {lesson} is not here", {{"lesson", report.lesson}});
    }
  }
  for (const std::string& field : report.left_out) {
    opened.notes += "; " + tr_format("left out (from a newer MeshEdit): {field}", {{"field", field}});
  }
  return opened;
}

// The report's code in a folder of its own, <temp>/meshedit report <name>/, emptied first so that no file of a report
// opened before under the same name stays beside it. Throws ReportError when it cannot be written.
std::filesystem::path write_code(const BugReport& report, const std::filesystem::path& path) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("meshedit report " + path.stem().string());
  std::error_code error;
  std::filesystem::remove_all(folder, error);
  std::filesystem::create_directories(folder, error);
  for (const StudentSource& file : report.files) {
    if (const std::string failure = write_file_bytes(folder / file.name, file.text); !failure.empty()) {
      throw ReportError(tr_format("{report}: its {file} could not be written into {folder}: {failure}",
                                  {{"report", path.filename().string()},
                                   {"file", file.name},
                                   {"folder", folder.string()},
                                   {"failure", failure}}));
    }
  }
  return folder;
}

}  // namespace

bool EditorApp::open_bug_report(const std::filesystem::path& path) {
  MeshDocument& doc = document_.doc();
  try {
    OpenedReport opened = read_report(path);
    const BugReport& report = opened.report;
    exercises_.session().finish_replay(doc);
    const std::filesystem::path folder = write_code(report, path);
    exercises_.session().set_folder(folder);
    if (!opened.lesson.empty() && lessons_.open(opened.lesson) && report.step > 0) {
      lessons_.runner().go_to(report.step - 1);
    }
    const std::string name = path.filename().string();
    if (opened.mesh) {
      show_mesh(std::move(*opened.mesh), name + (report.mesh_name.empty() ? "" : ": " + report.mesh_name));
    }
    if (opened.mesh && report.camera) {
      const BugReportCamera& seen = *report.camera;
      view_.choose_up_axis(seen.up == 'y' ? UpAxisChoice::Y : UpAxisChoice::Z);
      OrbitCamera& camera = view_.camera();
      camera.set_angles(seen.yaw, seen.pitch);
      camera.set_distance(seen.distance);
      camera.set_target(seen.target);
    }
    if (opened.exercise) exercises_.session().set_exercise(*opened.exercise);
    std::string message = tr_format("opened the bug report {file} saved by {app}: the student's code is in {folder}",
                                    {{"file", name}, {"app", report.app}, {"folder", folder.string()}}) +
                          opened.notes;
    ExerciseSession& session = exercises_.session();
    if (opened.run_again) {
      document_.selection().selected = opened.run_element;
      bring_exercises_tab_forward();
      exercises_.panel().bring_table_into_view = true;
      session.start_mine(doc, document_.selection());
      // The run's verdict comes in the status line when it ends; where it ended at once, it is said here.
      const std::string& label = report.operation->label;
      message += "; " + (session.running() ? tr_format("running its {operation} again", {{"operation", label}})
                                           : tr_format("its {operation} made again: {verdict}",
                                                       {{"operation", label}, {"verdict", doc.message.text}}));
    } else {
      document_.selection().selected = opened.selected;
    }
    document_.message(opened.notes.empty() ? Severity::Info : Severity::Warning, message);
    panels_.console().append_output(message);  // kept there once the run's verdict takes the status line
    return true;
  } catch (const std::bad_alloc& e) {
    report_exception(doc, e);
    return false;
  } catch (const std::exception& e) {
    document_.message(Severity::Error, e.what());
    return false;
  }
}

}  // namespace meshedit
