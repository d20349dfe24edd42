// ExerciseSession: see exercise_session.h for the contract.
//
// Kept here: the document is only written through apply_operation (the run, one undo entry) and show_state
// (replay frames, no history), and every replay frame is rebuilt from the run's before-mesh with core replay(),
// so stepping backwards is as exact as stepping forwards.
//
// A run is begun (begin_run: the checks, the label, the reference, the student's code lent to it), its code run
// (PendingRun::run_code, on the caller's thread for run(), on the run's own for start_mine), ended (end_run: the
// comparison and the texts, the run's mesh copied out of its report) and then taken (take_run: apply_operation, which
// never throws, and messages that fall back to kMemoryRanOut), as the document's actions do; a std::bad_alloc before
// take_run becomes an Error with nothing done.
#include "document/exercise_session.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "core/mesh_error.h"
#include "core/translation.h"
#include "document/document_actions.h"
#include "document/exception_report.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "script/lua_runtime.h"

namespace meshedit {
namespace {

// Moved into run_ and the document after the document changed: moves that cannot fail.
static_assert(std::is_nothrow_move_constructible_v<ExerciseRun> && std::is_nothrow_move_assignable_v<ExerciseRun>);
static_assert(std::is_nothrow_move_assignable_v<HalfedgeMesh>);

const char* operation_word(Exercise exercise) {
  switch (exercise.kind()) {
    case ExerciseKind::FlipEdge: return "flip";
    case ExerciseKind::SplitEdge: return "split";
    case ExerciseKind::VertexNormal: return "normal";
    case ExerciseKind::Upsample: return "upsample";
    default: return exercise_info(exercise).name;
  }
}

// "select a face first: flip_face(mesh, f)": the selection a scripted exercise asks for.
std::string select_first(ElementKind kind, const std::string& signature) {
  const MessageParts parts = {{"signature", signature}, {"kind", kind_name(kind)}};
  switch (kind) {
    case ElementKind::Vertex: return tr_format("select a vertex first: {signature}", parts);
    case ElementKind::Halfedge: return tr_format("select a halfedge first: {signature}", parts);
    case ElementKind::Edge: return tr_format("select an edge first: {signature}", parts);
    case ElementKind::Face: return tr_format("select a face first: {signature}", parts);
    case ElementKind::Boundary: return tr_format("select a boundary first: {signature}", parts);
  }
  return tr_format("select a {kind} first: {signature}", parts);
}

// The input the active exercise takes from the selection, or why the selection does not fit.
OpResult<ExerciseInput> input_for(Exercise exercise, const MeshDocument& doc, const Selection& selection) {
  auto mesh = std::make_shared<const HalfedgeMesh>(doc.mesh);
  switch (exercise.kind()) {
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge: {
      const OpResult<EdgeId> edge = edge_for_operation(doc.mesh, selection.selected);
      if (!edge.ok()) return {edge.check, {}};
      return {Check::yes(), ExerciseInput::edge(std::move(mesh), edge.value)};
    }
    case ExerciseKind::VertexNormal: {
      const ElementRef ref = selection.selected;
      if (!ref.valid() || ref.kind != ElementKind::Vertex) return {Check::no(tr("select a vertex first")), {}};
      if (reference_state(doc.mesh, ref) != RefState::Live) return {Check::no(reference_problem(doc.mesh, ref)), {}};
      return {Check::yes(), ExerciseInput::vertex(std::move(mesh), VertexId(ref.index))};
    }
    case ExerciseKind::Upsample: return {Check::yes(), ExerciseInput::whole_mesh(std::move(mesh))};
    default: break;
  }
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition()) {
    if (!scripted->takes()) return {Check::yes(), ExerciseInput::whole_mesh(std::move(mesh))};
    const ElementKind kind = *scripted->takes();
    if (kind == ElementKind::Edge) {  // as flip and split take it: a selected halfedge names its edge
      const OpResult<EdgeId> edge = edge_for_operation(doc.mesh, selection.selected);
      if (!edge.ok()) return {edge.check, {}};
      return {Check::yes(), ExerciseInput::element_of(std::move(mesh), edge.value)};
    }
    const ElementRef ref = selection.selected;
    if (!ref.valid() || ref.kind != kind) return {Check::no(select_first(kind, scripted->info().signature)), {}};
    if (reference_state(doc.mesh, ref) != RefState::Live) return {Check::no(reference_problem(doc.mesh, ref)), {}};
    return {Check::yes(), ExerciseInput::element_of(std::move(mesh), ref)};
  }
  return {Check::no(tr_format("{exercise} is not a mesh exercise", {{"exercise", exercise_info(exercise).name}})), {}};
}

std::string point_text(const std::vector<glm::dvec3>& points) {
  if (points.empty()) return tr("nothing");
  const glm::dvec3& p = points.front();
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

}  // namespace

std::string mine_verdict(const ExerciseReport& report) {
  const ExerciseOutcome& mine = report.mine;
  if (!mine.error.empty()) return mine.error;
  if (mine.validation && !mine.validation->ok()) {
    return tr_format("{summary}; yours is invalid: {problems}",
                     {{"summary", report.summary()}, {"problems", mine.validation->summary()}});
  }
  return report.summary();
}

std::vector<Exercise> mesh_exercises() {
  std::vector<Exercise> all = {Exercise::VertexNormal, Exercise::FlipEdge, Exercise::SplitEdge, Exercise::Upsample};
  for (Exercise scripted : exercise_registry().scripted()) all.push_back(scripted);
  return all;
}

struct ExerciseSession::PendingRun {
  PreparedRun run;  // its result so far: the exercise, mine or the reference, the label, the input
  bool on_values = false;
  std::string target;  // " e7", " (fixture)" or ""
  ExerciseOutcome reference;
  std::unique_ptr<StudentCode> code;  // mine: lent by the student file for the run
  uint64_t code_serial = 0;
  StudentCall call;  // mine: what runs (its file's text too, for a host that loads it afresh)
  // What the student's code gave, once it has ended.
  ExerciseOutcome mine;
  bool out_of_memory = false;
  std::string thrown;
  // The document's state when it started (a started run only).
  uint64_t generation = 0;
  uint64_t version = 0;
  std::chrono::steady_clock::time_point started;

