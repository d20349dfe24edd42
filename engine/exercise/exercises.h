// "Mine vs reference": the six student exercises (scripts/student/*.lua), and those an instructor defines in Lua
// (scripted_exercise.h), running a student's function and the reference on copies of the same input, and a report
// that points at the mistake.
//
//   auto code = load_student_file("scripts/student/flip.lua");          // ScriptError "flip.lua:3: ..." if broken
//   const ExerciseInput input = ExerciseInput::edge(mesh, EdgeId(5));
//   const ExerciseReport report = check_exercise(*code, Exercise::FlipEdge, input);
//   report.equal, report.differences ("f0.halfedge is h5, but h5.face is f1"), report.mine.mesh, ...
//
// Invariants:
// - Neither run changes the input: "mine" and the reference each get their own copy of the mesh (or their own
//   points), and the outcomes hold those copies for side-by-side tables.
// - Student code runs in its own LuaRuntime (the sandbox and limits of lua_runtime.h), one per
//   StudentCode; a Lua error, a limit or a wrong return type becomes ExerciseOutcome::error, never an
//   exception out of run_mine. After "mine" on a mesh, validate() always runs.
// - Student code sees the student API of student_api.h, grading's own: the file functions and the exercises'
//   reference operations hidden (a refusal in the same words), upsample given mesh:flip, mesh:split and the
//   reference flip_edge and split_edge.
// - The reference is the core: de_casteljau_step, evaluate_patch, vertex_normal (area-weighted), flip, split
//   and loop_subdivide with the course's weights (core/loop_subdivision.h), so "mine" and the app's own
//   operations agree by construction. A scripted exercise's reference is its definition's Lua function.
// - An Exercise is a handle: its kind() is one of the six built-in kinds, or Scripted with the definition the
//   registry that made it holds (exercise_registry.h). Every handle names a real exercise: there are no ids to cast
//   and no unknown value; a name that names none is an error where it is looked up (ExerciseRegistry::find).
//   exercise_info and everything below take both kinds; a scripted exercise works on a mesh (and the element its
//   definition takes), or on control points or a patch and the values after them (ExerciseInput::args), returning
//   values (ExerciseOutcome::value).
// - `equal` is the verdict (the same answer as the reference, up to renumbering and rounding); `identical`
//   is stronger (bit for bit, pointer for pointer). The correct solutions in tests/exercise/solutions are
//   identical on every input the tests use.
// - Messages name elements with format_id, say "yours" and "the reference", and put the likely mistake first. The
//   grader records the same messages (expect.exercise), so the window and the grader say the same thing.
// - A flip or a split must do a constant amount of work: on a big mesh, one that touches more elements than
//   exercise_locality.h allows is not equal to the reference, whatever mesh it leaves. run_mine counts what a flip or
//   a split touched (ExerciseOutcome::touched); the grader counts the student's calls the same way.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "core/bezier.h"
#include "core/edit_log.h"
#include "core/halfedge_mesh.h"
#include "core/validate.h"
#include "exercise/exercise_value.h"
#include "script/lua_runtime.h"
#include "script/touch_recorder.h"

namespace meshedit {

// What an exercise is: one of the six built-in ones, or one defined in Lua (scripted_exercise.h).
enum class ExerciseKind { CurveStep, PatchEvaluate, VertexNormal, FlipEdge, SplitEdge, Upsample, Scripted };

class ScriptedExercise;
struct ExerciseSlot;  // a registered name's place in its registry (exercise_registry.h)

struct ExerciseInfo {
  const char* name;       // "curve", "patch", "normals", "flip", "split", "upsample" (stable: CLI, grader)
  const char* file;       // "curve.lua" in scripts/student/
  const char* function;   // "evaluate_step"
  const char* signature;  // "evaluate_step(points, t) -> list of n - 1 vec3"
  const char* title;      // "Part 1: a de Casteljau step"
};

// A handle on one exercise. The built-in ones are Exercise::CurveStep ... Exercise::Upsample; a scripted one comes
// from ExerciseRegistry::add or find, and stays valid while its registry lives. Two handles are equal when they name
// the same exercise (a scripted name registered again keeps its handle).
class Exercise {
 public:
  // Named as ExerciseKind's enumerators, which they stand for.
  // NOLINTBEGIN(readability-identifier-naming)
  static const Exercise CurveStep, PatchEvaluate, VertexNormal, FlipEdge, SplitEdge, Upsample;
  // NOLINTEND(readability-identifier-naming)

  constexpr ExerciseKind kind() const { return kind_; }
  constexpr bool scripted() const { return kind_ == ExerciseKind::Scripted; }
  // A scripted exercise's definition (the one registered last under its name); nullptr for the built-in ones.
  std::shared_ptr<const ScriptedExercise> definition() const;
  // Its name, file and function. A scripted one's strings are its definition's, good until its name is registered
  // again.
  const ExerciseInfo& info() const;

