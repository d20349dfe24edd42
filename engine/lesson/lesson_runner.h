// LessonRunner: runs a lesson file (see lesson_api.h for the Lua globals) step by step for the app, with no
// window of its own. Each step body runs as a coroutine that yields to the app at wait_for and animate; the
// app calls update(dt) every frame and deliver(event) for keys, clicks, selections and button presses.
//
// Invariants:
// - Nothing here throws: a file that does not load, a Lua error in a step, a limit being hit, or an exception
//   from the host becomes error() ("welcome.lua:12: message") and the runner keeps working: next, back,
//   go_to, restart_step and reload stay possible.
// - Each load uses a fresh LuaRuntime. A load is whole or nothing: the file is read and run to its list of steps
//   (prepare) before anything the runner shows changes, then take() switches to it with steps that cannot fail and
//   starts its step. A load that fails, memory running out included, keeps the lesson that was running before (if
//   any), whole, so a typo saved during hot reload never takes the panel away (load()).
// - Out of memory: the script layer's rule of docs/ARCHITECTURE.md (Memory running out), kept in out_of_memory().
// - Entering a step (next, back, go_to, restart_step, a reload) clears the host's highlights and labels,
//   forgets what the step said and runs its body from the start: a step rebuilds its own scene. Back is
//   "run the previous step again from its start".
// - reload() keeps the step index (clamped to the new number of steps).
// - Every resume of a step (its start, each event, each update that wakes it) opens its own budget window
//   of the runtime's limits: a step that loops forever stops with the budget message, never hangs the app.
//   One call (update, deliver, next...) resumes a step at most once.
// - Calls made from inside a host callback (re-entrant) are ignored: deliver returns false, the others do
//   nothing.
// - Live blocks and plot markers (lesson_displays.h) are evaluated by update() after the wait, and by refresh_live(),
//   while the step waits or has finished (not after it failed): each in a budget window of its own under
//   live_limits(), far below a step's, so a slow one stops alone with its error and the frame goes on.
// - A question (choose, pick, answer: lesson_questions.h) is a wait like the others: deliver() of an answer of its
//   kind resumes the step and returns true whether the answer was right or wrong; judgements() counts the answers
//   judged and last_judgement() says how the latest went.
// - A your_turn wait (lesson_your_turn.h) is resumed by update() when the student's file changed on disk, read at most
//   every kStudentFileCheckSeconds of update time; your_turns() lists the step's runs and their verdicts. A run beside
//   the step (set_student_code_in_background) is taken by the first update() after it ended, which records its
//   verdict and resumes the step; leaving the step, a reload or the runner's end stops it and waits for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lesson/lesson_blocks.h"
#include "lesson/lesson_events.h"
#include "lesson/lesson_host.h"
#include "lesson/lesson_texts.h"
#include "script/lua_runtime.h"

namespace meshedit {

struct LessonScript;

class LessonRunner {
 public:
  enum class StepState {
    Empty,     // no lesson loaded
    Waiting,   // the step waits (waiting_for() says for what)
    Finished,  // the step's body returned; Next goes on
    Failed,    // the step stopped on an error (error() says where)
  };

  // Limits for one resume of a step: far below LuaRuntime's defaults, since the window waits for each one.
  static LuaLimits default_limits();
  // Limits for one evaluation of a live block or a plot marker, every frame: `step`'s memory, at most 2 million
  // instructions and 50 ms.
  static LuaLimits live_limits(const LuaLimits& step);

  explicit LessonRunner(LessonHost& host, LuaLimits limits = default_limits());
  ~LessonRunner();
  LessonRunner(const LessonRunner&) = delete;
  LessonRunner& operator=(const LessonRunner&) = delete;

  // Where the lesson's print() goes (each line without its newline); applies to later loads too.
  void set_print(std::function<void(const std::string&)> print);
  // The student's folder your_turn runs files from (lesson_your_turn.h), and the limits of the student's code (the
  // exercises' own by default); apply to the lesson running and to later loads.
  void set_student_folder(std::filesystem::path folder);
  const std::filesystem::path& student_folder() const { return student_folder_; }
  void set_student_limits(const LuaLimits& limits);
  // Whether a your_turn runs the student's code beside the step (the window: the step waits, the frames go on) or
  // in place (the default, the headless driver); applies to the lesson running and to later loads.
  void set_student_code_in_background(bool background);
  // A your_turn's run under way (LessonWait::Kind::YourTurnRunning), how long it has run, and its Stop: the code
  // stops at its next line, and the run's verdict says so.
  bool student_code_running() const;
  double student_code_seconds() const;
  void stop_student_code();

  // A lesson file read and run to its list of steps, not yet the one running (prepare, then take).
  struct Prepared {
    Prepared();
    ~Prepared();
    Prepared(Prepared&&) noexcept;
    Prepared& operator=(Prepared&&) noexcept;
    const std::string& title() const;  // lesson{title=} or the file's stem

   private:
    friend class LessonRunner;
    std::filesystem::path path_;
    // The script's state is declared before the runtime, so the runtime (whose closures point at it) goes first.
    std::unique_ptr<LessonScript> script_;
    std::unique_ptr<LuaRuntime> runtime_;
  };

