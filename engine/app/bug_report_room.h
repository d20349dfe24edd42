// BugReportRoom: Help > Save a bug report (document/bug_report.h). Its dialog shows what the report holds before it is
// written (the mesh and its selection, the last run of the student's function, the lesson and step, the app's
// version) and a box for each of the student's saved code files, so the report holds only what the student chose;
// Save writes it (on the desktop where the path says; in a page the browser downloads it). Reopening a report is the
// window's (EditorApp::open_bug_report, editor_bug_report.cpp).
//
// Invariants:
// - The report is made of what the window shows now: the document's mesh with every record and id, the selection,
//   the Exercises tab's last run when it ran the student's function on a mesh (its input, its label and verdict, and
//   whether the mesh shown is still the state the run left), the running lesson's file and step, and the mesh view's
//   camera when the mesh view is on screen.
// - The code sent is the saved files of the Exercises tab's folder (never unsaved editor text), each only when its
//   box is ticked; the boxes start ticked and are remembered while the window runs.
// - Nothing here throws: every outcome is a sentence in the status line and a Check.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/check.h"
#include "document/bug_report.h"

namespace meshedit {

class DocumentRoom;
class ExerciseRoom;
class LessonRoom;
class ViewRoom;

class BugReportRoom {
 public:
  BugReportRoom(DocumentRoom& document, ExerciseRoom& exercises, LessonRoom& lessons, const ViewRoom& view)
      : document_(document), exercises_(exercises), lessons_(lessons), view_(view) {}

  // The student's saved code files the report can hold: the Exercises tab folder's files of every exercise, in the
  // assignment's order.
  std::vector<std::filesystem::path> code_files() const;
  // The report of what the window shows, with the ticked files; throws (std::bad_alloc, a file gone while read).
  BugReport make() const;
  // make(), written to `path` and handed to the user (a page downloads it). Never throws.
  Check save(const std::filesystem::path& path);

  void open_dialog() { shown_ = true; }
  bool dialog_shown() const { return shown_; }
  void draw_dialog();
  // Ticks or unticks a file's box (a file name: "flip.lua").
  void choose_file(const std::string& name, bool send) { unticked_[name] = !send; }

 private:
  bool sends(const std::string& name) const;

  DocumentRoom& document_;
  ExerciseRoom& exercises_;
  LessonRoom& lessons_;
  const ViewRoom& view_;
  bool shown_ = false;
  std::string path_input_ = "report.meshedit";
  std::map<std::string, bool> unticked_;  // a file name -> its box was unticked
};

}  // namespace meshedit
