// ExerciseRoom: the exercises and the student's code. Owns the Exercises tab's session (the active exercise, the
// student's folder, the last runs and the write-by-write replay: document/exercise_session.h) and its panel state, and
// the "Your code" tab: the student files the window's editor has shown, each with its unsaved text and its draft.
//
// Invariants:
// - Unsaved text is never run: a file's editor text reaches the exercises only by save_student_code (or a file the
//   page's student picked), which the session then loads as any save of the file (an Info, or a Warning with the
//   file:line of the error when it does not load).
// - Unsaved text stays with its file while the student switches exercises; in a page each edited file's text is kept
//   as a draft once it rested half a second (host_keep_draft, window_host.h), forgotten once clean again, and taken
//   back the first time the editor shows the file.
// - Every outcome is reported in the document's status line (DocumentRoom::message); nothing here throws but memory
//   running out, which save_student_code reports too.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "core/check.h"
#include "document/exercise_session.h"
#include "document/student_edit.h"
#include "ui/element_link.h"
#include "ui/exercise_panel.h"
#include "ui/student_editor.h"

namespace meshedit {

class DocumentRoom;

class ExerciseRoom {
 public:
  explicit ExerciseRoom(DocumentRoom& document) : document_(document) {}

  ExerciseSession& session() { return session_; }
  const ExerciseSession& session() const { return session_; }
  ExercisePanelState& panel() { return panel_; }
  StudentEditorState& editor() { return editor_; }

  // The active exercise's student file as the editor shows it, and its save.
  StudentEdit& student_edit();
  Check save_student_code();
  // The error the editor marks: the file's load error, else the last mine run's error; and the line it names.
  std::string student_code_error();
  std::optional<size_t> student_code_error_line();
  // The names of the student files whose editor text is not saved, in path order ("flip.lua, split.lua"); "" when
  // none. save_unsaved saves each (the first that fails is an Error and stops it).
  std::string unsaved_student_files() const;
  bool any_unsaved() const;
  Check save_unsaved();
  // A file a page's student picked or dropped: a .lua named as a file of the student folder replaces that file (kept,
  // and loaded as a save is; the status line names it), or is refused with an Error; any other file is left alone.
  enum class Received { NotStudentFile, Refused, Taken };
  Received take_received_file(const std::filesystem::path& received);
  // File > Download your file: the editor's file, saved first when it has unsaved changes, handed to the user
  // (host_hand_over: a page's browser downloads it).
  void download_student_code();

  // Per frame: the drafts kept (see the invariants); the Exercises tab and the Your code tab drawn; in a page (no
  // editor of the student's own), whether the Exercises tab has just opened, so Your code opens beside it.
  void keep_student_drafts();
  void draw_exercises_tab(UiProbe& probe);
  void draw_student_code_tab(UiProbe& probe);
  bool exercises_just_opened();

 private:
  void take_back_student_draft(StudentEdit& edit);

  DocumentRoom& document_;
  ExerciseSession session_;
  ExercisePanelState panel_;
  StudentEditorState editor_;
  bool exercises_were_open_ = false;  // the Exercises tab was open last frame (exercises_just_opened)
  struct EditedStudentFile {
    StudentEdit edit;
    uint64_t changes_seen = 0;  // edit.changes() last frame
    uint64_t changes_kept = 0;  // ... when its draft was last kept or forgotten
    double changed_at = 0.0;    // ImGui's time when they last changed
  };
  std::map<std::filesystem::path, EditedStudentFile> student_files_;  // by path
};

}  // namespace meshedit