  // Loads the file and starts its first step: prepare, then take. False when the file cannot be read or run, or
  // defines no step (error() says why; "memory ran out" when it did). The error stays in error() until a load
  // succeeds, and path() names the file asked for (unless memory ran out copying its name), so hot reload loads it
  // once it is fixed.
  bool load(const std::filesystem::path& path);
  // Loads the same file again and starts the same step index (clamped). False as load(): prepare_reload, then take
  // with current_step().
  bool reload();
  // prepare() of the file the runner runs (or last asked for): what a caller that has more to make before the switch
  // (the window's title) calls first. False as reload(), "no lesson to reload" when there is no file.
  bool prepare_reload(Prepared& lesson);
  // Reads and runs the file into `lesson`, changing nothing the runner shows: what a caller that has more to make
  // before the switch (the window's title) calls first. False as load(), with error() and path() set as there.
  bool prepare(const std::filesystem::path& path, Prepared& lesson);
  // Switches to `lesson`, prepared by this runner, and starts its step `index` (clamped). Cannot fail: what stops
  // the step is the step's error.
  void take(Prepared&& lesson, size_t index = 0) noexcept;

  void next();               // the following step (nothing at the last one)
  void back();               // the previous step, from its start (step 1 starts again)
  void restart_step();       // the current step again, from its start
  void go_to(size_t index);  // that step (clamped), from its start

  // Advances the current wait (an animation by `dt` seconds, a condition checked again, a selection wait
  // met by the host's current selection), then refresh_live().
  void update(double dt) noexcept;
  // Evaluates the step's live blocks and plot markers again (what the panel shows follows the view).
  void refresh_live() noexcept;
  // Gives an app event to the waiting step. True when it was what the step waited for (the step resumed).
  bool deliver(const LessonEvent& event);

  // ---- what the lesson panel shows (references stay valid until the next non-const call) ----
  bool loaded() const { return script_ != nullptr; }
  const std::filesystem::path& path() const { return path_; }
  const std::string& title() const;    // lesson{title=} or the file's stem
  const std::string& summary() const;  // lesson{summary=}
  std::vector<std::string> step_titles() const;
  size_t step_count() const;
  size_t current_step() const { return index_; }  // 0-based
  StepState step_state() const { return state_; }
  bool step_finished() const { return state_ == StepState::Finished; }
  // The lesson's texts in the other languages, by their English (title(), said(), the questions... are English), and
  // what reading them found; empty before a load.
  const LessonTexts& texts() const;
  // The markdown blocks say() gave in the current step, in order.
  const std::vector<std::string>& said() const;
  // Everything the step shows, in order (lesson_blocks.h): each block indexes said(), lives(), plots() or answered().
  const std::vector<LessonBlock>& blocks() const;
  const std::vector<LessonLive>& lives() const;
  const std::vector<LessonPlot>& plots() const;
  const std::vector<LessonJudgement>& answered() const;  // the questions answered right, in order
  // The latest answer judged in this step (right or wrong), and how many were judged (0: none yet).
  const LessonJudgement& last_judgement() const;
  size_t judgements() const;
  // Every your_turn run of this step, in order (lesson_your_turn.h).
  const std::vector<YourTurnVerdict>& your_turns() const;
  // What the current step waits for (kind None when it does not wait).
  const LessonWait& waiting_for() const;
  // "" when all is well; else "file:line: message" of the failed load or the failed step.
  const std::string& error() const { return load_error_.empty() ? step_error_ : load_error_; }
  // Whether error() is memory running out (a std::bad_alloc, or a Lua error raised for one: ScriptError::
  // out_of_memory), which a retry can make go away; told from where it was caught (the exception's type, the
  // runtime's flag), never guessed from the text, so a lesson's own error("memory ran out") is the lesson's error.
  // A step that cannot start or run for lack of memory is a failed step whose error says memory ran out.
  bool out_of_memory() const { return load_error_.empty() ? step_out_of_memory_ : load_out_of_memory_; }

 private:
  // Reads `lesson.path` and runs it into `lesson`; "" or why it did not load (the file cannot be opened, or defines no
  // step). Throws ScriptError (the file's error) and std::bad_alloc.
  std::string read_and_run(Prepared& lesson);
  void start_step(size_t index) noexcept;
  void advance_wait(double dt) noexcept;
  // Resumes the step's coroutine with what `push` leaves on the stack (nullptr: nothing).
  void resume(const std::function<int(lua_State*)>& push) noexcept;
  // Runs `body` on the main thread inside a fresh budget window; returns "" or the error message, with
  // `out_of_memory` telling whether that error is memory running out.
  std::string protected_call(bool& out_of_memory, const std::function<void(lua_State*)>& body);
  static int trampoline(lua_State* L);
  void fail(const std::string& message, bool out_of_memory) noexcept;
  void fail_with(const std::exception& error) noexcept;  // fail with exception_text's message and flag

  LessonHost& host_;
  LuaLimits limits_;
  LuaLimits live_limits_;
  std::function<void(const std::string&)> print_;
  std::filesystem::path student_folder_;
  LuaLimits student_limits_;
  bool student_code_in_background_ = false;
  std::filesystem::path path_;
  // The script's state is declared before the runtime, so the runtime (whose closures point at it) goes first.
  std::unique_ptr<LessonScript> script_;
  std::unique_ptr<LuaRuntime> runtime_;
  const std::function<void(lua_State*)>* body_ = nullptr;  // what trampoline() runs
  int thread_ref_ = -2;                                    // LUA_NOREF: the current step's coroutine in the registry
  size_t index_ = 0;
  StepState state_ = StepState::Empty;
  std::string load_error_, step_error_;
  bool load_out_of_memory_ = false, step_out_of_memory_ = false;  // out_of_memory() of each
  bool busy_ = false;
};

}  // namespace meshedit