  friend constexpr bool operator==(const Exercise&, const Exercise&) = default;

 private:
  friend class ExerciseRegistry;
  constexpr explicit Exercise(ExerciseKind kind, const ExerciseSlot* slot = nullptr) : kind_(kind), slot_(slot) {}
  ExerciseKind kind_;
  const ExerciseSlot* slot_;  // Scripted: its slot in the registry; built-in: nullptr
};

inline constexpr Exercise Exercise::CurveStep{ExerciseKind::CurveStep};
inline constexpr Exercise Exercise::PatchEvaluate{ExerciseKind::PatchEvaluate};
inline constexpr Exercise Exercise::VertexNormal{ExerciseKind::VertexNormal};
inline constexpr Exercise Exercise::FlipEdge{ExerciseKind::FlipEdge};
inline constexpr Exercise Exercise::SplitEdge{ExerciseKind::SplitEdge};
inline constexpr Exercise Exercise::Upsample{ExerciseKind::Upsample};

// The six built-in ones, in the assignment's order.
std::span<const Exercise> builtin_exercises();
// exercise.info().
const ExerciseInfo& exercise_info(Exercise exercise);
// Whether the exercise works on a mesh: normals, flip, split, upsample and the scripted exercises that take a mesh or
// one of its elements (not those on points or a patch).
bool is_mesh_exercise(Exercise exercise);

// What one run works on. Build it with the named constructors; fields not used by the exercise are ignored.
struct ExerciseInput {
  std::vector<glm::dvec3> points;            // CurveStep: the points given to evaluate_step
  double t = 0.5;                            // CurveStep
  BezierPatch patch;                         // PatchEvaluate
  double u = 0.5, v = 0.5;                   // PatchEvaluate
  std::shared_ptr<const HalfedgeMesh> mesh;  // the mesh exercises (never changed: runs work on copies)
  ElementRef element;               // VertexNormal: the vertex; FlipEdge, SplitEdge: the edge; scripted: what it takes
  std::vector<ExerciseValue> args;  // scripted on points (`points`) or a patch (`patch`): what follows the input

  static ExerciseInput curve_step(std::vector<glm::dvec3> points, double t);
  static ExerciseInput patch_point(const BezierPatch& patch, double u, double v);
  static ExerciseInput vertex(std::shared_ptr<const HalfedgeMesh> mesh, VertexId v);
  static ExerciseInput edge(std::shared_ptr<const HalfedgeMesh> mesh, EdgeId e);
  static ExerciseInput whole_mesh(std::shared_ptr<const HalfedgeMesh> mesh);
  static ExerciseInput element_of(std::shared_ptr<const HalfedgeMesh> mesh, ElementRef element);
  static ExerciseInput of_points(std::vector<glm::dvec3> points, std::vector<ExerciseValue> args);
  static ExerciseInput of_patch(const BezierPatch& patch, std::vector<ExerciseValue> args);

  // "4 points, t = 0.3", "(u, v) = (0.3, 0.8)", "v3 of a mesh with 12 faces", "e5 of ...", "a mesh with ...",
  // "4 control points", "a patch of 16 control points, then 0.5, 0.5".
  std::string describe(Exercise exercise) const;
};

// What one run (mine or the reference) gave.
struct ExerciseOutcome {
  bool ran = false;            // the function returned a value of the expected shape
  std::string error;           // why not: the Lua error ("flip.lua:12: attempt to index a nil value (field
                               // 'twin')"), a limit, or "evaluate_step returned nil; ..."
  bool out_of_memory = false;  // `error` is memory running out under the call (ScriptError::out_of_memory), not the
                               // student's doing; a student's own error("memory ran out") is not
  ScriptError::Limit limit = ScriptError::Limit::None;  // the limit or cap that stopped the call, if one did
  std::string returned;            // the first return value, described: "nil", "e5", "a list of 3 points", "(0, 0, 1)"
  std::vector<glm::dvec3> points;  // CurveStep: the step; PatchEvaluate, VertexNormal: the one point
  ExerciseValue value;             // scripted on points or a patch: what the function returned
  std::shared_ptr<HalfedgeMesh> mesh;  // the mesh after the call (mesh exercises; the copy it ran on)
  ElementRef element;                  // FlipEdge, SplitEdge: the element returned (invalid for nil)
  std::string refused;                 // reference only: the core's reason when it refuses (flip of a boundary edge...)
  std::optional<ValidationReport> validation;  // mesh exercises, after the call
  std::vector<RecordedEdit> edits;             // mine on a mesh, when RunOptions::record_edits (an upsample: always)
  std::optional<TouchCount> touched;  // mine, for the exercises held to a bound (exercise_locality.h): what the run
                                      // touched of its mesh
  std::vector<std::string> output;    // what print() wrote during the call (capped)

