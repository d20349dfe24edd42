// A bug report's operation run again headless (see bug_report.h): the input mesh read back with its ids, the report's
// file of the exercise loaded as the window loads it (run_student_call, one fresh StudentCode), the reference run, and
// the comparison said in the window's words (mine_verdict, exercise_session.h) beside the one the report holds.
#include <memory>
#include <string>

#include "core/ids.h"
#include "core/mesh_records.h"
#include "core/validate.h"
#include "core/value_format.h"
#include "document/bug_report.h"
#include "document/exercise_session.h"
#include "document/selection.h"
#include "exercise/exercise_registry.h"

namespace meshedit {
namespace {

// The report's own lines: who saved it, the lesson, the mesh, the selection, the files.
std::string describe_report(const BugReport& report, const std::string& name) {
  std::string text =
      name + ": a bug report saved by " + (report.app.empty() ? "an unnamed MeshEdit" : report.app) + "\n";
  if (!report.lesson.empty()) text += "  lesson " + report.lesson + ", step " + std::to_string(report.step) + "\n";
  if (!report.mesh.empty()) {
    const HalfedgeMesh mesh = parse_mesh_records(report.mesh, name + " (its mesh)");
    const ValidationReport validation = validate(mesh);
    text += "  the mesh " + (report.mesh_name.empty() ? std::string("shown") : report.mesh_name) + ": " +
            plural(mesh.num_faces(), "face", "faces") + ", " +
            (validation.ok() ? std::string("valid") : "not valid: " + validation.summary()) + "\n";
  }
  if (!report.selection.empty()) text += "  selected: " + report.selection + "\n";
  if (!report.files.empty()) {
    text += "  the student's code:";
    for (const StudentSource& file : report.files) text += " " + file.name;
    text += "\n";
  }
  for (const std::string& field : report.left_out) text += "  left out (saved by a newer MeshEdit): " + field + "\n";
  return text;
}

const StudentSource* file_named(const BugReport& report, const std::string& file) {
  for (const StudentSource& source : report.files) {
    if (source.name == file) return &source;
  }
  return nullptr;
}

}  // namespace

BugReportReplay replay_bug_report(const BugReport& report, const std::string& name, const LuaLimits& limits) {
  BugReportReplay replay;
  replay.text = describe_report(report, name);
  if (!report.operation) {
    replay.text += "it holds no run of the student's function to replay\n";
    return replay;
  }
  const BugReportOperation& op = *report.operation;
  const std::optional<Exercise> exercise = find_exercise(op.exercise);
  if (!exercise || !is_mesh_exercise(*exercise)) {
    throw ReportError(name + ": its operation runs " + op.exercise + ", which this MeshEdit has no mesh exercise of");
  }
  const std::string file = exercise->info().file;
  const StudentSource* source = file_named(report, file);
  if (!source) {
    replay.text += "its last operation (" + op.label + ") ran " + file + ", which the student did not send\n";
    return replay;
  }
  auto mesh = std::make_shared<HalfedgeMesh>(parse_mesh_records(op.input, name + " (the operation's input)"));
  const ElementRef element = op.element.empty() ? ElementRef{} : live_element(*mesh, op.element);
  if (!op.element.empty() && !element.valid()) {
    throw ReportError(name + ": its operation's element " + op.element + " is not a live element of its input");
  }
  StudentCall call;
  call.exercise = *exercise;
  call.input = element.valid() ? ExerciseInput::element_of(mesh, element) : ExerciseInput::whole_mesh(mesh);
  call.limits = limits;
  call.files.push_back(*source);
  StudentCallResult result = run_student_call(call);
  std::string verdict;
  std::string differences;  // the window's list under the verdict, the likely mistake first
  if (!result.load_error.empty()) {
    verdict = result.load_error;
  } else if (!result.thrown.empty()) {
    verdict = result.thrown;
  } else {
    const ExerciseReport compared =
        compare(*exercise, call.input, std::move(result.outcome), run_reference(*exercise, call.input));
    verdict = mine_verdict(compared);
    replay.equal = compared.equal;
    for (const std::string& difference : compared.differences) differences.append("    ").append(difference) += "\n";
    if (compared.total_differences > compared.differences.size()) {
      differences += "    (" + std::to_string(compared.total_differences) + " differences in all)\n";
    }
  }
  replay.replayed = true;
  replay.same_verdict = verdict == op.verdict;
  replay.text += "replayed " + op.label + " (" + call.input.describe(*exercise) + ") with the report's " + file +
                 "\n  " + verdict + "\n" + differences;
  replay.text += replay.same_verdict ? "the same diagnosis as the student's window\n"
                                     : "the student's window said: " + op.verdict +
                                           "\n(not the same: this MeshEdit or the reference differs from the one "
                                           "that saved the report)\n";
  return replay;
}

}  // namespace meshedit