  // The student's code on the input, here. Never throws.
  void run_code() noexcept { keep(run_student_call_on(*code, call)); }
  void keep(StudentCallResult result) noexcept {
    mine = std::move(result.outcome);
    out_of_memory = result.out_of_memory;
    thrown = std::move(result.thrown);
    if (!result.load_error.empty()) thrown = std::move(result.load_error);  // the file loaded here, not there: a bug
  }
};

ExerciseSession::ExerciseSession(std::filesystem::path folder)
    : folder_(std::move(folder)), student_(folder_ / exercise_info(exercise_).file) {}

ExerciseSession::~ExerciseSession() {
  stop_running();
  work_.take();
}

void ExerciseSession::set_folder(std::filesystem::path folder) {
  folder_ = std::move(folder);
  student_.set_path(file());
}

bool ExerciseSession::set_exercise(Exercise exercise) {
  if (!is_mesh_exercise(exercise) && !exercise.definition()) return false;
  exercise_ = exercise;
  fixture_ = 0;
  values_input_.reset();
  student_.set_path(file());
  return true;
}

bool ExerciseSession::set_fixture(size_t index) {
  const std::shared_ptr<const ScriptedExercise> scripted = exercise_.definition();
  if (!scripted || !scripted->takes_values() || index >= scripted->fixtures().size()) return false;
  fixture_ = index;
  values_input_.reset();
  return true;
}

void ExerciseSession::set_values_input(ExerciseInput input, std::string what) {
  values_input_ = std::move(input);
  values_input_name_ = std::move(what);
}

OpResult<ExerciseInput> ExerciseSession::values_input_for(std::string& what) const {
  const std::shared_ptr<const ScriptedExercise> scripted = exercise_.definition();
  if (values_input_) {
    what = values_input_name_;
    return {Check::yes(), *values_input_};
  }
  if (!scripted || fixture_ >= scripted->fixtures().size()) {
    return {Check::no(tr_format("{exercise} has no fixture to run on (its definition's fixtures = {{...}})",
                                {{"exercise", exercise_info(exercise_).name}})),
            {}};
  }
  const ScriptedFixture& fixture = scripted->fixtures()[fixture_];
  what = fixture.name;
  return {Check::yes(), scripted->input_of(fixture)};
}

std::filesystem::path ExerciseSession::file() const { return folder_ / exercise_info(exercise_).file; }

Check ExerciseSession::run_mine(MeshDocument& doc, Selection& selection) { return run(doc, selection, true); }
Check ExerciseSession::run_reference(MeshDocument& doc, Selection& selection) { return run(doc, selection, false); }

Check ExerciseSession::run(MeshDocument& doc, Selection& selection, bool mine) {
  if (pending_) return refuse_while_running(doc);
  std::unique_ptr<PendingRun> pending;
  try {
    Check refused = begin_run(doc, selection, mine, pending);
    if (!pending) return refused;
  } catch (const std::exception& e) {
    // Nothing was done: the document is as it was (or as finish_replay left it, whole). The report needs no memory.
    report_exception(doc, e);
    return Check::no(kMemoryRanOut);  // fits std::string's inline buffer: no allocation
  }
  if (mine) {
    pending->run_code();
    student_.give_back(std::move(pending->code), pending->code_serial);
  }
  return end_and_take(doc, selection, *pending);
}

Check ExerciseSession::end_and_take(MeshDocument& doc, Selection& selection, PendingRun& pending) {
  std::optional<PreparedRun> prepared;
  try {
    Check ended = end_run(doc, pending, prepared);
    if (!prepared) return ended;
  } catch (const std::exception& e) {
    report_exception(doc, e);  // nothing was done, as above
    return Check::no(kMemoryRanOut);
  }
  return take_run(doc, selection, std::move(*prepared));
}

Check ExerciseSession::refuse_while_running(MeshDocument& doc) const {
  Check no = Check::no(tr_format("your code is still running ({run}): wait for it, or press Stop",
                                 {{"run", pending_->run.result.label}}));
  set_message_noexcept(doc, Severity::Warning, [&] { return no.reason; });
  return no;
}

Check ExerciseSession::start_mine(MeshDocument& doc, Selection& selection) {
  if (pending_) return refuse_while_running(doc);
  try {
    std::unique_ptr<PendingRun> pending;
    Check refused = begin_run(doc, selection, true, pending);
    if (!pending) return refused;
    pending->generation = doc.generation;
    pending->version = doc.mesh.version();
    pending->started = std::chrono::steady_clock::now();
    set_message(doc, Severity::Info,
                tr_format("{run}: your code is running (Stop ends it)", {{"run", pending->run.result.label}}));
    pending_ = std::move(pending);
    try {
      work_.start(std::move(pending_->call), std::move(pending_->code));
    } catch (...) {  // no thread to be had: nothing ran
      student_.give_back(work_.take_code(), pending_->code_serial);
      pending_.reset();
      throw;
    }
  } catch (const std::exception& e) {
    report_exception(doc, e);
    return Check::no(kMemoryRanOut);
  }
  if (work_.done()) return take_pending(doc, selection);  // a host without threads ran it at once
  return Check::yes();
}

double ExerciseSession::running_seconds() const {
  if (!pending_) return 0.0;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - pending_->started).count();
}

