// LessonRunner: loading a lesson into a fresh runtime, running each step as a coroutine, and turning every
// failure into error() (see lesson_runner.h for the invariants).
//
// All Lua work (creating the step's thread, resuming it, pushing what a wait returns) runs inside a
// trampoline called through LuaRuntime::call, so it is protected (an allocation failure is a Lua error, not
// a panic) and inside a fresh budget window. The step's thread gets the main thread's count hook before each
// resume, so the runtime's limits reach code running in the coroutine.
//
// Out of memory: a load builds everything into a Prepared (the file's text, the runtime, the script with its steps
// and title) before take() moves it in; the step functions catch what they cannot prevent (a std::function or a
// message that could not be made) and turn it into the step's error with exception_text, which cannot fail. Whether an
// error is memory running out travels with it as a flag (exception_text's, the runtime's ran_out_of_memory for a
// step's own Lua error), never read back from the text.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers                        BusyScope, the empty defaults, error_text
//   limits and settings            default_limits, live_limits, set_student_folder, set_student_limits
//   loading                        load, reload, prepare, read_and_run, take
//   moving between steps           next, back, restart_step, go_to, fail
//   running a step                 start_step, resume, trampoline, protected_call
//   waits, live values and events  update, advance_wait, refresh_live, deliver
//   what the panel reads           title, summary, step_titles, your_turns and the other getters
#include "lesson/lesson_runner.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

#include <lua.hpp>

#include "core/bezier.h"
#include "lesson/internal/lesson_api.h"
#include "lesson/internal/lesson_displays.h"
#include "lesson/internal/lesson_your_turn.h"
#include "lesson/internal/your_turn_run.h"
#include "script/exception_text.h"
#include "script/lua_args.h"
#include "script/script_runtime.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

// Sets the runner's busy flag for its lifetime: a script's calls back into the runner are refused meanwhile, and an
// exception (even one thrown while its message is copied, out of memory) cannot leave the runner busy for good.
class BusyScope {
 public:
  explicit BusyScope(bool& busy) : busy_(busy) { busy_ = true; }
  ~BusyScope() { busy_ = false; }
  BusyScope(const BusyScope&) = delete;
  BusyScope& operator=(const BusyScope&) = delete;

 private:
  bool& busy_;
};

const std::string kEmptyText;
const std::vector<std::string> kNoBlocks;
const LessonWait kNoWait;
const std::vector<LessonBlock> kNoDisplay;
const std::vector<LessonLive> kNoLives;
const std::vector<LessonPlot> kNoPlots;
const std::vector<LessonJudgement> kNoAnswers;
const LessonJudgement kNoJudgement;

std::string error_text(lua_State* co, const LuaLimits& limits) {
  std::string message = error_value_text(co, -1);
  // A memory error carries no position (Lua builds no message for it): the coroutine's stack, which an error
  // leaves in place, still says where it was.
  if (message == "not enough memory") {
    const std::string where = script_where(co, 0);
    message = (where.empty() ? "" : where + ": ") + memory_limit_message(limits.memory_bytes);
  }
  return message;
}

}  // namespace

// ---- limits and settings ---------------------------------------------------------------------------

LuaLimits LessonRunner::default_limits() {
  LuaLimits limits;
  limits.instructions = 200'000'000;
  limits.wall_seconds = 10.0;
  return limits;
}

LuaLimits LessonRunner::live_limits(const LuaLimits& step) {
  LuaLimits limits = step;
  limits.instructions = std::min<uint64_t>(step.instructions, 2'000'000);
  limits.wall_seconds = std::min(step.wall_seconds, 0.05);
  return limits;
}

LessonRunner::LessonRunner(LessonHost& host, LuaLimits limits)
    : host_(host), limits_(limits), live_limits_(live_limits(limits)) {}

LessonRunner::~LessonRunner() = default;

void LessonRunner::set_print(std::function<void(const std::string&)> print) { print_ = std::move(print); }

void LessonRunner::set_student_folder(std::filesystem::path folder) {
  student_folder_ = std::move(folder);
  if (script_) script_->student_folder = student_folder_;
}

void LessonRunner::set_student_limits(const LuaLimits& limits) {
  student_limits_ = limits;
  if (script_) script_->student_limits = limits;
}

void LessonRunner::set_student_code_in_background(bool background) {
  student_code_in_background_ = background;
  if (script_) script_->student_code_in_background = background;
}

