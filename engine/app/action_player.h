// ActionPlayer: plays scripted actions (scripted_actions.h) against the window's EditorApp, one step per frame, through
// the same handlers a key press or a click reaches, and counts the expectations that did not hold.
//
// Invariants: an action that throws, out of memory included, counts as a failed expectation (counted before it is
// logged with its source line, and logged without a copy of its message) and the script goes on with the next
// action; step() runs between frames, outside the frame guard, so it never throws: whatever escapes an action and its
// report is an Error in the status line (document/exception_report.h). `frames N` makes the next N steps wait.
// Checks (`expect-*`) run in the step of the action before them, so they need no frame of their own, except the checks
// of what a drawn frame computed (expect-gpu-update, expect-mine), which run after the frame that follows that action,
// and the checks after a wait (`frames`, `wait-message`, `wait-check`), which run once it is over.
// `wait-message N TEXT` holds the script until the status line contains TEXT (what arrives from outside, such as a
// file the page receives), checked once per frame, and fails after N frames without it; `wait-check N TEXT` the same
// for the Check tab's words (a check's progress). An action that starts the student's code on its thread (run-mine,
// lesson-show-mine, check-open: ExerciseSession::start_mine) holds the script until the code has ended and its run
// is in the document, frame after frame; start-mine alone does not (what follows it runs while the code does). A
// lesson's your_turn running the student's code holds the script the same way until its verdict is in the step, and
// so does the curve or patch view's "mine" (BezierMine::running) until its call has ended.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "app/scripted_actions.h"

namespace meshedit {

class EditorApp;

class ActionPlayer {
 public:
  ActionPlayer(std::vector<ScriptedAction> actions, std::ostream& log) : actions_(std::move(actions)), log_(log) {}

  bool active() const { return !actions_.empty(); }
  bool finished() const { return next_ >= actions_.size() && wait_frames_ == 0; }
  int failures() const { return failures_; }

  // Runs the next action unless a `frames N` wait is in progress. Returns false once the script asks to quit.
  bool step(EditorApp& app);

 private:
  void fail(const ScriptedAction& a, std::string_view why);
  bool run(EditorApp& app, const ScriptedAction& a);

  std::vector<ScriptedAction> actions_;
  std::ostream& log_;
  size_t next_ = 0;
  int wait_frames_ = 0;
  const ScriptedAction* waiting_for_text_ = nullptr;  // a wait-message or wait-check in progress
  bool waiting_for_run_ = false;                      // an action started the student's code: held until it ends
  int failures_ = 0;
};

}  // namespace meshedit