const std::string& ExerciseSession::running_label() const {
  static const std::string kNone;
  return pending_ ? pending_->run.result.label : kNone;
}

void ExerciseSession::stop_running() {
  if (pending_) work_.stop();
}

bool ExerciseSession::poll(MeshDocument& doc, Selection& selection) {
  if (!pending_ || !work_.done()) return false;
  take_pending(doc, selection);
  return true;
}

Check ExerciseSession::wait_for_run(MeshDocument& doc, Selection& selection) {
  if (!pending_) return Check::yes();
  return take_pending(doc, selection);  // take() waits for the thread
}

Check ExerciseSession::take_pending(MeshDocument& doc, Selection& selection) {
  const std::unique_ptr<PendingRun> pending = std::move(pending_);
  pending->keep(work_.take());
  student_.give_back(work_.take_code(), pending->code_serial);
  if (doc.generation != pending->generation || doc.mesh.version() != pending->version) {
    Check no =
        Check::no(tr_format("{run}: the mesh changed while your code ran, so its result is left out: run it "
                            "again",
                            {{"run", pending->run.result.label}}));
    set_message_noexcept(doc, Severity::Warning, [&] { return no.reason; });
    return no;
  }
  return end_and_take(doc, selection, *pending);
}

Check ExerciseSession::begin_run(MeshDocument& doc, Selection& selection, bool mine,
                                 std::unique_ptr<PendingRun>& pending) {
  finish_replay(doc);
  const char* who = mine ? "mine" : "reference";
  // An instructor's exercise whose definition was saved since: its new version runs (or its error is shown).
  if (const std::string error = exercise_registry().reload_if_changed(exercise_); !error.empty()) {
    Check refused = Check::no(tr_format("the exercise's definition did not load: {error}", {{"error", error}}));
    set_message_noexcept(doc, Severity::Error, [&] { return refused.reason; });
    return refused;
  }
  const std::shared_ptr<const ScriptedExercise> scripted = exercise_.definition();
  const bool on_values = scripted && scripted->takes_values();
  std::string values_what;
  OpResult<ExerciseInput> input = on_values ? values_input_for(values_what) : input_for(exercise_, doc, selection);
  if (!input.ok()) {
    // A refusal for lack of memory is an Error: memory to spare might have run it.
    const Severity severity = input.check.reason == kMemoryRanOut ? Severity::Error : Severity::Warning;
    set_message_noexcept(doc, severity, [&] {
      return tr_format(mine ? "mine: {reason}" : "reference: {reason}", {{"reason", input.check.reason}});
    });
    return std::move(input.check);
  }
  if (mine && !ensure_loaded()) {
    Check refused = Check::no(load_error());
    run_.reset();
    set_message_noexcept(doc, Severity::Error, [&] { return load_error(); });
    return refused;
  }

  auto made = std::make_unique<PendingRun>();
  ExerciseRun& result = made->run.result;
  result.exercise = exercise_;
  result.mine = mine;
  result.serial = runs_ + 1;
  made->on_values = on_values;
  made->target = on_values                     ? " (" + values_what + ")"
                 : input.value.element.valid() ? " " + format_id(input.value.element)
                                               : std::string();
  result.label = who + std::string(": ") + operation_word(exercise_) + made->target;
  result.input = input.value;
  try {
    if (mine) {
      made->reference = meshedit::run_reference(exercise_, result.input);
    } else {
      result.report.exercise = exercise_;
      result.report.reference = meshedit::run_reference(exercise_, result.input);
    }
  } catch (const std::bad_alloc&) {
    throw;                             // run() reports it: nothing was done
  } catch (const std::exception& e) {  // the reference promises not to throw; a bug must not close the window
    run_.reset();
    set_message_noexcept(doc, Severity::Error, [&] {
      return tr_format("{change}: {reason}", {{"change", result.label}, {"reason", e.what()}});
    });
    return Check::no(e.what());
  }
  if (mine) {
    made->call.exercise = exercise_;
    made->call.input = result.input;
    made->call.options.record_edits = true;
    made->call.limits = limits_;
    try {
      made->call.files.push_back(read_student_source(student_.path()));
    } catch (const ScriptError& e) {  // gone since it loaded
      Check refused = Check::no(e.what());
      set_message_noexcept(doc, Severity::Error, [&] { return refused.reason; });
      return refused;
    }
    made->code_serial = student_.serial();
    made->code = student_.lend();
  }
  pending = std::move(made);
  return Check::yes();
}

