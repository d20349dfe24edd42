// Exercises an instructor adds in Lua alone, with no C++: one file in scripts/exercises/ names the student's file
// and function, what the function takes, a reference that does the same right, the diagnoses that name likely
// mistakes, a hint, and the fixtures grading checks. Once registered, such an exercise is an Exercise like the six
// built-in ones (exercises.h): the window's Exercises tab runs and replays it, a lesson's your_turn asks for it, and
// `meshedit grade --suite scripts/exercises/NAME.lua` grades it, all through the same check (compare()).
//
//   -- scripts/exercises/collapse.lua
//   exercise {
//     name = "collapse", title = "Edge collapse", file = "collapse.lua", call = "collapse_edge",
//     signature = "collapse_edge(mesh, e) -> the vertex that remains, or nil",
//     takes = "edge",                          -- "vertex", "edge", "face", "halfedge", "mesh"; "points", "patch"
//     allow = {},                              -- hideable API the student's code may use (student_api.h)
//     reference = function(mesh, e) return mesh:collapse(e) end,
//     diagnose = function(run) ... end,        -- run.before, run.mine, run.reference, run.element, run.returned
//     hint = "...",
//     fixtures = { { name = "an interior edge", mesh = meshedit.grid(2, 2), element = "e7", points = 2 } },
//   }
//
// An exercise on control points or a Bézier patch instead of a mesh takes "points" or "patch":
//
//   -- scripts/exercises/hodograph.lua
//   exercise {
//     name = "hodograph", file = "hodograph.lua", call = "hodograph", takes = "points",   -- or "patch"
//     reference = function(points) ... return list end,   -- the same arguments as the student's function
//     diagnose = function(run) ... end,        -- run.input, run.args, run.mine, run.reference
//     tolerance = 1e-9,                        -- optional; default points_tolerance of the input (1e-9 x its size)
//     fixtures = { { name = "a cubic", control = { {0, 0}, {1, 2}, {3, 2}, {4, 0} }, args = {}, points = 2 } },
//   }
//
//   takes = "points": the function gets a fresh list of vec3, the fixture's control points ({x, y} or {x, y, z}, or
//   vec3), then the fixture's args one by one. takes = "patch": it gets a patch as the built-in patch exercise does,
//   {points = 16 vec3} row by row (points[4 * row + col + 1]), then the args; a fixture's patch = is 16 points row by
//   row, 4 rows of 4, or meshedit.patch(...). `points =` stays the fixture's score. What the function returns (a
//   number, a point, a list of those, to any depth: exercise_value.h) is compared with what the reference returns,
//   item by item within the tolerance (value_compare.h); the definition's diagnoses come first.
//
// Invariants:
// - A definition runs in a LuaRuntime of its own (the meshedit module, LuaRuntime's sandbox and default limits): the
//   instructor's code, kept apart from any student's. Loading checks every field; a mistake is a ScriptError naming
//   "NAME.lua:LINE: exercise: ..." (the exercise{} call's line) or the Lua error's own file:line.
// - The reference and diagnose run on copies: reference(mesh, element) on its own copy of the input; diagnose gets
//   copies of the mesh before, yours and the reference's (read them; changing them changes nothing). Neither ever
//   throws out of run_reference/diagnose: the reference's error is the outcome's error, a diagnose error becomes one
//   message naming the definition's file:line.
// - A reference that returns nil and leaves the mesh as it was refuses the input: the student's code must change
//   nothing and return nil too (a second return value, a string, says why). On points or a patch, nil is a value
//   like any other: yours must return nil too.
// - On points or a patch, the reference and the student's function get the same arguments, made afresh for each
//   call (changing them changes nothing); diagnose gets copies of the input, the args and both returned values (a
//   returned value that is not a number, a point or a list of them is nil there).
// - Registered (ExerciseRegistry::add, exercise_registry.h), a definition is one Exercise handle of kind Scripted;
//   a name registered again keeps its handle and takes the new definition. Names of the built-ins cannot be taken.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/bezier.h"
#include "core/halfedge_mesh.h"
#include "exercise/exercise_value.h"
#include "exercise/exercises.h"
#include "exercise/student_api.h"
#include "script/file_stamp.h"

