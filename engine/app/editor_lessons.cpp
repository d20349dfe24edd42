// EditorApp and lessons: showing what a lesson asks for, telling the lesson about the selection (keys and
// commands: editor_commands.cpp; clicks: editor_input.cpp), the lesson panel with hot reload, and the lesson's
// highlights and arrows over the mesh (its labels are placed with the id labels: id_labels.cpp).
//
// Whole or nothing, as opening a file (editor_files.cpp): open_lesson has the runner read and run the file first
// (LessonRunner::prepare), then makes the title and the message, and only then switches (take, the title, the
// message, the panel's watch) with steps that cannot fail. A lesson's mesh is copied before take_mesh switches to it.
// Going back to the list (show_lesson_list) makes the fresh runner before it clears the lesson's highlights and labels;
// a window titled after the lesson gets its title at start back (kStartTitle).
// A reload (reload_lesson: the panel's Reload, hot reload) is whole or nothing the same way: prepare_reload, the new
// title (while the window is titled after the lesson), then take and the title's swap.
#include <imgui.h>

#include "app/editor_app.h"
#include "app/element_highlight.h"
#include "app/mesh_loading.h"
#include "core/palette.h"
#include "document/exception_report.h"
#include "render/arrow_overlay.h"
#include "render/mesh_geometry.h"