Check ExerciseSession::end_run(MeshDocument& doc, PendingRun& pending, std::optional<PreparedRun>& prepared) {
  PreparedRun& run = pending.run;
  ExerciseRun& result = run.result;
  const bool mine = result.mine;
  if (pending.out_of_memory) throw std::bad_alloc();  // under the student's code, not of its doing: nothing is done
  try {
    if (!pending.thrown.empty()) throw std::runtime_error(pending.thrown);
    if (mine) {
      result.report = compare(result.exercise, result.input, std::move(pending.mine), std::move(pending.reference));
    }
  } catch (const std::bad_alloc&) {
    throw;                             // run() reports it: nothing was done
  } catch (const std::exception& e) {  // the run promises not to throw; a bug must not close the window
    run_.reset();
    set_message_noexcept(doc, Severity::Error, [&] {
      return tr_format("{change}: {reason}", {{"change", result.label}, {"reason", e.what()}});
    });
    return Check::no(e.what());
  }

  const ExerciseOutcome& outcome = mine ? result.report.mine : result.report.reference;
  // Memory that ran out under the student's code (a binding's std::bad_alloc, turned into a Lua error flagged
  // out_of_memory) is not the student's error: nothing is done, as for the reference's std::bad_alloc. The flag, not
  // the text: a student's own error("memory ran out") is the student's error.
  if (outcome.out_of_memory) throw std::bad_alloc();
  const bool failed = !outcome.error.empty();
  if (failed && mine) result.label = "mine (error): " + std::string(operation_word(result.exercise)) + pending.target;
  // The status line says what happened beyond "N fields changed": made now, before the document changes.
  if (failed) {
    run.verdict = outcome.error;
  } else if (!mine) {
    run.verdict = outcome.refused.empty() ? tr_format("returned {value}", {{"value", outcome.returned}})
                                          : tr_format("refused: {reason}", {{"reason", outcome.refused}});
    if (result.exercise == Exercise::VertexNormal) {
      run.verdict = tr_format("normal {point}", {{"point", point_text(outcome.points)}});
    }
  } else {
    run.verdict = mine_verdict(result.report);
  }
  run.severity = failed || (mine && !result.report.equal) ? Severity::Warning : Severity::Info;
  const MessageParts parts = {{"change", result.label}, {"reason", run.verdict}, {"verdict", run.verdict}};
  run.unchanged_text = pending.on_values ? tr_format("{change}: {reason}", parts)
                                         : tr_format("{change}: nothing changed ({verdict})", parts);
  run.returned = failed ? Check::no(outcome.error) : Check::yes();
  if (outcome.mesh && !outcome.mesh->same_as(doc.mesh)) run.mesh = *outcome.mesh;  // the report keeps its own
  prepared = std::move(run);
  return Check::yes();
}