bool LessonRunner::student_code_running() const { return script_ && script_->running_turn; }

double LessonRunner::student_code_seconds() const {
  return student_code_running() ? script_->running_turn->seconds() : 0.0;
}

void LessonRunner::stop_student_code() {
  if (student_code_running()) script_->running_turn->stop();
}

LessonRunner::Prepared::Prepared() = default;
LessonRunner::Prepared::~Prepared() = default;
LessonRunner::Prepared::Prepared(Prepared&&) noexcept = default;
LessonRunner::Prepared& LessonRunner::Prepared::operator=(Prepared&&) noexcept = default;

const std::string& LessonRunner::Prepared::title() const { return script_ ? script_->title : kEmptyText; }

// ---- loading ---------------------------------------------------------------------------------------

bool LessonRunner::load(const std::filesystem::path& path) {
  Prepared lesson;
  if (!prepare(path, lesson)) return false;
  take(std::move(lesson), 0);
  return true;
}

bool LessonRunner::reload() {
  Prepared lesson;
  if (!prepare_reload(lesson)) return false;
  take(std::move(lesson), index_);
  return true;
}

bool LessonRunner::prepare_reload(Prepared& lesson) {
  if (busy_) return false;
  if (path_.empty()) {
    load_out_of_memory_ = false;
    try {
      load_error_ = "no lesson to reload";
    } catch (const std::exception&) {
      load_error_ = kScriptMemoryRanOut;  // fits std::string's inline buffer: allocates nothing
      load_out_of_memory_ = true;
    }
    return false;
  }
  return prepare(path_, lesson);
}

bool LessonRunner::prepare(const std::filesystem::path& path, Prepared& lesson) {
  if (busy_) return false;
  bool named = false, out_of_memory = false;
  std::string failure;
  try {
    lesson.path_ = path;
    named = true;
    failure = read_and_run(lesson);
  } catch (const std::exception& e) {  // ScriptError, bad_alloc: what was made so far goes with `lesson`
    failure = exception_text(e, out_of_memory);
  }
  if (failure.empty()) return true;
  // The lesson that was running goes on; the file asked for is the one hot reload watches.
  if (named) path_.swap(lesson.path_);
  load_error_ = std::move(failure);
  load_out_of_memory_ = out_of_memory;
  return false;
}

std::string LessonRunner::read_and_run(Prepared& lesson) {
  const std::filesystem::path& path = lesson.path_;
  const std::optional<std::string> text = read_lua_file(path);
  if (!text) return "cannot open " + path.string();
  const std::string chunk = path.filename().string();

  lesson.script_ = std::make_unique<LessonScript>();
  LessonScript& script = *lesson.script_;
  script.host = &host_;
  script.directory = path.parent_path();  // lesson_file() finds assets next to the lesson
  script.student_folder = student_folder_;
  script.student_limits = student_limits_;
  script.student_code_in_background = student_code_in_background_;
  {
    const BusyScope busy(busy_);
    lesson.runtime_ = std::make_unique<ScriptRuntime>(limits_);
    lesson.runtime_->set_print([this](const std::string& line) {
      if (print_) print_(line);
    });
    open_lesson_api(*lesson.runtime_, script);
    lesson.runtime_->load(*text, chunk);
    lesson.runtime_->start_budget();
    lesson.runtime_->call(0, 0);
  }
  if (script.steps.empty()) {
    return chunk + ": no steps (a lesson defines them with step(\"title\", function() ... end))";
  }
  script.phase = LessonScript::Phase::Idle;
  if (script.title.empty()) script.title = path.stem().string();
  return {};
}

void LessonRunner::take(Prepared&& lesson, size_t index) noexcept {
  load_error_.clear();
  load_out_of_memory_ = false;
  thread_ref_ = LUA_NOREF;  // it belonged to the old runtime
  runtime_ = std::move(lesson.runtime_);
  script_ = std::move(lesson.script_);
  path_.swap(lesson.path_);
  start_step(std::min(index, script_->steps.size() - 1));
}

// ---- moving between steps --------------------------------------------------------------------------

void LessonRunner::next() {
  if (!script_ || busy_) return;
  if (index_ + 1 < script_->steps.size()) start_step(index_ + 1);
}

