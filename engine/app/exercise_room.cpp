// ExerciseRoom (see exercise_room.h): the Exercises tab, and the "Your code" tab: the active exercise's student file in
// the window's editor (ui/student_editor.h), saved where the Exercises tab's StudentFile watches it, so the next run of
// mine, its comparison and its replay run the new code.
#include "app/exercise_room.h"

#include <algorithm>
#include <new>

#include <imgui.h>

#include "app/document_room.h"
#include "app/window_host.h"
#include "core/file_bytes.h"
#include "core/translation.h"
#include "document/exception_report.h"
#include "io/file_access.h"

namespace meshedit {

StudentEdit& ExerciseRoom::student_edit() {
  const auto [shown, first_time] = student_files_.try_emplace(session_.file());
  StudentEdit& edit = shown->second.edit;
  edit.follow(session_.file());
  if (first_time) take_back_student_draft(edit);
  return edit;
}

void ExerciseRoom::take_back_student_draft(StudentEdit& edit) {
  const std::string name = edit.path().filename().string();
  if (name.empty()) return;
  std::optional<std::string> draft = host_kept_draft(name);
  if (draft && edit.take_draft(std::move(*draft))) {
    document_.message(Severity::Info, tr_format("your unsaved changes to {file} are back in Your code: Save keeps them",
                                                {{"file", name}}));
  }
}

void ExerciseRoom::keep_student_drafts() {
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
      document_.message(Severity::Warning, tr_format("your unsaved changes to {file} are not kept: {why}",
                                                     {{"file", name}, {"why", failure}}));
    }
  }
}

std::string ExerciseRoom::student_code_error() {
  session_.ensure_loaded();  // a stat of the file when nothing changed
  if (!session_.load_error().empty()) return session_.load_error();
  const std::optional<ExerciseRun>& run = session_.last_run();
  if (run && run->mine && run->exercise == session_.exercise()) return run->report.mine.error;
  return "";
}

std::optional<size_t> ExerciseRoom::student_code_error_line() {
  return error_line_in(student_code_error(), session_.file().filename().string());
}

Check ExerciseRoom::save_student_code() {
  try {
    StudentEdit& edit = student_edit();
    const std::string name = edit.path().filename().string();
    if (Check saved = edit.save(); !saved) {
      document_.message(Severity::Error, tr_format("not saved: {why}", {{"why", saved.reason}}));
      return saved;
    }
    host_drop_draft(name);
    std::string kept = host_keep_file(edit.path());
    if (!session_.ensure_loaded()) {
      document_.message(Severity::Warning, tr_format("saved {file}, which does not load: {error}",
                                                     {{"file", name}, {"error", session_.load_error()}}));
    } else {
      document_.message(Severity::Info, kept.empty() ? tr_format("saved {file}: Run mine runs it", {{"file", name}})
                                                     : tr_format("saved {file} ({kept}): Run mine runs it",
                                                                 {{"file", name}, {"kept", kept}}));
    }
    return Check::yes();
  } catch (const std::bad_alloc& e) {
    report_exception(document_.doc(), e);
    return Check::no(kMemoryRanOut);
  }
}

std::string ExerciseRoom::unsaved_student_files() const {
  std::string names;
  for (const auto& [path, file] : student_files_) {
    if (file.edit.dirty()) names += (names.empty() ? "" : ", ") + path.filename().string();
  }
  return names;
}

bool ExerciseRoom::any_unsaved() const {  // allocates nothing: asked as the window closes, outside the frame's guard
  return std::any_of(student_files_.begin(), student_files_.end(),
                     [](const auto& shown) { return shown.second.edit.dirty(); });
}

Check ExerciseRoom::save_unsaved() {
  for (auto& [path, file] : student_files_) {
    if (!file.edit.dirty()) continue;
    if (Check saved = file.edit.save(); !saved) return saved;
  }
  return Check::yes();
}

ExerciseRoom::Received ExerciseRoom::take_received_file(const std::filesystem::path& received) {
  const std::filesystem::path target = session_.folder() / received.filename();
  std::error_code error;
  if (lowercase_extension(received) != ".lua" || !std::filesystem::is_regular_file(target, error)) {
    return Received::NotStudentFile;
  }
  const std::string name = target.filename().string();
  FileBytes bytes = read_file_bytes(received, kMaxStudentFileBytes);
  std::string failure = bytes.ok() ? write_file_bytes(target, bytes.bytes) : bytes.error;
  if (!failure.empty()) {
    document_.message(Severity::Error,
                      tr_format("{file} from this computer was not taken: {why}", {{"file", name}, {"why", failure}}));
    return Received::Refused;
  }
  host_drop_draft(name);
  const std::string kept = host_keep_file(target);
  if (const auto shown = student_files_.find(target); shown != student_files_.end()) shown->second.edit.reread();
  const bool loads = session_.file() != target || session_.ensure_loaded();
  const MessageParts parts = {{"file", name}, {"kept", kept}, {"error", loads ? "" : session_.load_error()}};
  const char* replaced =
      loads ? (kept.empty() ? "{file} from this computer replaced your {file}"
                            : "{file} from this computer replaced your {file} ({kept})")
            : (kept.empty() ? "{file} from this computer replaced your {file}, which does not load: {error}"
                            : "{file} from this computer replaced your {file} ({kept}), which does not load: {error}");
  document_.message(loads ? Severity::Info : Severity::Warning, tr_format(replaced, parts));
  return Received::Taken;
}

void ExerciseRoom::download_student_code() {
  StudentEdit& edit = student_edit();
  if (edit.dirty() && !save_student_code()) return;
  try {
    const std::string words = host_hand_over(edit.path());
    document_.message(Severity::Info,
                      words.empty() ? tr_format("your file is {file}", {{"file", edit.path().string()}}) : words);
  } catch (const std::exception& e) {
    report_exception(document_.doc(), e);
  }
}

bool ExerciseRoom::exercises_just_opened() {
  const bool opened = panel_.open && !exercises_were_open_;
  exercises_were_open_ = panel_.open;
  return opened;
}

void ExerciseRoom::draw_exercises_tab(UiProbe& probe) {
  probe.record_last_item("exercises-tab");  // the tab is in front (tests)
  draw_exercise_panel_contents(session_, panel_, document_.doc(), document_.selection());
}

void ExerciseRoom::draw_student_code_tab(UiProbe& probe) {
  probe.record_last_item("code-tab");  // the tab is in front (tests)
  const std::string error = student_code_error();
  const std::optional<size_t> line = error_line_in(error, session_.file().filename().string());
  if (draw_student_editor_contents(student_edit(), editor_, error, line)) save_student_code();
}

}  // namespace meshedit