Check ExerciseSession::take_run(MeshDocument& doc, Selection& selection, PreparedRun&& run) noexcept {
  ExerciseRun& result = run.result;
  ++runs_;
  if (run.mesh) {
    const uint64_t seen = doc.mesh.version();
    Check check = apply_operation(doc, result.label, [&](HalfedgeMesh& mesh) {
      mesh = std::move(*run.mesh);  // a move: the mesh is never left half copied
      mesh.bump_version_above(seen);
      return Check::yes();
    });
    if (!check.ok) {  // not done (memory ran out): apply_operation's message says so
      run_.reset();
      return check;  // moved: no copy to run out of memory
    }
    result.applied = true;
    keep_if_alive(selection, doc.mesh);
    // Kept without its record, the document's Warning stays a Warning.
    const Severity severity = std::max(run.severity, doc.message.severity);
    set_message_noexcept(doc, severity, [&] {
      return tr_format("{message} ({verdict})", {{"message", doc.message.text}, {"verdict", run.verdict}});
    });
  } else {
    set_message(doc, run.severity, std::move(run.unchanged_text));
  }
  result.generation = doc.generation;
  result.version = doc.mesh.version();
  run_ = std::move(result);
  return std::move(run.returned);
}

const std::vector<RecordedEdit>& ExerciseSession::edits() const {
  static const std::vector<RecordedEdit> kNone;
  return run_ && run_->mine ? run_->report.mine.edits : kNone;
}