void LessonRunner::back() {
  if (!script_ || busy_) return;
  start_step(index_ > 0 ? index_ - 1 : 0);
}

void LessonRunner::restart_step() {
  if (!script_ || busy_) return;
  start_step(index_);
}

void LessonRunner::go_to(size_t index) {
  if (!script_ || busy_) return;
  start_step(std::min(index, script_->steps.size() - 1));
}

void LessonRunner::fail(const std::string& message, bool out_of_memory) noexcept {
  state_ = StepState::Failed;
  step_out_of_memory_ = out_of_memory;
  try {
    step_error_ = message;
  } catch (const std::exception&) {
    step_error_ = kScriptMemoryRanOut;  // fits the inline buffer: allocates nothing
    step_out_of_memory_ = true;
  }
  if (script_) script_->wait = {};
}

void LessonRunner::fail_with(const std::exception& error) noexcept {
  bool out_of_memory = false;
  std::string message = exception_text(error, out_of_memory);
  fail(message, out_of_memory);
}

// ---- running a step --------------------------------------------------------------------------------

void LessonRunner::start_step(size_t index) noexcept try {
  index_ = index;
  step_error_.clear();
  step_out_of_memory_ = false;
  clear_step_display(runtime_->state(), *script_);
  script_->running_turn.reset();  // a your_turn of the step left: its code stopped, waited for
  script_->wait = {};
  script_->step_thread = nullptr;
  state_ = StepState::Waiting;
  std::string failure;
  bool out_of_memory = false, failed = false;
  try {
    const BusyScope busy(busy_);
    host_.clear_annotations();
  } catch (const std::exception& e) {
    failure = exception_text(e, out_of_memory);
    failed = true;
  }
  if (failed) return fail(failure, out_of_memory);

  const int function_ref = script_->steps[index].function_ref;
  failure = protected_call(out_of_memory, [&](lua_State* L) {
    if (thread_ref_ != LUA_NOREF) luaL_unref(L, LUA_REGISTRYINDEX, thread_ref_);
    thread_ref_ = LUA_NOREF;
    lua_State* co = lua_newthread(L);
    thread_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
    lua_rawgeti(L, LUA_REGISTRYINDEX, function_ref);
    lua_xmove(L, co, 1);
    script_->step_thread = co;
  });
  if (!failure.empty()) return fail(failure, out_of_memory);
  resume(nullptr);
} catch (const std::exception& e) {  // memory ran out making a std::function or a message
  fail_with(e);
}

void LessonRunner::resume(const std::function<int(lua_State*)>& push) noexcept try {
  enum class Outcome { None, Yielded, Finished, Failed };
  Outcome outcome = Outcome::None;
  std::string message;
  bool out_of_memory = false;
  const std::string failure = protected_call(out_of_memory, [&](lua_State* L) {
    lua_rawgeti(L, LUA_REGISTRYINDEX, thread_ref_);
    lua_State* co = lua_tothread(L, -1);
    lua_pop(L, 1);  // the registry keeps it
    if (!co) luaL_error(L, "lesson runner: the step has no coroutine");
    const int nargs = push ? push(L) : 0;
    lua_xmove(L, co, nargs);
    // The coroutine runs under the same limits as the window just opened on the main thread.
    lua_sethook(co, lua_gethook(L), lua_gethookmask(L), lua_gethookcount(L));
    script_->wait = {};
    script_->api_yield = false;
    script_->phase = LessonScript::Phase::Step;
    int nresults = 0;
    const int status = lua_resume(co, L, nargs, &nresults);
    script_->phase = LessonScript::Phase::Idle;
    if (status == LUA_YIELD && script_->api_yield) {
      lua_pop(co, nresults);
      outcome = Outcome::Yielded;
    } else if (status == LUA_YIELD) {
      const std::string where = script_where(co, 0);
      message = (where.empty() ? "" : where + ": ") +
                std::string("coroutine.yield stopped the step; wait with wait_for or animate");
      outcome = Outcome::Failed;
    } else if (status == LUA_OK) {
      lua_pop(co, nresults);
      outcome = Outcome::Finished;
    } else {
      message = error_text(co, limits_);
      outcome = Outcome::Failed;
    }
  });
  script_->phase = LessonScript::Phase::Idle;
  switch (outcome) {
    case Outcome::None: return fail(failure, out_of_memory);  // the step never ran: pushing its arguments failed
    case Outcome::Failed: return fail(message, runtime_->ran_out_of_memory());  // the step's window
    case Outcome::Finished:
      state_ = StepState::Finished;
      script_->wait = {};
      return;
    case Outcome::Yielded: state_ = StepState::Waiting; return;
  }
} catch (const std::exception& e) {  // memory ran out making the call's std::function
  script_->phase = LessonScript::Phase::Idle;
  fail_with(e);
}