namespace meshedit {

class LuaRuntime;

// One fixture: what `meshedit grade --suite THE_DEFINITION` checks in one test.
struct ScriptedFixture {
  std::string name;                          // "an interior edge of a 2x2 grid"
  std::shared_ptr<const HalfedgeMesh> mesh;  // as it was before the call (exercises on a mesh)
  ElementRef element;                        // invalid when the exercise takes the whole mesh
  std::vector<glm::dvec3> control;           // takes = "points": control = {...}
  BezierPatch patch;                         // takes = "patch": patch = {...}
  std::vector<ExerciseValue> args;           // points or patch: args = {...}, passed after the input
  double points = 1.0;                       // the test's score
};

class ScriptedExercise {
 public:
  // Runs the definition file. Throws ScriptError (its file:line) for a Lua error or a field that is missing or wrong.
  static std::shared_ptr<ScriptedExercise> load(const std::filesystem::path& file);
  ~ScriptedExercise();
  ScriptedExercise(const ScriptedExercise&) = delete;
  ScriptedExercise& operator=(const ScriptedExercise&) = delete;

  const std::filesystem::path& path() const { return path_; }
  const FileStamp& stamp() const { return stamp_; }
  // name, file, function (`call`), signature, title, as exercise_info gives them once registered.
  const ExerciseInfo& info() const { return info_; }
  // What the function takes first: an element of a mesh (after the mesh), the whole mesh, control points, a patch.
  enum class Input { Element, Mesh, Points, Patch };
  Input input() const { return input_; }
  // Points or a patch: the exercise works on values, not on a mesh (is_mesh_exercise is false for it).
  bool takes_values() const { return input_ == Input::Points || input_ == Input::Patch; }
  // The kind of element the function takes after the mesh; nullopt when it takes the whole mesh, points or a patch.
  std::optional<ElementKind> takes() const { return takes_; }
  // Within how much a returned number or point agrees with the reference's (points or a patch): the definition's
  // tolerance, else points_tolerance of the input's points (core/mesh_compare.h), as the curve exercise's.
  double tolerance(const ExerciseInput& input) const;
  const ExerciseApi& api() const { return api_; }
  const std::string& hint() const { return hint_; }
  const std::vector<ScriptedFixture>& fixtures() const { return fixtures_; }
  // What a fixture gives the function (and the reference): its mesh and element, or its points or patch and args.
  ExerciseInput input_of(const ScriptedFixture& fixture) const;
  // Points or a patch: pushes the arguments of the function for `input` (a fresh list of vec3 or {points = 16 vec3},
  // then the args) and returns how many. Throws ScriptError when the stack cannot hold them.
  int push_value_arguments(lua_State* L, const ExerciseInput& input) const;

  // The reference on a copy of input.mesh: out.mesh, out.element (what it returned, of that mesh), out.returned,
  // out.refused (nil and the mesh unchanged), out.validation; out.error when the reference itself failed. On points
  // or a patch: out.value (what it returned) and out.returned, its description.
  ExerciseOutcome run_reference(const ExerciseInput& input) const;
  // The definition's diagnose on the run (called only when yours differs from the reference): its messages, the
  // likely mistake first; none when it has no diagnose or returns nil.
  std::vector<std::string> diagnose(const ExerciseInput& input, const ExerciseOutcome& mine,
                                    const ExerciseOutcome& reference) const;

 private:
  friend struct ScriptedExerciseReader;  // exercise{}: fills the fields while the file runs
  ScriptedExercise() = default;
  ExerciseOutcome run_values_reference(const ExerciseInput& input) const;
  // diagnose's `run` table: {input, args, mine, reference} for values, {before, mine, reference, element, returned}.
  void push_values_run(lua_State* L, const ExerciseInput& input, const ExerciseOutcome& mine,
                       const ExerciseOutcome& reference) const;
  void push_mesh_run(lua_State* L, const ExerciseInput& input, const ExerciseOutcome& mine,
                     const ExerciseOutcome& reference) const;

  std::filesystem::path path_;
  FileStamp stamp_;  // the file as it was loaded
  std::string name_, file_, function_, signature_, title_, hint_;
  ExerciseInfo info_{};
  std::optional<ElementKind> takes_;
  Input input_ = Input::Element;
  std::optional<double> tolerance_;
  ExerciseApi api_;
  std::vector<ScriptedFixture> fixtures_;
  std::unique_ptr<LuaRuntime> runtime_;  // the definition's own state; reference_ and diagnose_ are registry refs
  int reference_ = -1, diagnose_ = -1;
};

}  // namespace meshedit
