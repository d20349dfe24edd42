// Help > Save a bug report (see bug_report_room.h): the report made of what the window shows, its dialog, and its
// file written and handed to the user.
#include "app/bug_report_room.h"

#include <imgui.h>

#include <exception>
#include <new>

#include "app/document_room.h"
#include "app/exercise_room.h"
#include "app/lesson_room.h"
#include "app/mesh_loading.h"
#include "app/view_room.h"
#include "app/window_host.h"
#include "core/app_version.h"
#include "core/file_bytes.h"
#include "core/ids.h"
#include "core/mesh_records.h"
#include "core/translation.h"
#include "document/exception_report.h"
#include "exercise/exercise_registry.h"
#include "ui/dialog.h"

namespace meshedit {
namespace {

// The lesson as the report names it: its path in the lessons folder, else its file name (a report never holds the
// folders of the student's disk).
std::string lesson_name(const std::filesystem::path& lesson) {
  std::error_code error;
  const std::filesystem::path relative = std::filesystem::relative(lesson, lessons_dir(), error);
  if (!error && !relative.empty() && relative.native().rfind("..", 0) != 0) return relative.generic_string();
  return lesson.filename().string();
}

std::optional<BugReportOperation> last_operation(const ExerciseSession& session, const MeshDocument& doc) {
  const std::optional<ExerciseRun>& run = session.last_run();
  if (!run || !run->mine || !run->input.mesh) return std::nullopt;
  BugReportOperation op;
  op.exercise = run->exercise.info().function;
  op.label = run->label;
  if (run->input.element.valid()) op.element = format_id(run->input.element);
  op.verdict = mine_verdict(run->report);
  op.result_shown = run->generation == doc.generation && run->version == doc.mesh.version();
  op.input = format_mesh_records(*run->input.mesh);
  return op;
}

}  // namespace

std::vector<std::filesystem::path> BugReportRoom::code_files() const {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path& folder = exercises_.session().folder();
  std::vector<Exercise> exercises(builtin_exercises().begin(), builtin_exercises().end());
  for (const Exercise& scripted : exercise_registry().scripted()) exercises.push_back(scripted);
  std::error_code error;
  for (const Exercise& exercise : exercises) {
    const std::filesystem::path file = folder / exercise.info().file;
    if (std::filesystem::is_regular_file(file, error)) files.push_back(file);
  }
  return files;
}

bool BugReportRoom::sends(const std::string& name) const {
  const auto found = unticked_.find(name);
  return found == unticked_.end() || !found->second;
}

BugReport BugReportRoom::make() const {
  BugReport report;
  report.app = kAppVersion;
  if (text_language() != Language::English) report.language = language_code(text_language());
  const LessonRunner& lesson = lessons_.runner();
  if (lesson.loaded()) {
    report.lesson = lesson_name(lesson.path());
    report.step = lesson.current_step() + 1;
  }
  const MeshDocument& doc = document_.doc();
  report.mesh_name = std::filesystem::path(doc.path).filename().string();
  if (doc.mesh.num_faces() > 0 || doc.mesh.num_vertices() > 0) report.mesh = format_mesh_records(doc.mesh);
  if (document_.selection().selected.valid()) report.selection = format_id(document_.selection().selected);
  report.operation = last_operation(exercises_.session(), doc);
  if (view_.mode() == ViewMode::Mesh) {
    const OrbitCamera& camera = view_.camera();
    report.camera = BugReportCamera{camera.up_axis() == UpAxis::Y ? 'y' : 'z', camera.yaw_degrees(),
                                    camera.pitch_degrees(), camera.distance(), camera.target()};
  }
  for (const std::filesystem::path& file : code_files()) {
    const std::string name = file.filename().string();
    if (sends(name)) report.files.push_back(read_student_source(file));
  }
  return report;
}

Check BugReportRoom::save(const std::filesystem::path& path) {
  try {
    const BugReport report = make();
    if (const std::string failure = write_file_bytes(path, format_bug_report(report)); !failure.empty()) {
      document_.message(Severity::Error, tr_format("the bug report was not saved: {why}", {{"why", failure}}));
      return Check::no(failure);
    }
    const std::string handed = host_hand_over(path);
    const std::string count = std::to_string(report.files.size());
    document_.message(Severity::Info,
                      handed.empty() ? tr_format("saved a bug report in {file}: send it to your TA (it holds the mesh, "
                                                 "the selection, your last run, {count} code files and the lesson's "
                                                 "step)",
                                                 {{"file", path.string()}, {"count", count}})
                                     : tr_format("saved a bug report ({handed}): send it to your TA (it holds the "
                                                 "mesh, the selection, your last run, {count} code files and the "
                                                 "lesson's step)",
                                                 {{"handed", handed}, {"count", count}}));
    shown_ = false;
    return Check::yes();
  } catch (const std::bad_alloc& e) {
    report_exception(document_.doc(), e);
    return Check::no(kMemoryRanOut);
  } catch (const std::exception& e) {
    document_.message(Severity::Error, tr_format("the bug report was not saved: {why}", {{"why", e.what()}}));
    return Check::no(e.what());
  }
}

void BugReportRoom::draw_dialog() {
  const float em = ImGui::GetFontSize();
  if (!begin_dialog(tr_label("Save a bug report"), shown_, ImVec2(40 * em, 19 * em))) return;
  ImGui::TextWrapped("%s", tr("One file for your TA, which opens MeshEdit as you see it now. It holds:"));
  const MeshDocument& doc = document_.doc();
  const ElementRef selected = document_.selection().selected;
  const std::string shown =
      tr_format("the mesh shown ({count} faces, every id as you see it) and the selection ({selection})",
                {{"count", std::to_string(doc.mesh.num_faces())},
                 {"selection", selected.valid() ? format_id(selected) : std::string(tr("none"))}});
  ImGui::BulletText("%s", shown.c_str());
  const std::optional<ExerciseRun>& run = exercises_.session().last_run();
  if (run && run->mine && run->input.mesh) {
    const std::string last = tr_format("your last run, {run}, and the mesh it was given", {{"run", run->label}});
    ImGui::BulletText("%s", last.c_str());
  } else {
    ImGui::BulletText("%s", tr("no run of your code (the Exercises tab has not run yours on a mesh)"));
  }
  const LessonRunner& lesson = lessons_.runner();
  if (lesson.loaded()) {
    const std::string step =
        tr_format("the lesson {lesson}, step {step}",
                  {{"lesson", lesson_name(lesson.path())}, {"step", std::to_string(lesson.current_step() + 1)}});
    ImGui::BulletText("%s", step.c_str());
  }
  const std::string files = tr_format("{version}, and the saved code files you tick:", {{"version", kAppVersion}});
  ImGui::BulletText("%s", files.c_str());
  // The files in three columns, so the Save row stays in sight at 1024x640.
  if (ImGui::BeginTable("code files", 3)) {
    for (const std::filesystem::path& file : code_files()) {
      ImGui::TableNextColumn();
      const std::string name = file.filename().string();
      bool send = sends(name);
      if (ImGui::Checkbox(name.c_str(), &send)) choose_file(name, send);
    }
    ImGui::EndTable();
  }
  ImGui::Separator();
  if (host_has_file_picker()) {
    if (ImGui::Button(tr_label("Download report.meshedit"))) {
      save(std::filesystem::temp_directory_path() / "report.meshedit");
    }
  } else {
    const bool entered = input_path(tr_label("file"), path_input_);
    ImGui::SameLine();
    if ((ImGui::Button(tr_label("Save")) || entered) && !path_input_.empty()) save(path_input_);
  }
  end_dialog(shown_);
}

}  // namespace meshedit
