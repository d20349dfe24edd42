// your_turn (see lesson_your_turn.h): a Lua prelude loops "run, wait for a save" in the step's coroutine; the C
// functions below check the table and build the exercise's input, run the student's file beside the reference
// (YourTurnRun, judged by the Exercises tab's comparison), record the verdict and make the waits.
#include "lesson/internal/lesson_your_turn.h"

#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/ids.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/scripted_exercise.h"
#include "lesson/internal/diagram_names.h"
#include "lesson/internal/lesson_api_support.h"
#include "lesson/internal/your_turn_run.h"
#include "script/bezier_bindings.h"
#include "script/file_stamp.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"

namespace meshedit {
namespace {

constexpr const char* kYourTurnPrelude = R"lua(local api = __lesson_your_turn
__lesson_your_turn = nil
local check, run, await = api.check, api.run, api.await

function your_turn(spec)
  local input = check(spec)
  while not run(spec, input) do await(spec) end
  return true
end
)lua";

constexpr const char* kExerciseNames =
    "curve, patch, normals, flip, split, upsample or an exercise of scripts/exercises";

Exercise read_exercise(lua_State* L, int index) {
  lua_getfield(L, index, "exercise");
  if (lua_type(L, -1) != LUA_TSTRING) {
    raise(L, std::string("your_turn: exercise must be one of ") + kExerciseNames + ", got " + type_name(L, -1));
  }
  const std::string name = lua_tostring(L, -1);
  lua_pop(L, 1);
  const std::optional<Exercise> exercise = find_exercise(name);
  if (!exercise) raise(L, "your_turn: " + exercise_registry().unknown_name_error(name));
  return *exercise;
}

double read_number(lua_State* L, int index, const char* field) {
  lua_getfield(L, index, field);
  if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1))) {
    raise(L, std::string("your_turn: ") + field + " must be a finite number, got " + type_name(L, -1));
  }
  const double value = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return value;
}

// A copy of the mesh field, so the lesson's later edits change nothing of the runs.
std::shared_ptr<const HalfedgeMesh> read_mesh(lua_State* L, int index, Exercise exercise) {
  lua_getfield(L, index, "mesh");
  std::shared_ptr<HalfedgeMesh> mesh = to_mesh(L, -1);
  if (!mesh) {
    raise(L, std::string("your_turn: the ") + exercise_info(exercise).name + " exercise needs mesh = a mesh, got " +
                 type_name(L, -1));
  }
  lua_pop(L, 1);
  return std::make_shared<const HalfedgeMesh>(*mesh);
}

ElementRef read_element(lua_State* L, int index, const HalfedgeMesh& mesh, ElementKind kind) {
  lua_getfield(L, index, "element");
  const std::optional<ElementRef> element = to_element(L, -1);
  if (!element || element->kind != kind || !mesh.alive(*element)) {
    const std::string got = element ? format_id(*element) : "a " + type_name(L, -1);
    raise(L, std::string("your_turn: element must be ") + (kind == ElementKind::Edge ? "an " : "a ") + kind_name(kind) +
                 " of the mesh (a handle or an id like \"" + kind_prefix(kind) + "0\"), got " + got);
  }
  lua_pop(L, 1);
  return *element;
}

std::vector<glm::dvec3> read_points(lua_State* L, int index) {
  lua_getfield(L, index, "points");
  if (!lua_istable(L, -1)) {
    raise(L, "your_turn: the curve exercise needs points = {{x, y}, ...}, got " + type_name(L, -1));
  }
  std::vector<glm::dvec3> points;
  const lua_Integer n = luaL_len(L, -1);
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, -1, i);
    glm::dvec3 p(0.0);
    if (!read_point(L, -1, p)) {
      raise(L, "your_turn: point " + std::to_string(i) + " is not a point: " + type_name(L, -1));
    }
    points.push_back(p);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (points.empty()) raise(L, "your_turn: the curve exercise needs at least one point");
  return points;
}

// A scripted exercise on points (control = {...}) or a patch (patch = ...), with args = {...} after it.
ExerciseInput read_values_input(lua_State* L, int index, const ScriptedExercise& scripted) {
  const bool patch = scripted.input() == ScriptedExercise::Input::Patch;
  const std::string name = scripted.info().name;
  lua_getfield(L, index, "args");
  std::vector<ExerciseValue> args;
  if (const std::string bad = read_argument_values(L, -1, args); !bad.empty()) {
    raise(L, "your_turn: args" + std::string(bad[0] == '[' ? "" : " ") + bad);
  }
  lua_pop(L, 1);
  lua_getfield(L, index, patch ? "patch" : "control");
  if (lua_isnil(L, -1)) {
    raise(L, "your_turn: the " + name + " exercise takes " +
                 (patch ? "patch = (16 points, or meshedit.patch(...))" : "control = {the control points}") +
                 ", got nil");
  }
  BezierPatch points16;
  std::vector<glm::dvec3> control;
  const std::string bad = patch ? read_patch_points(L, -1, points16) : read_control_points(L, -1, control);
  if (!bad.empty()) raise(L, std::string("your_turn: ") + (patch ? "patch " : "control ") + bad);
  lua_pop(L, 1);
  return patch ? ExerciseInput::of_patch(points16, std::move(args))
               : ExerciseInput::of_points(std::move(control), std::move(args));
}

