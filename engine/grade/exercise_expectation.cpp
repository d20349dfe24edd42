// expect.exercise: reading the suite's arguments into the window's ExerciseInput and ExerciseOutcome, and
// recording compare()'s verdict (see exercise_expectation.h).
#include "grade/exercise_expectation.h"

#include <memory>
#include <string>

#include <lua.hpp>

#include "core/translation.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/scripted_exercise.h"
#include "grade/expectations.h"
#include "grade/failing_case.h"
#include "script/bezier_bindings.h"
#include "script/lua_handles.h"
#include "script/mesh_bindings.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

constexpr int kInput = 2, kReturned = 3, kYours = 4, kMessage = 5;

double number_field(lua_State* L, const char* field) {
  lua_getfield(L, kInput, field);
  if (lua_type(L, -1) != LUA_TNUMBER) luaL_error(L, "expect.exercise: input.%s must be a number", field);
  const double value = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return value;
}

std::vector<glm::dvec3> points_at(lua_State* L, int index, const char* what) {
  if (!lua_istable(L, index)) luaL_error(L, "expect.exercise: %s must be a list of points", what);
  std::vector<glm::dvec3> points;
  const lua_Unsigned n = lua_rawlen(L, index);
  for (lua_Unsigned i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, static_cast<lua_Integer>(i));
    glm::dvec3 p;
    if (!to_vec3(L, -1, p)) luaL_error(L, "expect.exercise: %s[%d] is not a point", what, int(i));
    points.push_back(p);
    lua_pop(L, 1);
  }
  return points;
}

BezierPatch patch_field(lua_State* L) {
  lua_getfield(L, kInput, "patch");
  if (const BezierPatch* patch = to_patch(L, -1)) {
    BezierPatch copy = *patch;
    lua_pop(L, 1);
    return copy;
  }
  if (!lua_istable(L, -1)) luaL_error(L, "expect.exercise: input.patch must be a patch or {points = 16 points}");
  lua_getfield(L, -1, "points");
  const std::vector<glm::dvec3> points = points_at(L, lua_gettop(L), "input.patch.points");
  if (points.size() != 16) luaL_error(L, "expect.exercise: input.patch.points must hold 16 points");
  BezierPatch patch;
  std::copy(points.begin(), points.end(), patch.points.begin());
  lua_pop(L, 2);
  return patch;
}

// input.<field>: a handle of `mesh` or an id, of kind `kind`.
ElementRef element_field(lua_State* L, const char* field, ElementKind kind, const std::shared_ptr<HalfedgeMesh>& mesh) {
  lua_getfield(L, kInput, field);
  ElementRef ref;
  if (const Handle* h = test_handle(L, -1)) {
    if (h->mesh() != mesh) luaL_error(L, "expect.exercise: input.%s is not an element of input.mesh", field);
    ref = h->ref();
  } else if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0 && lua_tointeger(L, -1) <= lua_Integer(UINT32_MAX)) {
    ref = ElementRef(kind, static_cast<uint32_t>(lua_tointeger(L, -1)));
  } else {
    luaL_error(L, "expect.exercise: input.%s must be a %s or its id", field, kind_name(kind));
  }
  lua_pop(L, 1);
  if (ref.kind != kind || !mesh->alive(ref)) {
    luaL_error(L, "expect.exercise: input.%s is %s, not a live %s of input.mesh", field, format_id(ref).c_str(),
               kind_name(kind));
  }
  return ref;
}

// A scripted exercise on points or a patch: {control = points, args = {...}} or {patch = ..., args = {...}}.
ExerciseInput read_values_input(lua_State* L, const ScriptedExercise& scripted) {
  lua_getfield(L, kInput, "args");
  std::vector<ExerciseValue> args;
  if (const std::string bad = read_argument_values(L, -1, args); !bad.empty()) {
    luaL_error(L, "expect.exercise: input.args%s%s", bad[0] == '[' ? "" : " ", bad.c_str());
  }
  lua_pop(L, 1);
  if (scripted.input() == ScriptedExercise::Input::Patch) {
    lua_getfield(L, kInput, "patch");
    BezierPatch patch;
    if (const std::string bad = read_patch_points(L, -1, patch); !bad.empty()) {
      luaL_error(L, "expect.exercise: input.patch %s", bad.c_str());
    }
    lua_pop(L, 1);
    return ExerciseInput::of_patch(patch, std::move(args));
  }
  lua_getfield(L, kInput, "control");
  std::vector<glm::dvec3> points;
  if (const std::string bad = read_control_points(L, -1, points); !bad.empty()) {
    luaL_error(L, "expect.exercise: input.control %s", bad.c_str());
  }
  lua_pop(L, 1);
  return ExerciseInput::of_points(std::move(points), std::move(args));
}