  // The one way a script error becomes the outcome: `error` is `prefix` and its text, with its out_of_memory flag
  // and its limit.
  void fail_with(const ScriptError& e, std::string_view prefix = {});
};

struct RunOptions {
  bool record_edits = false;  // fill ExerciseOutcome::edits (for the app's write-by-write replay; upsample always)
  // The most changes recorded before the run is stopped (a Lua error at the line making the next one); 0: the
  // exercise's own bound (upsample: upsample_edit_budget of the input, upsample_runaway.h; others EditRecorder's).
  size_t max_edits = 0;
};

// One or more student files loaded into one fresh LuaRuntime (so upsample.lua may call a flip_edge defined
// in flip.lua when both are loaded).
class StudentCode {
 public:
  explicit StudentCode(LuaLimits limits = {});
  ~StudentCode();
  StudentCode(const StudentCode&) = delete;
  StudentCode& operator=(const StudentCode&) = delete;

  // Runs the file (under the limits). Throws ScriptError whose message starts with "name.lua:LINE:" for a
  // syntax or runtime error, or "cannot open PATH". The file's name (without folders) is its chunk name.
  void load(const std::filesystem::path& file);
  // Runs `code` as load() runs a file named `name` ("flip.lua": its chunk name); `code` as read_lua_file reads one.
  void load_text(std::string_view code, const std::string& name);
  // Whether the exercise's function exists: a field of a table a loaded file returned, else a global.
  bool defines(Exercise exercise);
  // Calls the student's function on a copy of the input. Never throws for anything the script does.
  ExerciseOutcome run(Exercise exercise, const ExerciseInput& input, const RunOptions& options = {});

  LuaRuntime& runtime() { return *runtime_; }

 private:
  void run_protected(int closure_ref);
  bool push_function(Exercise exercise);
  // Shows what `exercise` may use of the student API (student_api.h) and installs its reference functions; with
  // nullptr, hides everything hideable. Throws ScriptError if the bindings cannot be restricted.
  void open_exercise_api(const Exercise* exercise);

  std::unique_ptr<LuaRuntime> runtime_;
  int helpers_ref_ = -1;  // registry ref: the helper functions, made before any student code runs
  int modules_ref_ = -1;  // registry ref: list of tables the loaded files returned
  std::vector<std::string>* output_ = nullptr;
};

// A fresh StudentCode with one file loaded (throws ScriptError like StudentCode::load).
std::unique_ptr<StudentCode> load_student_file(const std::filesystem::path& file, LuaLimits limits = {});

ExerciseOutcome run_mine(StudentCode& code, Exercise exercise, const ExerciseInput& input,
                         const RunOptions& options = {});
ExerciseOutcome run_reference(Exercise exercise, const ExerciseInput& input);

struct ExerciseReport {
  Exercise exercise = Exercise::CurveStep;
  bool equal = false;      // the same answer as the reference (up to renumbering and rounding): the verdict
  bool identical = false;  // bit for bit / pointer for pointer
  std::vector<std::string> differences;  // why not equal, the likely mistake first (first kMaxMessages)
  size_t total_differences = 0;
  std::vector<std::string> notes;  // what differs without being wrong (ids, rounding, conventions)
  ExerciseOutcome mine;
  ExerciseOutcome reference;

  static constexpr size_t kMaxMessages = 20;
  // "same as the reference" or "different: <first difference>" (plus " (N more)").
  std::string summary() const;
};

// Reads what a student's function returned (the value at `index` of L) into `out`, as run_mine does: out.ran, and
// out.error for a value of the wrong shape; out.returned described; the points, or the element when it is a handle
// of `mesh`. Reads raw: no metamethod runs. The grader reads the values a student's function returned to the suite
// through this too (expect.exercise).
void read_returned_value(lua_State* L, int index, Exercise exercise, const std::shared_ptr<HalfedgeMesh>& mesh,
                         ExerciseOutcome& out);

// Compares two outcomes of the same exercise and input.
ExerciseReport compare(Exercise exercise, const ExerciseInput& input, ExerciseOutcome mine, ExerciseOutcome reference);
// What to tell a student whose `exercise` ran out of time, instructions or memory ("upsample did not finish: split
// only the edges of the original mesh ..."); the window adds it under the limit's error, the grader under its
// "Timed out" or "Out of memory" line.
std::string unfinished_run_hint(Exercise exercise);

// run_mine, run_reference, compare.
ExerciseReport check_exercise(StudentCode& code, Exercise exercise, const ExerciseInput& input,
                              const RunOptions& options = {});

}  // namespace meshedit