// The exercise's input, copied out of the table at `index`.
ExerciseInput read_input(lua_State* L, int index, Exercise exercise) {
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition()) {
    if (scripted->takes_values()) return read_values_input(L, index, *scripted);
    std::shared_ptr<const HalfedgeMesh> mesh = read_mesh(L, index, exercise);
    if (!scripted->takes()) return ExerciseInput::whole_mesh(std::move(mesh));
    const ElementRef element = read_element(L, index, *mesh, *scripted->takes());
    return ExerciseInput::element_of(std::move(mesh), element);
  }
  switch (exercise.kind()) {
    case ExerciseKind::CurveStep: {
      std::vector<glm::dvec3> points = read_points(L, index);
      return ExerciseInput::curve_step(std::move(points), read_number(L, index, "t"));
    }
    case ExerciseKind::PatchEvaluate: {
      lua_getfield(L, index, "patch");
      const BezierPatch* patch = to_patch(L, -1);
      if (!patch) raise(L, "your_turn: the patch exercise needs patch = meshedit.patch(...), got " + type_name(L, -1));
      const BezierPatch copy = *patch;
      lua_pop(L, 1);
      return ExerciseInput::patch_point(copy, read_number(L, index, "u"), read_number(L, index, "v"));
    }
    case ExerciseKind::VertexNormal: {
      std::shared_ptr<const HalfedgeMesh> mesh = read_mesh(L, index, exercise);
      const ElementRef v = read_element(L, index, *mesh, ElementKind::Vertex);
      return ExerciseInput::vertex(std::move(mesh), VertexId(v.index));
    }
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge: {
      std::shared_ptr<const HalfedgeMesh> mesh = read_mesh(L, index, exercise);
      const ElementRef e = read_element(L, index, *mesh, ElementKind::Edge);
      return ExerciseInput::edge(std::move(mesh), EdgeId(e.index));
    }
    case ExerciseKind::Upsample: return ExerciseInput::whole_mesh(read_mesh(L, index, exercise));
    case ExerciseKind::Scripted: break;  // read above, as its definition takes
  }
  raise(L, "your_turn: unknown exercise");
}

// The input, held by Lua between check and the runs (a full userdata with a finaliser).
constexpr const char* kInputMeta = "meshedit.your_turn_input";

struct HeldInput {
  Exercise exercise;
  ExerciseInput input;
  DiagramNames names;  // names = {...}: the diagram's name of each storage id (diagram_names.h)
};

int held_input_gc(lua_State* L) {
  static_cast<HeldInput*>(luaL_checkudata(L, 1, kInputMeta))->~HeldInput();
  return 0;
}

HeldInput& check_held_input(lua_State* L, int index) {
  return *static_cast<HeldInput*>(luaL_checkudata(L, index, kInputMeta));
}

// names = {a = v2, h0 = "h3", ...} at `index`: each diagram name with its element (a handle or an id), as storage id
// and diagram name.
DiagramNames read_names(lua_State* L, int index) {
  DiagramNames names;
  lua_getfield(L, index, "names");
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return names;
  }
  if (!lua_istable(L, -1)) raise(L, "your_turn: names must be a table from the diagram's names to elements");
  const int table = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, table) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING) raise(L, "your_turn: names' keys are the diagram's names, strings");
    const std::string name = lua_tostring(L, -2);
    const std::string id = luaL_tolstring(L, -1, nullptr);
    lua_pop(L, 1);
    if (!parse_element(id)) {
      raise(L, "your_turn: names." + name + " must be an element (a handle or an id like \"h3\"), got " + id);
    }
    names.emplace_back(id, name);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return names;
}

// ---- what the prelude calls ---------------------------------------------------------------------------------------