size_t ExerciseSession::replay_length() const { return edits().size(); }

bool ExerciseSession::can_replay(const MeshDocument& doc) const {
  if (pending_) return false;  // a run is running: its result replaces the last run's
  if (!run_ || !run_->mine || !run_->applied || edits().empty() || !run_->input.mesh) return false;
  if (replaying_) return true;
  return doc.generation == run_->generation && doc.mesh.version() == run_->version;
}

void ExerciseSession::show(MeshDocument& doc, HalfedgeMesh mesh, std::string label, std::optional<HalfedgeMesh> from) {
  show_state(doc, std::move(mesh), std::move(label), std::move(from));
  shown_generation_ = doc.generation;
  shown_version_ = doc.mesh.version();
}

Check ExerciseSession::start_replay(MeshDocument& doc) {
  if (pending_) return refuse_while_running(doc);
  if (!can_replay(doc)) {
    const Check no = Check::no(tr("nothing to replay: run mine on a mesh exercise first (and do not edit in between)"));
    set_message(doc, Severity::Warning, no.reason);
    return no;
  }
  replaying_ = true;
  position_ = 0;
  const HalfedgeMesh& before = *run_->input.mesh;
  show(doc, before,
       tr_format("replay {step}/{steps}: before {run}",
                 {{"step", "0"}, {"steps", std::to_string(replay_length())}, {"run", run_->label}}),
       before);
  return Check::yes();
}

Check ExerciseSession::replay_step(MeshDocument& doc, size_t k) {
  if (!replaying_) return Check::no("no replay in progress");
  k = std::min(k, replay_length());
  const HalfedgeMesh& before = *run_->input.mesh;
  const std::vector<RecordedEdit>& log = edits();
  try {
    HalfedgeMesh previous = replay(before, log, k == 0 ? 0 : k - 1);
    HalfedgeMesh state = previous;
    std::string label = tr_format("replay {step}/{steps}: before {run}",
                                  {{"step", "0"}, {"steps", std::to_string(log.size())}, {"run", run_->label}});
    if (k > 0) {
      apply_edit(state, log[k - 1]);
      const RecordedEdit& edit = log[k - 1];
      const MessageParts parts = {{"step", std::to_string(k)},
                                  {"steps", std::to_string(log.size())},
                                  {"edit", describe(edit)},
                                  {"where", edit.where}};
      label = edit.where.empty() ? tr_format("replay {step}/{steps}: {edit}", parts)
                                 : tr_format("replay {step}/{steps}: {edit}  ({where})", parts);
    }
    show(doc, std::move(state), std::move(label), std::move(previous));
  } catch (const std::exception& e) {
    // The recording promises a faithful replay; if it is not, say so and go back to the real result.
    const Check no = Check::no(
        tr_format("replay failed at write {write}: {error}", {{"write", std::to_string(k)}, {"error", e.what()}}));
    finish_replay(doc);
    set_message(doc, Severity::Error, no.reason);
    return no;
  }
  position_ = k;
  return Check::yes();
}

void ExerciseSession::finish_replay(MeshDocument& doc) {
  if (!replaying_) return;
  sync(doc);
  if (!replaying_) return;  // the document moved on: leave it alone
  // Copied first: when memory runs out here the replay goes on as it was.
  HalfedgeMesh final_state = *run_->report.mine.mesh;
  std::string label = run_->label;
  std::optional<HalfedgeMesh> before(*run_->input.mesh);
  replaying_ = false;
  show(doc, std::move(final_state), std::move(label), std::move(before));
  run_->generation = doc.generation;
  run_->version = doc.mesh.version();
}

void ExerciseSession::sync(const MeshDocument& doc) {
  if (replaying_ && (doc.generation != shown_generation_ || doc.mesh.version() != shown_version_)) replaying_ = false;
}

}  // namespace meshedit
