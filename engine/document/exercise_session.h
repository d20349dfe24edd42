// ExerciseSession: the window's "mine vs reference" for the mesh exercises (flip, split, normals, upsample) and the
// scripted ones (scripted_exercise.h), as plain data (no ImGui): which exercise is active, the student folder, the
// last report, and the write-by-write replay of the student's operation in the document. A scripted exercise on
// points or a patch runs on one of its fixtures (or on the input a lesson's your_turn gave), not on the document.
//
// Invariants:
// - The student file is read through a StudentFile (student_file.h): loaded again when it is saved, so saving
//   the file in an editor is enough. A file that does not load (syntax error, missing) leaves the document
//   untouched and keeps the error ("flip.lua:3: ...").
// - run_mine / run_reference never throw and change the document by at most one undoable operation, labelled
//   "mine: flip e7" / "reference: flip e7" ("mine (error): ..." when the student's function failed half way);
//   the student's result goes in even when it differs from the reference (validation says what broke). An
//   unchanged mesh (a refusal, the templates) records nothing, nor does a run on points or a patch (the document and
//   the selection are not read; the status line says the verdict).
// - They keep document_actions.h's out-of-memory contract: everything that can fail (the input's copy of the mesh,
//   the run, the label, the status line's text) is made before the document changes, and the run goes in through
//   apply_operation. When memory runs out before that, or under the student's code (a Lua error flagged
//   ExerciseOutcome::out_of_memory, not the student's doing; a student's own error("memory ran out") is an error of
//   the run like any other), nothing is done: an Error that says memory ran out (kMemoryRanOut), the document
//   as it was (a replay in progress finished first, whole). Once the run went in, it is the session's last run.
// - A replay shows states with show_state(), never history: while it runs, the document shows
//   replay(before, edits, k) and `last` is the diff of edit k alone (state k-1 -> k), so the tables highlight
//   the cell edit k wrote. finish_replay() (or stepping to the end) leaves the document at the operation's
//   final state with its single undo entry, as run_mine left it.
// - A replay only starts on the document state run_mine left (same generation and version); if anything else
//   changes the document during a replay, the replay is dropped (sync()) rather than overwrite that change.
//   Callers should finish_replay() before their own edits and undo/redo (a no-op when no replay runs): an undo
//   in the middle of a replay would put the partly replayed state on the redo list.
// - start_mine runs the student's code off the window's thread (student_call_work.h: a thread on the desktop, a Web
//   Worker in a page): the file's StudentCode is lent to the run (StudentFile::lend; the page's worker loads the
//   file's text afresh) and nothing else of the session is touched by it (nor is the exercise registry changed
//   meanwhile: the reload of a scripted exercise's definition is part of a run, refused while one runs, and the window
//   loads exercise folders only as it opens); poll() takes the run into the document as run_mine does, unless the
//   document changed meanwhile (then the result is left out, and the status line says so). While a run is running,
//   every other run and replay is refused (the status line says why), and stop_running() stops the code
//   ("stopped: you pressed Stop": an error of the run; on the desktop at its next line, with its writes up to there to
//   replay). The destructor stops a running run and waits for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/check.h"
#include "core/edit_log.h"
#include "core/halfedge_mesh.h"
#include "document/mesh_document.h"
#include "document/selection.h"
#include "document/student_call_work.h"
#include "document/student_file.h"
#include "exercise/exercises.h"

namespace meshedit {

// The exercises the Exercises tab runs: normals, flip, split, upsample (in the assignment's order), then the scripted
// ones registered from scripts/exercises (scripted_exercise.h), those on points or a patch among them.
std::vector<Exercise> mesh_exercises();

// What the status line says of a run of the student's function ("different: ...; yours is invalid: ..."), and of
// one that failed (its error): the words a bug report's replay gives too (bug_report.h).
std::string mine_verdict(const ExerciseReport& report);

// The last run (mine or the reference) and what it worked on.
struct ExerciseRun {
  Exercise exercise = Exercise::FlipEdge;
  bool mine = true;         // false: the reference alone (report.mine is empty)
  std::string label;        // "mine: flip e7"
  ExerciseInput input;      // input.mesh is the document's mesh before the run
  ExerciseReport report;    // mine runs: check_exercise with record_edits; reference runs: .reference only
  bool applied = false;     // the result went into the document as one undo entry
  uint64_t generation = 0;  // the document's generation and mesh version right after the run
  uint64_t version = 0;
  uint64_t serial = 0;  // +1 per run, so views rebuild what they derive from it once per run
};

class ExerciseSession {
 public:
  explicit ExerciseSession(std::filesystem::path folder = default_student_folder());
  ~ExerciseSession();
  ExerciseSession(const ExerciseSession&) = delete;
  ExerciseSession& operator=(const ExerciseSession&) = delete;

  const std::filesystem::path& folder() const { return folder_; }
  void set_folder(std::filesystem::path folder);  // forgets the loaded code (the next run loads afresh)
  Exercise exercise() const { return exercise_; }
  // Only mesh exercises and scripted ones; anything else is ignored (returns false). Choosing one goes back to its
  // first fixture.
  bool set_exercise(Exercise exercise);
  // A scripted exercise on points or a patch: which of its fixtures the next run uses (false past the last), or the
  // input a lesson's your_turn gave (`what` names it in the label), until another fixture or exercise is chosen.
  size_t fixture() const { return fixture_; }
  bool set_fixture(size_t index);
  void set_values_input(ExerciseInput input, std::string what);
  bool has_values_input() const { return values_input_.has_value(); }
  std::filesystem::path file() const;  // folder() / "flip.lua"

