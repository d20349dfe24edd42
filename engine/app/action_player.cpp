// Playing scripted actions against the window (see action_player.h); what each verb does is action_verbs.cpp's.
#include "app/action_player.h"

#include <stdexcept>
#include <string>

#include "app/action_verbs.h"
#include "app/check_room.h"
#include "app/editor_app.h"
#include "document/exception_report.h"

namespace meshedit {
namespace {

// Checks of what a drawn frame computed (the mesh view's last geometry update, the curve view's "mine" line): they
// run in the step after the frame that follows the action before them, not in that action's step.
bool reads_a_drawn_frame(const ScriptedAction& a) { return a.verb == "expect-gpu-update" || a.verb == "expect-mine"; }

// What a wait reads: the status line (wait-message) or the Check tab's words (wait-check).
std::string waited_text(EditorApp& app, const ScriptedAction& a) {
  return a.verb == "wait-check" ? app.check_room().text() : app.document().message.text;
}

// Whether that text contains the words of the wait after its number of frames.
bool wait_over(EditorApp& app, const ScriptedAction& a) {
  return waited_text(app, a).find(a.words(1)) != std::string::npos;
}

}  // namespace

bool ActionPlayer::step(EditorApp& app) {
  // A lesson's your_turn running the student's code: what follows waits for its verdict (the student's deadline,
  // student_code_seconds, ends a runaway).
  if (app.lesson().student_code_running()) return true;
  // The curve or patch view's "mine" running the student's code: what follows sees its result.
  if (app.view().bezier_mine().running()) return true;
  if (waiting_for_run_) {
    if (app.exercises().running()) return true;
    waiting_for_run_ = false;
  }
  if (waiting_for_text_) {
    bool arrived = false;
    run_guarded(app.document(), [&] {
      const ScriptedAction& a = *waiting_for_text_;
      arrived = wait_over(app, a);
      if (!arrived && --wait_frames_ > 0) return;
      waiting_for_text_ = nullptr;
      wait_frames_ = 0;
      if (!arrived) {
        fail(a, std::string(a.verb == "wait-check" ? "the Check tab says '" : "the status line is '") +
                    waited_text(app, a) + "' after " + a.args[0] + " frames");
      }
      arrived = true;  // the wait is over either way
    });
    if (!arrived) return true;
  } else if (wait_frames_ > 0) {
    --wait_frames_;
    return true;
  }
  // Checks need no frame of their own: run them together with the action before the next one that does (but a check
  // of a drawn frame waits for one).
  while (next_ < actions_.size()) {
    const ScriptedAction& a = actions_[next_++];
    bool quit = false;
    // Between frames, outside the frame guard: the action's failure is counted, and whatever still escapes goes to
    // the status line instead of ending the window.
    run_guarded(app.document(), [&] {
      try {
        quit = !run(app, a);
      } catch (const std::exception& e) {
        fail(a, e.what());
      }
    });
    if (quit) return false;
    if (waiting_for_text_ || wait_frames_ > 0 || waiting_for_run_) return true;  // what follows a wait runs after it
    const bool checks_follow = next_ < actions_.size() && actions_[next_].verb.rfind("expect-", 0) == 0 &&
                               !reads_a_drawn_frame(actions_[next_]);
    if (!checks_follow) return true;
  }
  return false;
}

void ActionPlayer::fail(const ScriptedAction& a, std::string_view why) {
  ++failures_;  // first: a log that cannot be written (a stream out of memory goes bad) still fails the script
  log_ << a.source << ": " << a.verb << " failed: " << why << "\n";
}

bool ActionPlayer::run(EditorApp& app, const ScriptedAction& a) {
  if (a.verb == "quit") return false;
  if (a.verb == "frames") {
    wait_frames_ = std::stoi(a.args[0]);
    return true;
  }
  if (a.verb == "wait-message" || a.verb == "wait-check") {
    const int frames = std::stoi(a.args[0]);
    if (a.args.size() < 2 || frames < 1) throw std::runtime_error(a.verb + " takes a number of frames and a text");
    if (wait_over(app, a)) return true;
    wait_frames_ = frames;
    waiting_for_text_ = &a;
    return true;
  }
  const ActionVerb* verb = find_action_verb(a.verb);
  if (!verb || !verb->run) throw std::runtime_error("unknown action '" + a.verb + "'");
  const bool was_running = app.exercises().running();
  const std::string failure = verb->run(app, a);
  if (!was_running && app.exercises().running() && a.verb != "start-mine") waiting_for_run_ = true;
  if (!failure.empty()) fail(a, failure);
  return true;
}

}  // namespace meshedit