// check(spec) -> the input: the whole table, before the first run.
int api_check(lua_State* L) {
  require_step_thread(L, "your_turn{}");
  if (!lua_istable(L, 1)) {
    raise(L, "your_turn: expected a table like your_turn{ exercise = \"flip\", mesh = m, element = \"e0\" }, got " +
                 type_name(L, 1));
  }
  check_fields(L, 1, "your_turn",
               {"exercise", "mesh", "element", "points", "t", "patch", "u", "v", "control", "args", "hint", "names"});
  lua_getfield(L, 1, "hint");
  if (!lua_isnil(L, -1) && !is_text(L, -1)) raise(L, "your_turn: hint must be a string");
  lua_pop(L, 1);
  const Exercise exercise = read_exercise(L, 1);
  ExerciseInput input = read_input(L, 1, exercise);
  DiagramNames names = read_names(L, 1);
  void* memory = lua_newuserdatauv(L, sizeof(HeldInput), 0);
  new (memory) HeldInput{exercise, std::move(input), std::move(names)};
  if (luaL_newmetatable(L, kInputMeta)) {
    lua_pushcfunction(L, held_input_gc);
    lua_setfield(L, -2, "__gc");
  }
  lua_setmetatable(L, -2);
  return 1;
}

// run(spec, input) -> right: the student's file and the reference on the input, the verdict recorded.
int api_run(lua_State* L) {
  require_step_thread(L, "your_turn{}");
  LessonScript& script = script_of(L);
  const HeldInput& held = check_held_input(L, 2);
  const ExerciseInfo& info = exercise_info(held.exercise);
  if (script.student_folder.empty()) {
    raise(L, "your_turn: no student folder (meshedit lesson FILE --headless --student DIR)");
  }
  const std::filesystem::path file = script.student_folder / info.file;
  YourTurnVerdict verdict;
  verdict.exercise = held.exercise;
  verdict.exercise_input = held.input;  // shares the held copy's mesh, which nothing changes
  verdict.file = info.file;
  verdict.function = info.function;
  verdict.input = held.input.describe(held.exercise);
  verdict.where = caller_where(L);
  verdict.block = script.blocks.size();
  verdict.path = file.string();
  verdict.stamp = file_stamp(file);
  auto run = std::make_shared<YourTurnRun>(std::move(verdict), held.names, script.student_limits,
                                           script.student_code_in_background);
  if (script.student_code_in_background) {  // the step waits while it runs; the runner resumes it with the verdict
    LessonWait wait;
    wait.kind = LessonWait::Kind::YourTurnRunning;
    wait.name = info.file;
    wait.question = "Your turn: your " + std::string(info.function) + " in " + info.file + " is running on " +
                    run->running().input + ".";
    wait.where = run->running().where;
    script.running_turn = std::move(run);
    script.wait = std::move(wait);
    script.api_yield = true;
    return lua_yield(L, 0);
  }
  lua_pushboolean(L, record_your_turn(script, run->finish()));
  return 1;
}

// await(spec): waits until the student's file changes; the runner resumes the step then.
int api_await(lua_State* L) {
  require_step_thread(L, "your_turn{}");
  LessonScript& script = script_of(L);
  if (script.your_turns.empty()) raise(L, "your_turn: nothing ran yet");
  const YourTurnVerdict& last = script.your_turns.back();
  LessonWait wait;
  wait.kind = LessonWait::Kind::YourTurn;
  wait.name = last.file;
  wait.question =
      "Your turn: write " + last.function + " in " + last.file + "; it runs on " + last.input + " each time you save.";
  wait.feedback = last.feedback;
  lua_getfield(L, 1, "hint");
  if (!lua_isnil(L, -1) && is_text(L, -1)) wait.hint = read_text(L, -1, "your_turn", "hint");
  lua_pop(L, 1);
  if (wait.hint.empty()) {  // an exercise defined in Lua brings its own
    if (const std::shared_ptr<const ScriptedExercise> scripted = last.exercise.definition()) {
      wait.hint = scripted->hint();
    }
  }
  for (const YourTurnVerdict& verdict : script.your_turns) wait.tries += verdict.right ? 0 : 1;
  wait.watched_file = last.path;
  wait.watched_stamp = last.stamp;
  wait.where = last.where;
  script.wait = std::move(wait);
  script.api_yield = true;
  return lua_yield(L, 0);
}

}  // namespace

bool record_your_turn(LessonScript& script, YourTurnVerdict verdict) {
  const bool right = verdict.right;
  if (right) {
    LessonJudgement judgement;
    judgement.question = "Your turn: " + verdict.function + " in " + verdict.file + ", on " + verdict.input;
    judgement.given = "your " + verdict.function;
    judgement.right = true;
    judgement.feedback = "it gives the reference's answer";
    script.answered.push_back(std::move(judgement));
    script.blocks.push_back({LessonBlock::Kind::Answered, script.answered.size() - 1});
  }
  script.your_turns.push_back(std::move(verdict));
  return right;
}

void open_lesson_your_turn(LuaRuntime& runtime, LessonScript& script) {
  open_prelude_functions(
      runtime, script, "__lesson_your_turn",
      {{"check", lesson_guarded<api_check>}, {"run", lesson_guarded<api_run>}, {"await", lesson_guarded<api_await>}},
      kYourTurnPrelude);
}

}  // namespace meshedit
