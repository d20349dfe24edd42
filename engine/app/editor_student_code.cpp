// The "Your code" tab: the active exercise's student file in the window's editor (ui/student_editor.h), saved where
// the Exercises tab's StudentFile watches it, so the next run of mine, its comparison and its replay run the new code.
// Unsaved text is never run; in a page it is kept as a draft (window_host.h) and taken back after a reload.
#include <algorithm>
#include <new>

#include <imgui.h>

#include "app/editor_app.h"
#include "app/window_host.h"
#include "core/file_bytes.h"
#include "document/exception_report.h"
#include "io/file_access.h"

namespace meshedit {

StudentEdit& EditorApp::student_edit() {
  const auto [shown, first_time] = student_files_.try_emplace(exercises_.file());
  StudentEdit& edit = shown->second.edit;
  edit.follow(exercises_.file());
  if (first_time) take_back_student_draft(edit);
  return edit;
}

void EditorApp::take_back_student_draft(StudentEdit& edit) {
  const std::string name = edit.path().filename().string();
  if (name.empty()) return;
  std::optional<std::string> draft = host_kept_draft(name);
  if (draft && edit.take_draft(std::move(*draft))) {
    message(Severity::Info, "your unsaved changes to " + name + " are back in Your code: Save keeps them");
  }
}

void EditorApp::keep_student_drafts() {
  const double now = ImGui::GetTime();
  for (auto& [path, file] : student_files_) {
    if (file.edit.changes() != file.changes_seen) {
      file.changes_seen = file.edit.changes();
      file.changed_at = now;
    }
    if (file.changes_kept == file.changes_seen || now - file.changed_at < 0.5 || path.empty()) continue;
    file.changes_kept = file.changes_seen;
    const std::string name = path.filename().string();
    if (!file.edit.dirty()) {
      host_drop_draft(name);
    } else if (const std::string failure = host_keep_draft(name, file.edit.text()); !failure.empty()) {
      message(Severity::Warning, "your unsaved changes to " + name + " are not kept: " + failure);
    }
  }
}

std::string EditorApp::student_code_error() {
  exercises_.ensure_loaded();  // a stat of the file when nothing changed
  if (!exercises_.load_error().empty()) return exercises_.load_error();
  const std::optional<ExerciseRun>& run = exercises_.last_run();
  if (run && run->mine && run->exercise == exercises_.exercise()) return run->report.mine.error;
  return "";
}

std::optional<size_t> EditorApp::student_code_error_line() {
  return error_line_in(student_code_error(), exercises_.file().filename().string());
}

Check EditorApp::save_student_code() {
  try {
    StudentEdit& edit = student_edit();
    const std::string name = edit.path().filename().string();
    if (Check saved = edit.save(); !saved) {
      message(Severity::Error, "not saved: " + saved.reason);
      return saved;
    }
    host_drop_draft(name);
    std::string kept = host_keep_file(edit.path());
    if (!exercises_.ensure_loaded()) {
      message(Severity::Warning, "saved " + name + ", which does not load: " + exercises_.load_error());
    } else {
      message(Severity::Info, "saved " + name + (kept.empty() ? "" : " (" + kept + ")") + ": Run mine runs it");
    }
    return Check::yes();
  } catch (const std::bad_alloc& e) {
    report_exception(doc_, e);
    return Check::no(kMemoryRanOut);
  }
}

std::string EditorApp::unsaved_student_files() const {
  std::string names;
  for (const auto& [path, file] : student_files_) {
    if (file.edit.dirty()) names += (names.empty() ? "" : ", ") + path.filename().string();
  }
  return names;
}

bool EditorApp::may_close() {  // called outside the frame's guard: allocates nothing
  const bool unsaved = std::any_of(student_files_.begin(), student_files_.end(),
                                   [](const auto& shown) { return shown.second.edit.dirty(); });
  if (close_confirmed_ || !host_files_on_users_disk() || !unsaved) return true;
  quit_requested_ = false;
  show_unsaved_code_ = true;
  return false;
}

void EditorApp::answer_unsaved_code(UnsavedCodeAnswer answer) {
  show_unsaved_code_ = false;
  if (answer == UnsavedCodeAnswer::KeepEditing) return;
  if (answer == UnsavedCodeAnswer::SaveAndQuit) {
    for (auto& [path, file] : student_files_) {
      if (!file.edit.dirty()) continue;
      if (Check saved = file.edit.save(); !saved) {
        message(Severity::Error, "not saved, so the window stays open: " + saved.reason);
        return;
      }
    }
  }
  close_confirmed_ = true;
  quit_requested_ = true;
}

void EditorApp::receive_files(const std::vector<std::string>& paths) {
  std::vector<std::string> others;
  for (const std::string& path : paths) {
    const std::filesystem::path received(path);
    const std::filesystem::path target = exercises_.folder() / received.filename();
    std::error_code error;
    if (lowercase_extension(received) != ".lua" || !std::filesystem::is_regular_file(target, error)) {
      others.push_back(path);
      continue;
    }
    const std::string name = target.filename().string();
    FileBytes bytes = read_file_bytes(received, kMaxStudentFileBytes);
    std::string failure = bytes.ok() ? write_file_bytes(target, bytes.bytes) : bytes.error;
    if (!failure.empty()) {
      message(Severity::Error, name + " from this computer was not taken: " + failure);
      continue;
    }
    host_drop_draft(name);
    const std::string kept = host_keep_file(target);
    if (const auto shown = student_files_.find(target); shown != student_files_.end()) shown->second.edit.reread();
    show_student_code();
    const bool loads = exercises_.file() != target || exercises_.ensure_loaded();
    message(loads ? Severity::Info : Severity::Warning,
            name + " from this computer replaced your " + name + (kept.empty() ? "" : " (" + kept + ")") +
                (loads ? "" : ", which does not load: " + exercises_.load_error()));
  }
  if (!others.empty()) open_dropped(others);
}

void EditorApp::download_student_code() {
  StudentEdit& edit = student_edit();
  if (edit.dirty() && !save_student_code()) return;
  try {
    const std::string words = host_hand_over(edit.path());
    message(Severity::Info, words.empty() ? "your file is " + edit.path().string() : words);
  } catch (const std::exception& e) {
    report_exception(doc_, e);
  }
}

void EditorApp::show_student_code() {
  student_editor_.open = true;
  settings_.layout.right_open = true;
  select_tab_ = RightTab::Code;
}

void EditorApp::open_student_code_with_exercises() {
  if (exercise_panel_.open && !exercises_were_open_ && !host_files_on_users_disk()) student_editor_.open = true;
  exercises_were_open_ = exercise_panel_.open;
}

void EditorApp::draw_student_code_tab() {
  probe_.record_last_item("code-tab");  // the tab is in front (tests)
  const std::string error = student_code_error();
  const std::optional<size_t> line = error_line_in(error, exercises_.file().filename().string());
  if (draw_student_editor_contents(student_edit(), student_editor_, error, line)) save_student_code();
}

}  // namespace meshedit