int LessonRunner::trampoline(lua_State* L) {
  auto* self = static_cast<LessonRunner*>(lua_touserdata(L, 1));
  lua_settop(L, 0);
  std::string message;
  try {
    (*self->body_)(L);
    return 0;
  } catch (const std::exception& e) {  // from the host (current_mesh...): must not cross the Lua frames
    message = lua_error_text(L, e);
  }
  return luaL_error(L, "%s", message.c_str());
}

std::string LessonRunner::protected_call(bool& out_of_memory, const std::function<void(lua_State*)>& body) {
  lua_State* L = runtime_->state();
  body_ = &body;
  std::string failure;
  out_of_memory = false;
  try {
    const BusyScope busy(busy_);
    lua_pushcfunction(L, &LessonRunner::trampoline);  // a light C function and a light userdata: no allocation
    lua_pushlightuserdata(L, this);
    runtime_->start_budget();
    runtime_->call(1, 0);
  } catch (const std::exception& e) {
    failure = exception_text(e, out_of_memory);
  }
  body_ = nullptr;
  return failure;
}

// ---- waits, live values and events -----------------------------------------------------------------

void LessonRunner::update(double dt) noexcept {
  advance_wait(dt);
  refresh_live();
}

void LessonRunner::advance_wait(double dt) noexcept try {
  if (!script_ || busy_ || state_ != StepState::Waiting) return;
  const LessonWait& wait = script_->wait;  // read only before resume(), which clears it; a copy could run out
  switch (wait.kind) {
    case LessonWait::Kind::Condition: return resume(nullptr);
    case LessonWait::Kind::Animation: {
      const double seconds = std::isfinite(dt) && dt > 0.0 ? dt : 0.0;
      return resume([seconds](lua_State* L) {
        lua_pushnumber(L, seconds);
        return 1;
      });
    }
    case LessonWait::Kind::Selection: {
      ElementRef selected;
      std::string failure;
      bool out_of_memory = false, failed = false;
      try {
        const BusyScope busy(busy_);
        selected = host_.current_selection();
      } catch (const std::exception& e) {
        failure = exception_text(e, out_of_memory);
        failed = true;
      }
      if (failed) return fail(failure, out_of_memory);
      if (!wait.selection_matches(selected)) return;
      return resume([this, selected](lua_State* L) {
        push_element_value(L, host_, selected);
        return 1;
      });
    }
    case LessonWait::Kind::YourTurnRunning: {
      if (!script_->running_turn || !script_->running_turn->done()) return;
      const std::shared_ptr<YourTurnRun> run = std::move(script_->running_turn);
      const bool right = record_your_turn(*script_, run->finish());
      return resume([right](lua_State* L) {
        lua_pushboolean(L, right);
        return 1;
      });
    }
    case LessonWait::Kind::YourTurn: {
      LessonWait& turn = script_->wait;
      turn.since_checked += std::isfinite(dt) && dt > 0.0 ? dt : 0.0;
      if (turn.since_checked < kStudentFileCheckSeconds) return;
      turn.since_checked = 0.0;
      if (file_stamp(turn.watched_file) == turn.watched_stamp) return;
      return resume(nullptr);  // saved: your_turn runs the file again
    }
    default: return;
  }
} catch (const std::exception& e) {  // memory ran out making what resumes the step
  fail_with(e);
}