ExerciseInput read_input(lua_State* L, Exercise exercise) {
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition();
      scripted && scripted->takes_values()) {
    return read_values_input(L, *scripted);
  }
  switch (exercise.kind()) {
    case ExerciseKind::CurveStep: {
      lua_getfield(L, kInput, "points");
      std::vector<glm::dvec3> points = points_at(L, lua_gettop(L), "input.points");
      lua_pop(L, 1);
      return ExerciseInput::curve_step(std::move(points), number_field(L, "t"));
    }
    case ExerciseKind::PatchEvaluate: {
      const BezierPatch patch = patch_field(L);
      return ExerciseInput::patch_point(patch, number_field(L, "u"), number_field(L, "v"));
    }
    default: break;
  }
  lua_getfield(L, kInput, "mesh");
  const std::shared_ptr<HalfedgeMesh> mesh = to_mesh(L, -1);
  lua_pop(L, 1);
  if (!mesh) luaL_error(L, "expect.exercise: input.mesh must be the mesh before the call");
  if (const std::shared_ptr<const ScriptedExercise> scripted = exercise.definition()) {
    if (!scripted->takes()) return ExerciseInput::whole_mesh(mesh);
    return ExerciseInput::element_of(mesh, element_field(L, "element", *scripted->takes(), mesh));
  }
  switch (exercise.kind()) {
    case ExerciseKind::VertexNormal:
      return ExerciseInput::vertex(mesh, VertexId(element_field(L, "vertex", ElementKind::Vertex, mesh).index));
    case ExerciseKind::FlipEdge:
    case ExerciseKind::SplitEdge:
      return ExerciseInput::edge(mesh, EdgeId(element_field(L, "edge", ElementKind::Edge, mesh).index));
    default: return ExerciseInput::whole_mesh(mesh);
  }
}

}  // namespace

int expect_exercise(lua_State* L) {
  lua_settop(L, kMessage);
  const std::string name = luaL_checkstring(L, 1);
  const std::optional<Exercise> exercise = find_exercise(name);
  if (!exercise) return luaL_error(L, "expect.exercise: %s", exercise_registry().unknown_name_error(name).c_str());
  luaL_checktype(L, kInput, LUA_TTABLE);
  const std::string message = lua_isnoneornil(L, kMessage) ? "" : luaL_checkstring(L, kMessage);
  TestRecorder& recorder = current_recorder(L);

  const ExerciseInput input = read_input(L, *exercise);
  ExerciseOutcome mine;
  if (is_mesh_exercise(*exercise)) {
    mine.mesh = to_mesh(L, kYours);
    if (!mine.mesh) return luaL_argerror(L, kYours, "the mesh the student's function worked on expected");
    if (mine.mesh.get() == input.mesh.get()) {
      return luaL_argerror(L, kYours, "the student's mesh must be another mesh than input.mesh (pass a copy)");
    }
  }
  read_returned_value(L, kReturned, *exercise, mine.mesh, mine);
  if (mine.mesh) mine.touched = recorder.touches_of(mine.mesh.get());
  const std::shared_ptr<const HalfedgeMesh> yours = mine.mesh;  // compare() takes the outcome
  const ExerciseReport report = compare(*exercise, input, std::move(mine), run_reference(*exercise, input));
  const std::string detail = report.equal ? std::string(tr("same as the reference"))
                                          : first_items(report.differences, report.total_differences);
  // The headline: what was checked and the first difference, the likely mistake (the Markdown folds the rest).
  const size_t headline =
      report.equal || report.differences.empty() ? 0 : join_message(message, report.differences.front()).size();
  std::optional<FailingCase> failing_case;
  if (!report.equal) failing_case = failing_case_of(*exercise, input, yours.get());
  lua_pushboolean(L, recorder.record(report.equal, join_message(message, detail), headline, std::move(failing_case)));
  return 1;
}

}  // namespace meshedit
