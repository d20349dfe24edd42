// LessonRoom: the lesson being run. Owns the lesson runner (lesson/lesson_runner.h), the window's lesson host (what a
// lesson shows and lays over the view: window_lesson_host.h), the lesson panel's state with its hot reload, and the
// selection the lesson last heard about.
//
// Invariants:
// - Whole or nothing, as opening a file: open has the runner read and run the file first (LessonRunner::prepare), then
//   makes the title and the message, and only then switches (take, the title, the message, the panel's watch) with
//   steps that cannot fail. A reload is whole or nothing the same way (prepare_reload, the new title while the window
//   is titled after the lesson, then take and the title's swap). Going back to the list makes the fresh runner before
//   it clears the lesson's highlights and labels; a window titled after the lesson gets its title at start back.
// - The lesson's student folder is the Exercises tab's (update keeps them the same), so your_turn runs the files the
//   student edits; what the lesson prints goes to the console.
// - A selection made any way (a click, the tables, N/T walking, a scripted `select`) is news for the lesson, told once
//   per change.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/window_lesson_host.h"
#include "lesson/lesson_runner.h"
#include "ui/lesson_panel.h"

namespace meshedit {

class DocumentRoom;
class ExerciseRoom;
class ViewRoom;

class LessonRoom {
 public:
  using Print = std::function<void(const std::string&)>;
  LessonRoom(DocumentRoom& document, ViewRoom& view, ExerciseRoom& exercises, Print print);

  LessonRunner& runner() { return *runner_; }
  const LessonRunner& runner() const { return *runner_; }
  const LessonMarks& marks() const { return host_.marks(); }  // the lesson's highlights, labels and arrows
  LessonPanelState& panel() { return panel_; }

  // Loads a lesson file into the lesson panel, whole or nothing: the lesson runs, the title names it and the status
  // line says so; or the lesson that ran goes on under its title, and the status line and the panel say why not
  // (file:line, or that memory ran out). Never throws. Returns whether it loaded.
  bool open(const std::filesystem::path& path);
  // Loads the running lesson's file again at its step (the panel's Reload and hot reload), whole or nothing: the new
  // version runs and, while the window is titled after the lesson, the title follows its new lesson{title=}; or the
  // version that ran goes on, and the panel says why. Never throws.
  ReloadOutcome reload();
  // The lesson panel's "Lessons": leaves the lesson for the list of lessons, with a fresh runner, whole or nothing: the
  // lesson, its highlights and labels all go, or (memory ran out making the runner) all stay and the exception is
  // thrown (the frame guard reports it).
  void show_list();

  // Per frame: the selection's news, hot reload, the student folder, the lesson's time; after the panel is drawn, the
  // lesson picked from the list or "Lessons" (back to the list).
  void update(float frame_ms);
  void take_request();
  // What the lesson hears besides the selection (while one is loaded): a key by its lesson name, a command by its
  // name, a click on an element, a click on the curve view (the curve view's clicked point, taken).
  void tell_key(int key, KeyMods mods);
  void tell_command(const char* name);
  void tell_click(ElementRef element);
  void tell_curve_click();
  // True while the step waits for an animation to end: the window must not sleep.
  bool animating() const;

 private:
  // A runner with no lesson, for the window's lesson host, printing to the console.
  std::unique_ptr<LessonRunner> make_runner();
  // The runner's student folder is the Exercises tab's (your_turn runs the files the tab runs).
  void follow_student_folder();

  DocumentRoom& document_;
  ViewRoom& view_;
  ExerciseRoom& exercises_;
  Print print_;
  WindowLessonHost host_;
  std::unique_ptr<LessonRunner> runner_;
  LessonPanelState panel_;
  ElementRef selection_heard_;  // the selection the lesson last heard about
};

}  // namespace meshedit