void LessonRunner::refresh_live() noexcept {
  if (!script_ || busy_ || (state_ != StepState::Waiting && state_ != StepState::Finished)) return;
  bool follows = false;  // anything that follows the view: most steps have nothing, and pay nothing
  for (const LessonLive& live : script_->lives) follows = follows || live.error.empty();
  for (const LessonPlot& plot : script_->plots) {
    follows = follows || (plot.error.empty() && plot.marker_ref != LUA_NOREF);
  }
  if (!follows) return;
  // Each block in a budget window of its own, under the live limits: one slow block stops alone.
  struct LiveLimits {
    LuaRuntime& runtime;
    const LuaLimits& step;
    LiveLimits(LuaRuntime& r, const LuaLimits& live, const LuaLimits& s) : runtime(r), step(s) { r.set_limits(live); }
    ~LiveLimits() { runtime.set_limits(step); }
  } scope(*runtime_, live_limits_, limits_);
  const auto evaluate = [this](std::string& error, const std::function<void(lua_State*)>& body) {
    bool out_of_memory = false;
    std::string failure = protected_call(out_of_memory, body);
    // Memory that ran out is not the block's doing: the next frame tries again.
    if (!failure.empty() && !out_of_memory && error.empty()) error = std::move(failure);
  };
  try {
    for (LessonLive& live : script_->lives) {
      if (live.error.empty()) evaluate(live.error, [&](lua_State* L) { evaluate_live(L, *script_, live); });
    }
    for (LessonPlot& plot : script_->plots) {
      if (plot.error.empty() && plot.marker_ref != LUA_NOREF) {
        evaluate(plot.error, [&](lua_State* L) { evaluate_marker(L, *script_, plot); });
      }
    }
  } catch (const std::exception&) {  // memory ran out making a block's call: the next frame tries again
  }
}

bool LessonRunner::deliver(const LessonEvent& event) {
  if (!script_ || busy_ || state_ != StepState::Waiting || !script_->wait.matches(event)) return false;
  std::optional<CurveReading> curve;
  if (event.kind == LessonEvent::Kind::CurveClick) {
    curve = host_.curve_reading();
    if (!curve || curve->control_points.empty()) return false;  // no curve on screen to have clicked
  }
  try {
    resume([this, &event, &curve](lua_State* L) {
      if (event.kind == LessonEvent::Kind::Click || event.kind == LessonEvent::Kind::Selection) {
        push_element_value(L, host_, event.element);
      } else if (curve) {  // the curve's t nearest the click, its point, and whether the click was on the curve
        const CurveNearest nearest = nearest_on_curve(curve->control_points, event.point);
        lua_pushnumber(L, nearest.t);
        push_vec3(L, glm::dvec3(nearest.point, 0.0));
        lua_pushboolean(L, nearest.distance <= event.radius);
        return 3;
      } else {  // a key, a button label, an option, the text typed
        lua_pushstring(L, event.name.c_str());
      }
      return 1;
    });
  } catch (const std::exception& e) {  // memory ran out making what resumes the step
    fail_with(e);
  }
  return true;
}

// ---- what the panel reads --------------------------------------------------------------------------

const std::string& LessonRunner::title() const { return script_ ? script_->title : kEmptyText; }

const std::string& LessonRunner::summary() const { return script_ ? script_->summary : kEmptyText; }

std::vector<std::string> LessonRunner::step_titles() const {
  std::vector<std::string> titles;
  if (script_) {
    for (const LessonStepDef& step : script_->steps) titles.push_back(step.title);
  }
  return titles;
}

size_t LessonRunner::step_count() const { return script_ ? script_->steps.size() : 0; }

const std::vector<std::string>& LessonRunner::said() const { return script_ ? script_->said : kNoBlocks; }

const LessonTexts& LessonRunner::texts() const {
  static const LessonTexts kNoTexts;
  return script_ ? script_->texts : kNoTexts;
}

const std::vector<LessonBlock>& LessonRunner::blocks() const { return script_ ? script_->blocks : kNoDisplay; }

const std::vector<LessonLive>& LessonRunner::lives() const { return script_ ? script_->lives : kNoLives; }

const std::vector<LessonPlot>& LessonRunner::plots() const { return script_ ? script_->plots : kNoPlots; }

const std::vector<LessonJudgement>& LessonRunner::answered() const { return script_ ? script_->answered : kNoAnswers; }

const LessonJudgement& LessonRunner::last_judgement() const { return script_ ? script_->last_judgement : kNoJudgement; }

size_t LessonRunner::judgements() const { return script_ ? script_->judgements : 0; }

const std::vector<YourTurnVerdict>& LessonRunner::your_turns() const {
  static const std::vector<YourTurnVerdict> kNone;
  return script_ ? script_->your_turns : kNone;
}

const LessonWait& LessonRunner::waiting_for() const { return script_ ? script_->wait : kNoWait; }

}  // namespace meshedit
