// LessonRoom (see lesson_room.h): opening, reloading and leaving a lesson, whole or nothing, and what the lesson hears
// from the window each frame. The lesson's highlights, arrows and labels are drawn by the view (view_marks.cpp,
// id_labels.cpp) from the host's marks.
#include "app/lesson_room.h"

#include <algorithm>

#include "app/document_room.h"
#include "app/exercise_room.h"
#include "app/mesh_loading.h"
#include "app/view_room.h"
#include "app/window_host.h"
#include "core/translation.h"
#include "document/exception_report.h"
#include "document/student_call_work.h"

namespace meshedit {

LessonRoom::LessonRoom(DocumentRoom& document, ViewRoom& view, ExerciseRoom& exercises, Print print)
    : document_(document), view_(view), exercises_(exercises), print_(std::move(print)), host_(document, view) {
  runner_ = make_runner();
  panel_.lessons_dir = lessons_dir();
  panel_.lessons_editable = host_files_on_users_disk();
  refresh_lessons(panel_);
  panel_.reload = [this](LessonRunner&) { return reload(); };
}

std::unique_ptr<LessonRunner> LessonRoom::make_runner() {
  auto runner = std::make_unique<LessonRunner>(host_);
  runner->set_print(print_);
  runner->set_student_folder(exercises_.session().folder());  // your_turn runs the Exercises tab's files
  // Beside the frames (a thread, or the page's Web Worker): a runaway your_turn never holds the window.
  runner->set_student_code_in_background(StudentCallWork::off_the_callers_thread());
  return runner;
}

bool LessonRoom::open(const std::filesystem::path& path) {
  follow_student_folder();  // the first step's your_turn runs the Exercises tab's files as they are now
  LessonRunner::Prepared lesson;
  if (!runner_->prepare(path, lesson)) {
    watch_lesson(panel_, runner_->path());  // the file asked for: saving a fix loads it
    set_message_noexcept(document_.doc(), Severity::Error, [&] { return runner_->error(); });
    return false;
  }
  try {
    std::string title = DocumentRoom::window_title(lesson.title());  // "MeshEdit - Walking the half-edge mesh"
    std::string text = tr_format("lesson {file}", {{"file", path.filename().string()}});
    // Nothing from here on can fail: the window switches to the lesson whole (what stops its first step is the
    // step's error, in the panel).
    view_.follow_lesson_up_axis();
    runner_->take(std::move(lesson));
    watch_lesson(panel_, runner_->path());
    selection_heard_ = document_.selection().selected;
    document_.take_title(title, true);
    set_message(document_.doc(), Severity::Info, std::move(text));
    return true;
  } catch (const std::exception& e) {
    report_exception(document_.doc(), e);  // nothing was switched: the lesson that ran goes on, under its title
    return false;
  }
}

ReloadOutcome LessonRoom::reload() {
  LessonRunner::Prepared lesson;
  if (!runner_->prepare_reload(lesson)) {  // the version that ran goes on; the panel shows why
    return runner_->out_of_memory() ? ReloadOutcome::OutOfMemory : ReloadOutcome::Failed;
  }
  try {
    const bool renames = document_.title_names_lesson();
    std::string title = renames ? DocumentRoom::window_title(lesson.title()) : std::string();
    // Nothing from here on can fail: the new version runs, under its title.
    runner_->take(std::move(lesson), runner_->current_step());
    if (renames) document_.take_title(title, true);
    return ReloadOutcome::Reloaded;
  } catch (const std::exception& e) {
    report_exception(document_.doc(), e);  // nothing was switched: the version that ran goes on, under its title
    return ReloadOutcome::OutOfMemory;     // std::bad_alloc, the only exception making the title throws
  }
}

void LessonRoom::show_list() {
  std::unique_ptr<LessonRunner> runner = make_runner();  // the one step that can fail: nothing changed yet
  const bool renames = document_.title_names_lesson();
  std::string title = renames ? std::string(DocumentRoom::kStartTitle) : std::string();
  // Nothing from here on can fail: the lesson's highlights and labels go with it, and a title naming it too.
  host_.clear_annotations();
  runner_ = std::move(runner);
  if (renames) document_.take_title(title, false);
}

void LessonRoom::update(float frame_ms) {
  follow_student_folder();
  if (!runner_->loaded()) return;
  const Selection& selection = document_.selection();
  if (selection.selected != selection_heard_) {
    selection_heard_ = selection.selected;
    if (selection.selected.valid()) runner_->deliver(LessonEvent::selection(selection.selected));
  }
  const double dt = std::min(0.25, double(frame_ms) / 1000.0);  // a long stall must not skip an animation
  reload_if_changed(*runner_, panel_, dt);
  runner_->update(dt);
}

void LessonRoom::follow_student_folder() {
  const std::filesystem::path& folder = exercises_.session().folder();
  if (runner_->student_folder() != folder) runner_->set_student_folder(folder);
}

void LessonRoom::take_request() {
  if (!panel_.requested) return;
  const std::filesystem::path requested = *panel_.requested;
  panel_.requested.reset();
  if (requested.empty()) {  // "Lessons": back to the list with a fresh runner
    show_list();
    return;
  }
  open(requested);
}

void LessonRoom::tell_key(int key, KeyMods mods) {
  if (!runner_->loaded()) return;
  const std::string name = lesson_key_name(key, mods);
  if (!name.empty()) runner_->deliver(LessonEvent::key(name));
}

void LessonRoom::tell_command(const char* name) {
  if (runner_->loaded()) runner_->deliver(LessonEvent::command(name));
}

void LessonRoom::tell_click(ElementRef element) {
  if (runner_->loaded()) runner_->deliver(LessonEvent::click(element));
}

void LessonRoom::tell_curve_click() {
  // A click on the curve answers a lesson's pick on the curve; within the pick radius in pixels it is on the curve.
  CurveEditorState& curve = view_.curve();
  if (curve.clicked && runner_->loaded()) {
    runner_->deliver(LessonEvent::curve_click(*curve.clicked, kCurvePickRadius / curve.view.scale));
  }
  curve.clicked.reset();
}

bool LessonRoom::animating() const {
  return runner_->step_state() == LessonRunner::StepState::Waiting &&
         runner_->waiting_for().kind == LessonWait::Kind::Animation;
}

}  // namespace meshedit