namespace meshedit {
namespace {

constexpr float kHiddenArrowAlpha = 0.3f;  // a lesson's arrow where the mesh is in front of it

}  // namespace

void EditorApp::show_lesson_mesh(const HalfedgeMesh& mesh, bool fit, std::optional<UpAxis> up) {
  HalfedgeMesh copy = mesh;  // the one step that can fail: the window is as it was when it does
  // Core's primitives are Z-up; a mesh the lesson read from a file is shown as the lesson says its file is.
  if (up) file_up_axis_ = FileUpAxis{*up, UpAxisSource::Lesson};
  else file_up_axis_.reset();
  take_mesh(std::move(copy), std::string(), fit || mode_ != ViewMode::Mesh);
}

bool EditorApp::open_lesson(const std::filesystem::path& path) {
  LessonRunner::Prepared lesson;
  if (!lesson_->prepare(path, lesson)) {
    watch_lesson(lesson_panel_, lesson_->path());  // the file asked for: saving a fix loads it
    set_message_noexcept(doc_, Severity::Error, [&] { return lesson_->error(); });
    return false;
  }
  try {
    std::string title = window_title(lesson.title());  // "MeshEdit - Walking the half-edge mesh"
    std::string text = "lesson " + path.filename().string();
    // Nothing from here on can fail: the window switches to the lesson whole (what stops its first step is the
    // step's error, in the panel).
    up_axis_choice_ = UpAxisChoice::FromFile;  // the lesson's meshes are Z-up whatever the file before was turned to
    if (apply_up_axis()) fit_camera();
    lesson_->take(std::move(lesson));
    watch_lesson(lesson_panel_, lesson_->path());
    lesson_selection_ = selection_.selected;
    title_.swap(title);
    title_names_lesson_ = true;
    set_message(doc_, Severity::Info, std::move(text));
    return true;
  } catch (const std::exception& e) {
    report_exception(doc_, e);  // nothing was switched: the lesson that ran goes on, under its title
    return false;
  }
}

ReloadOutcome EditorApp::reload_lesson() {
  LessonRunner::Prepared lesson;
  if (!lesson_->prepare_reload(lesson)) {  // the version that ran goes on; the panel shows why
    return lesson_->out_of_memory() ? ReloadOutcome::OutOfMemory : ReloadOutcome::Failed;
  }
  try {
    std::string title = title_names_lesson_ ? window_title(lesson.title()) : std::string();
    // Nothing from here on can fail: the new version runs, under its title.
    lesson_->take(std::move(lesson), lesson_->current_step());
    if (title_names_lesson_) title_.swap(title);
    return ReloadOutcome::Reloaded;
  } catch (const std::exception& e) {
    report_exception(doc_, e);          // nothing was switched: the version that ran goes on, under its title
    return ReloadOutcome::OutOfMemory;  // std::bad_alloc, the only exception making the title throws
  }
}

std::unique_ptr<LessonRunner> EditorApp::make_lesson_runner() {
  auto runner = std::make_unique<LessonRunner>(*lesson_host_);
  runner->set_print([this](const std::string& line) { console_.append_output(line); });
  runner->set_student_folder(exercises_.folder());  // your_turn runs the Exercises tab's files
  return runner;
}

bool EditorApp::animating() const {
  if (hover_pending_ || edit_animator_.playing()) return true;
  return lesson_->step_state() == LessonRunner::StepState::Waiting &&
         lesson_->waiting_for().kind == LessonWait::Kind::Animation;
}

void EditorApp::update_lesson(float frame_ms) {
  if (!lesson_->loaded()) return;
  // A selection made any way (a click, the tables, N/T walking, a scripted `select`) is news for the lesson.
  if (selection_.selected != lesson_selection_) {
    lesson_selection_ = selection_.selected;
    if (selection_.selected.valid()) lesson_->deliver(LessonEvent::selection(selection_.selected));
  }
  const double dt = std::min(0.25, double(frame_ms) / 1000.0);  // a long stall must not skip an animation
  reload_if_changed(*lesson_, lesson_panel_, dt);
  if (lesson_->student_folder() != exercises_.folder()) lesson_->set_student_folder(exercises_.folder());
  lesson_->update(dt);
}

void EditorApp::take_lesson_request() {
  if (!lesson_panel_.requested) return;
  const std::filesystem::path requested = *lesson_panel_.requested;
  lesson_panel_.requested.reset();
  if (requested.empty()) {  // "Lessons": back to the list with a fresh runner
    show_lesson_list();
    return;
  }
  open_lesson(requested);
}

void EditorApp::show_lesson_list() {
  std::unique_ptr<LessonRunner> runner = make_lesson_runner();  // the one step that can fail: nothing changed yet
  std::string title = title_names_lesson_ ? std::string(kStartTitle) : std::string();
  // Nothing from here on can fail: the lesson's highlights and labels go with it, and a title naming it too.
  lesson_host_->clear_annotations();
  lesson_ = std::move(runner);
  if (title_names_lesson_) title_.swap(title);
  title_names_lesson_ = false;
}

void EditorApp::draw_lesson_marks() {
  const LessonMarks& marks = lesson_host_->marks();
  if (marks.highlights.empty() && marks.arrows.empty()) return;
  const HalfedgeMesh& mesh = doc_.mesh;
  Overlay overlay;
  overlay.on_top = true;
  for (const auto& [element, colour] : marks.highlights) {
    const glm::vec4 rgba(swatch_in_theme(colour, settings_.theme), 1.0f);  // a named swatch in this theme's shade
    add_highlight(overlay, mesh, element, rgba);
  }
  overlay_renderer_->draw(camera_, viewport(), overlay);
  draw_lesson_arrows();
}

void EditorApp::draw_lesson_arrows() {
  const LessonMarks& marks = lesson_host_->marks();
  if (marks.arrows.empty()) return;
  // Arrows (normals, directions) as solid where the mesh does not hide them, and faint where it does: a normal on the
  // far side of a closed mesh shows as what it is.
  Overlay hidden, seen;
  hidden.on_top = true;
  for (const LessonArrow& arrow : marks.arrows) {
    const glm::vec3 rgb = swatch_in_theme(arrow.colour, settings_.theme);
    add_arrow(hidden, arrow.from, arrow.to, camera_.eye(), glm::vec4(rgb, kHiddenArrowAlpha), 2.0f);
    add_arrow(seen, arrow.from, arrow.to, camera_.eye(), glm::vec4(rgb, 1.0f), 3.0f);
  }
  overlay_renderer_->draw(camera_, viewport(), hidden);
  overlay_renderer_->draw(camera_, viewport(), seen);
}

}  // namespace meshedit