  // The student file differs from the last load attempt (or there was none).
  bool file_changed() const { return student_.changed(); }
  // Loads the file if file_changed(); returns false (and sets load_error()) when it does not load.
  bool ensure_loaded() { return student_.ensure_loaded(); }
  const std::string& load_error() const { return student_.error(); }
  size_t loads() const { return student_.loads(); }  // how many times a file was loaded (tests)

  // The active exercise on the selection (edge or its halfedge for flip/split, vertex for normals, the whole
  // mesh for upsample). Refused (with doc.message) when the selection does not fit or the file does not load.
  // Ends a replay in progress first.
  Check run_mine(MeshDocument& doc, Selection& selection);
  Check run_reference(MeshDocument& doc, Selection& selection);

  // Run mine as the window's button runs it: everything run_mine checks first, then the student's code off the
  // window's thread while it draws (at once in a native build without threads: StudentCallWork). Returns the refusal,
  // or yes once it runs (the run's own Check where it ran at once).
  Check start_mine(MeshDocument& doc, Selection& selection);
  bool running() const { return pending_ != nullptr; }
  double running_seconds() const;            // since start_mine, while running()
  const std::string& running_label() const;  // "mine: flip e7", while running()
  void stop_running();
  // The limits the student's code runs under (the window's: window_student_limits of its setting; LuaLimits' own
  // until set). They apply from the next run.
  void set_limits(const LuaLimits& limits) { limits_ = limits; }
  // Once a started run has ended: takes it into the document as run_mine does and returns true. Call once per frame.
  bool poll(MeshDocument& doc, Selection& selection);
  // Waits for the started run's code to end and takes it as poll() does, returning what run_mine would (yes when no
  // run was started). For tests (a page cannot wait for its worker: a run not ended yet is stopped).
  Check wait_for_run(MeshDocument& doc, Selection& selection);

  const std::optional<ExerciseRun>& last_run() const { return run_; }

  // Replay of the last mine run's recorded writes.
  bool can_replay(const MeshDocument& doc) const;  // a mine run with edits whose state the document still shows
  bool replaying() const { return replaying_; }
  size_t replay_position() const { return position_; }  // k: edits 1..k applied
  size_t replay_length() const;                         // N
  const std::vector<RecordedEdit>& edits() const;       // empty without a mine run
  // Shows the before-mesh (k = 0). Refused when !can_replay(doc).
  Check start_replay(MeshDocument& doc);
  // Shows state k (clamped to N); `last` is edit k alone. Refused when not replaying.
  Check replay_step(MeshDocument& doc, size_t k);
  // Back to the operation's final state with its diff as `last`; no-op when not replaying.
  void finish_replay(MeshDocument& doc);
  // Drops the replay when the document no longer shows the state the replay put there (an undo, an edit, a
  // new file). Call once per frame; cheap.
  void sync(const MeshDocument& doc);

 private:
  // A run made before the document changes: its result, the status line's parts and what run() returns.
  struct PreparedRun {
    ExerciseRun result;
    std::string verdict;         // "(...)" after the document's own message
    std::string unchanged_text;  // the whole message when the mesh does not change
    Severity severity = Severity::Info;
    Check returned;
    std::optional<HalfedgeMesh> mesh;  // the run's mesh, when it differs from the document's
  };

  // A run between its start and its result: the checks done, the reference run, the student's code lent to it.
  struct PendingRun;

  Check run(MeshDocument& doc, Selection& selection, bool mine);
  // Everything before the student's code: the input, the file loaded, the label, the reference. A refusal is returned
  // with `pending` left empty (its message set); std::bad_alloc escapes with the document as it was.
  Check begin_run(MeshDocument& doc, Selection& selection, bool mine, std::unique_ptr<PendingRun>& pending);
  // Everything after it: the comparison and the texts, as a PreparedRun (or a refusal with `prepared` left empty);
  // std::bad_alloc escapes with the document as it was.
  Check end_run(MeshDocument& doc, PendingRun& pending, std::optional<PreparedRun>& prepared);
  // end_run, then take_run; a std::bad_alloc on the way is an Error with nothing done.
  Check end_and_take(MeshDocument& doc, Selection& selection, PendingRun& pending);
  // A started run that has ended, into the document (or left out when the document changed since it started).
  Check take_pending(MeshDocument& doc, Selection& selection);
  Check refuse_while_running(MeshDocument& doc) const;
  // Puts the prepared run in the document (apply_operation, which never throws) and says so; cannot fail.
  Check take_run(MeshDocument& doc, Selection& selection, PreparedRun&& run) noexcept;
  void show(MeshDocument& doc, HalfedgeMesh mesh, std::string label, std::optional<HalfedgeMesh> from);

  // The input of a run on points or a patch, or why there is none.
  OpResult<ExerciseInput> values_input_for(std::string& what) const;

  std::filesystem::path folder_;
  Exercise exercise_ = Exercise::FlipEdge;
  size_t fixture_ = 0;
  std::optional<ExerciseInput> values_input_;
  std::string values_input_name_;
  StudentFile student_;

  std::optional<ExerciseRun> run_;
  uint64_t runs_ = 0;
  bool replaying_ = false;
  size_t position_ = 0;
  uint64_t shown_generation_ = 0;  // what the replay last put in the document
  uint64_t shown_version_ = 0;

  LuaLimits limits_;
  std::unique_ptr<PendingRun> pending_;  // the started run, until poll() takes it
  StudentCallWork work_;                 // last: destroyed first, it ends the run that pending_ started
};

}  // namespace meshedit
